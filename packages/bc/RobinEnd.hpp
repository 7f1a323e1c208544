#pragma once
// A Robin condition alpha F + beta u = gamma at one end of a 1-D body (primer eq. 1.1,
// footnote 3: alpha = 0, beta = 1 prescribes u; alpha = 1, beta = 0 prescribes the force;
// alpha = 1, beta = -k is a spring).  The end force F is an unknown of the grid system
// (eq. 1.18); it enters the force balance through the boundary-force array
// Fhat_i = N_i(x_end) F (eq. 1.12, 1.46), and the condition reads
//   alpha F + beta (u_end + sum_i N_i(x_end) du_i) = gamma(t),
// with u(x_end) = N^T(x_end) u (eq. 1.19).  N_i are the grid's tents at the end point, so
// an end inside a cell (Fig. 1.2) gives two non-zero entries (footnote 16).
//
// The end point moves with the grid's displacement field (updated-Lagrangian kinematics)
// or stays at its reference position (small kinematics).

#include <Teuchos_ParameterList.hpp>

#include <string>

#include "assembly/Kinematics.hpp"
#include "core/Formula.hpp"
#include "solver/Contribution.hpp"

namespace impm {

class RobinEnd : public Contribution<1> {
 public:
  static Teuchos::ParameterList validParameters();

  // `referenceEnd`: position of the body's end in the reference configuration.
  RobinEnd(const std::string& name, const Teuchos::ParameterList& params, double referenceEnd,
           Kinematics kinematics);

  void prepare(const NodeOwnership<1>& ownership, std::vector<ExtraDof>& extras,
               std::vector<GlobalId>& touched) override;
  void couplings(const ContributionContext<1>& ctx,
                 std::vector<std::pair<GO, GO>>& out) const override;
  void initialGuess(const ContributionContext<1>& ctx, Vector& x) const override;
  void addResidual(const ContributionContext<1>& ctx, const HostValues& x,
                   const HostValuesMutable& f) const override;
  void addJacobian(const ContributionContext<1>& ctx, const HostValues& x,
                   FECrsMatrix& J) const override;
  void commit(const ContributionContext<1>& ctx, const HostValues& x) override;
  // F du_end summed over the steps (trapezoidal in F).
  double work() const override { return work_; }
  // position, displacement, force and work of the end.
  std::vector<double> state() const override { return {position_, displacement_, force_, work_}; }
  void restore(const std::vector<double>& s) override;
  bool readsParticleMotion() const override { return false; }  // it follows its own end

  const std::string& name() const { return name_; }
  const std::string& body() const { return body_; }
  bool isLeft() const { return left_; }
  double force() const { return force_; }                // F at the end of the last step
  double displacement() const { return displacement_; }  // u(x_end)
  double position() const { return position_; }          // x_end

 private:
  struct Support {
    GlobalId node[2];
    double weight[2];
    int count = 0;
  };
  double gamma(const ContributionContext<1>& ctx) const;

  std::string name_, body_;
  bool left_;
  double alpha_, beta_;
  Formula gamma_;
  Kinematics kinematics_;
  double position_, displacement_ = 0.0, force_ = 0.0, work_ = 0.0;
  Support support_;  // nodes with N_i(x_end) != 0, valid during a step
  bool owner_ = false;
};

}  // namespace impm
