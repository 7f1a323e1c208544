#pragma once
// Prescribed displacement of one component on the grid nodes of a face or a box (2-D
// rollers, clamps, moving platens): u_a(x_i, t) = g(x_i, t) at every selected node i that
// some integration point reaches.  The step's unknowns are increments, so the row of each
// such unknown becomes du_ia = lambda_(n+1) g(x_i, t_(n+1)) - lambda_n g(x_i, t_n), with
// lambda the load factor of static load steps (1 in dynamics).  Nodes that no integration
// point reaches are not unknowns and are left alone.  The support's work on the bodies is
// the trapezoidal sum over steps and nodes of (R_i^n + R_i^(n+1)) / 2 times the prescribed
// increment, R_i the nodal reaction: a prescribed displacement is a load (a footing, a
// platen) and its work enters the energy balance.

#include <Teuchos_ParameterList.hpp>

#include <array>
#include <string>

#include "core/Formula.hpp"
#include "solver/Contribution.hpp"

namespace impm {

template <int Dim>
class DirichletNodes : public Contribution<Dim> {
 public:
  static Teuchos::ParameterList validParameters();

  // initialLoadFactor: the load factor at t = 0 (0 for static load steps, 1 in dynamics).
  // Throws InputError naming "Boundary Conditions/<name>/..." when the selection is empty
  // or does not fit the grid.
  DirichletNodes(const std::string& name, const Teuchos::ParameterList& params,
                 const GridGeometry<Dim>& grid, double initialLoadFactor);

  void constraints(const ContributionContext<Dim>& ctx,
                   std::vector<std::pair<GO, double>>& out) const override;
  void commit(const ContributionContext<Dim>& ctx, const HostValues& x) override;
  double work() const override { return work_; }
  // The time and load factor of the last commit (the prescribed values reached), the work so
  // far, then (node key, reaction) of every node held at the last commit.
  std::vector<double> state() const override;
  void restore(const std::vector<double>& state) override;
  std::string reactionName() const override { return name_; }
  double reaction(const ContributionContext<Dim>& ctx, const HostValues& r) override;
  bool readsParticleMotion() const override { return false; }  // grid nodes only

 private:
  bool selects(const int idx[Dim]) const;
  double prescribed(const double* x, double time, double loadFactor) const;
  // The increment of the prescribed value at a node over the step.
  double increment(const ContributionContext<Dim>& ctx, GlobalId node) const;

  std::string name_;
  GridGeometry<Dim> grid_;
  int component_;
  std::array<int, Dim> lo_{}, hi_{};  // selected node index range per direction (inclusive)
  Formula value_;
  double committedTime_ = 0.0, committedLoad_;
  // Reactions by node key (node * Dim + component), sorted, at the last commit and of the
  // step waiting for its commit.
  std::vector<std::pair<double, double>> forces_, pendingForces_;
  double work_ = 0.0, pendingWork_ = 0.0;
  bool pending_ = false;
};

}  // namespace impm
