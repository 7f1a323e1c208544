#pragma once
// The nonlinear system of one step on the grid (primer eq. 1.62: f_int + f_ext = 0, with
// the boundary forces of eq. 1.18-1.19 as extra unknowns):
//   R(du) = f_int(du) - load * f_ext - boundary forces + contributions = 0,
// where du are the grid displacement increments of the step.  Built at the start of a step
// from the particle-grid map; the integration points' state at the start of the step is
// read, never written, until the stepper accepts the solution.

#include <memory>
#include <vector>

#include "assembly/Kinematics.hpp"
#include "basis/Method.hpp"
#include "material/Material.hpp"
#include "solver/Contribution.hpp"
#include "solver/ResidualModel.hpp"

namespace impm {

template <int Dim>
class GridSystem : public ResidualModel {
 public:
  using Materials = std::vector<std::shared_ptr<Material<Dim>>>;
  using Contributions = std::vector<std::shared_ptr<Contribution<Dim>>>;

  // Builds the map, the unknowns and the graph.  Collective.
  GridSystem(const NodeOwnership<Dim>& ownership, Method method, Kinematics kinematics,
             const ParticleSet<Dim>& particles, const Materials& materials,
             const Contributions& contributions, double time, double loadFactor);

  Teuchos::RCP<const Map> map() const override { return dofs_.ownedMap(); }
  Teuchos::RCP<CrsMatrix> createJacobian() const override;
  void evaluate(const Vector& x, Vector* residual, CrsMatrix* jacobian) override;

  // A zero increment with the contributions' guesses for their extra unknowns.
  Teuchos::RCP<Vector> initialGuess() const;
  // Overlap values of an owned vector.
  Teuchos::RCP<Vector> toOverlap(const Vector& owned) const;
  // Tells the contributions that the step converged at x.  Collective.
  void commit(const Vector& x);
  // Deformation gradient, first Piola stress at x (trial state of every particle).
  void trialState(const Vector& x, typename ParticleSet<Dim>::Tensors& F,
                  typename ParticleSet<Dim>::Tensors& P);

  const ParticleGridMap<Dim>& particleGridMap() const { return map_; }
  const Kokkos::View<LO*>& entryDofs() const { return entryDofs_; }
  const DofMap<Dim>& dofs() const { return dofs_; }
  StepContext<Dim> context(int contribution) const;

 private:
  void updateStress(const Vector& x);
  void checkEveryActiveNodeIsIntegrated() const;

  const GridGeometry<Dim> grid_;
  Kinematics kinematics_;
  const ParticleSet<Dim>& particles_;
  const Materials& materials_;
  const Contributions& contributions_;
  double time_, loadFactor_;
  ParticleGridMap<Dim> map_;
  std::vector<int> firstExtra_;
  DofMap<Dim> dofs_;
  Kokkos::View<LO*> entryDofs_;  // overlap-map index of each map entry's node
  Kokkos::View<LO*> entryCols_;  // the same in the Jacobian's column map
  Teuchos::RCP<FECrsGraph> graph_;
  Teuchos::RCP<const Import> importer_;
  // Work arrays: trial F, P and A, and P, A relative to the start of the step.
  typename ParticleSet<Dim>::Tensors F_, P_, Pn_;
  Tangents<Dim> A_, An_;
};

}  // namespace impm
