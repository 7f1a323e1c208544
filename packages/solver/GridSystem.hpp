#pragma once
// The nonlinear system of one step on the grid (primer eq. 1.62: f_int + f_ext = 0; with
// inertia eq. 1.44, 1.70: f_int + f_ext = M a; the boundary forces of eq. 1.18-1.19 are
// extra unknowns):
//   R(du) = f_int(du) - load * f_ext - boundary forces + M a(du) + contributions = 0,
// where du are the grid displacement increments of the step and, in dynamic steps,
// a(du) = c0 du - r is the time integrator's acceleration (Newmark, explicit).  Built at the start
// of a step from the particle-grid map; the integration points' state at the start of the step is
// read, never written, until the stepper accepts the solution: the materials' trial state lives
// here until commit().

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "assembly/FBar.hpp"
#include "assembly/GhostPenalty.hpp"
#include "assembly/Kinematics.hpp"
#include "assembly/Mass.hpp"
#include "basis/Method.hpp"
#include "material/MaterialState.hpp"
#include "solver/Contribution.hpp"
#include "solver/DiagonalSolve.hpp"
#include "solver/ResidualModel.hpp"
#include "solver/StepWorkspace.hpp"
#include "solver/SystemLayout.hpp"

namespace impm {

template <int Dim>
class GridSystem : public ResidualModel {
 public:
  using Contributions = std::vector<std::shared_ptr<Contribution<Dim>>>;

  // Builds the map, then the unknowns and the graph or takes them from `layouts` (see
  // solver/SystemLayout.hpp).  Collective.  `workspace`: the per-particle arrays kept
  // across steps; null `workspace` or `layouts`: the system's own.  `coupling`: the graph's
  // node pairs; NodeCoupling::self serves only a Jacobian with hasDiagonalJacobian().
  // `fbar`: the anti-locking average of the laws' F (assembly/FBar.hpp); every particle
  // must then be on the rank that owns the cell of its map position.  `ghostPenalty`: gamma
  // of the penalty on the cut cells' faces (assembly/GhostPenalty.hpp); 0: none.
  GridSystem(const NodeOwnership<Dim>& ownership, Method method, Kinematics kinematics,
             const ParticleSet<Dim>& particles, const Materials<Dim>& materials,
             const Contributions& contributions, double time, double loadFactor,
             StepWorkspace<Dim>* workspace = nullptr, LayoutCache<Dim>* layouts = nullptr,
             NodeCoupling coupling = NodeCoupling::shared, FBar fbar = FBar::none,
             double ghostPenalty = 0.0);

  // The inertia term M a of a dynamic step, a = c0 du - r on the nodal unknowns.  With the
  // lumped mass, M a is m_i a_i on the owned rows (lumpedMass()): one pass over the grid
  // instead of one over the particles.
  struct Inertia {
    MassType mass = MassType::lumped;
    double c0 = 0.0;
    Teuchos::RCP<const Vector> r;  // on unknownMap()
  };
  void setInertia(const Inertia& inertia);
  // Explicit steps: the internal force is that of the start of the step whatever du is,
  // and contributes nothing to the Jacobian.
  void freezeInternalForce(bool frozen) { frozen_ = frozen; }
  // The particles' stress is the Cauchy stress their last update committed (the stepper
  // knows it): a frozen internal force in updated-Lagrangian kinematics then takes it as the
  // stress at the start of the step instead of evaluating the laws at du = 0.  With laws
  // without a trial state that evaluation gives the same bits (P at the same F_n, pushed
  // forward by the same operations as the update's Cauchy stress); with others the laws
  // are evaluated as before.
  void startFromCommittedStress();
  // The time at the end of the step and the load factor (a system built at reference
  // positions serves every step of a total-Lagrangian run).  Like the constructor, it reads
  // whether the particles carry forces: the loads of the step are applied before.
  void setTime(double time, double loadFactor);
  // Whether a particle of this rank carries a force (assembly/Energy.hpp), as read when the
  // system was built or its time last set.  A rank without forces skips the external force.
  bool particlesCarryForces() const { return loaded_; }

  // Particle to grid on unknownMap(): sum_p m_p phi_ip q_p (momentum for q = v).
  Teuchos::RCP<Vector> particleToGrid(const typename ParticleSet<Dim>::Vectors& q) const;
  // The lumped mass m_i = sum_p m_p phi_ip on unknownMap() (0 on extra unknowns), summed
  // once: the particles' masses and the map do not change while a system lives.  Collective
  // the first time.
  Teuchos::RCP<const Vector> lumpedMass() const;
  // The consistent mass matrix, with 1 on the diagonal of the extra unknowns so that it can
  // be solved (the lumped one is lumpedMass()).
  Teuchos::RCP<CrsMatrix> consistentMassMatrix() const;
  // 1 on nodal unknowns, 0 on extra unknowns.
  const Vector& nodalMask() const { return *layout_.nodalMask; }
  const std::vector<LO>& extraRows() const { return layout_.extraRows; }

  Teuchos::RCP<const Map> unknownMap() const override { return dofs_.ownedMap(); }
  // Explicit steps, and linear materials whose step is linear in du (1-D, or total
  // Lagrangian: no push-forward by J).  Boundary conditions and inertia are linear.
  bool isLinear() const override;
  // Explicit steps with the lumped mass: the Jacobian's nodal block is diagonal (the lumped
  // mass times c0, the constraint scale on constrained rows) and the extra unknowns couple to
  // it through their rows and columns only, so the step needs no Krylov solve.
  bool hasDiagonalJacobian() const;
  // Then: the Jacobian's elimination (solver/DiagonalSolve), kept while c0 stays the same:
  // the rest of that Jacobian (the particles' masses, the constrained rows, the Robin ends'
  // alpha, beta and support) does not change while a system lives.  Collective;
  // NumericalError when the Jacobian is not finite or the elimination singular.
  const DiagonalElimination& explicitElimination();
  // The global indices of the extra unknowns (Robin end forces), the same on every rank.
  std::vector<GO> extraDofs() const;
  Teuchos::RCP<CrsMatrix> createJacobian() const override;
  // The rigid-body modes of the nodal unknowns (solver/RigidBodyModes).
  Teuchos::RCP<MultiVector> nearNullSpace() const override;
  void evaluate(const Vector& x, Vector* residual, CrsMatrix* jacobian) override;
  // The internal force's rounding when the laws see F rounded to doubles: at a small strain
  // of a stiff law (lambda eps) it is the residual's floor (assembly/Forces.hpp).
  double roundOffScale() const override;

  // A zero increment with the contributions' guesses for their extra unknowns and the
  // prescribed increments.
  Teuchos::RCP<Vector> initialGuess() const;
  // Sets the prescribed unknowns of x to their prescribed increments (a guess must meet them,
  // see eliminateConstrained).
  void imposeConstraints(Vector& x) const;
  // Overlap values of an owned vector.  Collective.
  Teuchos::RCP<const Vector> toOverlap(const Vector& owned) const;
  // The step converged at x: the contributions and the materials commit their state (after
  // trialState(x), whose stress then serves as the next step's start where it is the same:
  // see startStressKept()).  Collective.
  void commit(const Vector& x);
  // The force that each contribution reporting a reactionName() exerts on the bodies through
  // its constrained unknowns at the converged x: the unconstrained residual f_int - f_ext
  // (+ M a) summed over its rows, in the order of those contributions.  It uses the stress
  // of the last evaluation (Newton's last residual, at x; an explicit step's start-of-step
  // stress), so call it before anything re-evaluates the materials.  Collective.
  std::vector<double> supportForces(const Vector& x);
  // The materials alone commit their trial state (after a particle update: the particles'
  // F has moved too).
  void commitMaterials();
  // Evaluates the materials at x (their trial state); returns the trial F and P, views
  // that stay valid until the next evaluation, and x on the overlap map; with F-bar also g,
  // the compatible deformation gradient relative to the map's configuration.
  struct Trial {
    typename ParticleSet<Dim>::Tensors F, P, g;
    Teuchos::RCP<const Vector> xOverlap;
  };
  Trial trialState(const Vector& x);

  const GridGeometry<Dim>& grid() const { return grid_; }
  const ParticleGridMap<Dim>& particleGridMap() const { return particleGridMap_; }
  const EntryDofs<>& entryDofs() const { return entryDofs_; }
  const DofMap<Dim>& dofs() const { return dofs_; }
  ContributionContext<Dim> context(int contribution) const;

 private:
  // The trial F, P and tangent at x, in work_ (unless they are there already); returns x
  // on the overlap map.
  Teuchos::RCP<const Vector> updateStress(const Vector& x);
  // Whether work_ holds the stress at x, bit for bit the same x on every rank.  Collective.
  bool stressIsAt(const Vector& x) const;
  // Whether the stress that trialState(x) left, once committed, is bit for bit the one the
  // next step of this system would evaluate at du = 0: total Lagrangian (P relative to the
  // step start is P itself) and no law with a trial state (re-evaluating a return map from
  // its committed state could differ by round-off).
  bool startStressKept() const;
  // Whether a material has a trial state (a return map, say).
  bool hasTrialState() const;
  // c0 du - r on the overlap map in dynamic steps with the consistent mass (the
  // acceleration), null otherwise.
  Teuchos::RCP<Vector> acceleration(const Vector& xOverlap) const;
  // The residual's m_i (c0 du_i - r_i) on the owned rows, with the lumped mass.
  void addLumpedInertia(const Vector& xOverlap, Vector& residual) const;
  // f_int - f_ext (+ M a) + the contributions' terms at x (given on the overlap map),
  // without the constrained rows.
  void assembleResidual(const Vector& xOverlap, Vector& residual) const;
  // This rank's terms of the residual into f (in its assembly phase); `a`: the
  // consistent-mass acceleration, or null.
  void addLocalResidual(const Teuchos::RCP<const Vector>& a, const Vector& xOverlap,
                        FEMultiVector& f) const;
  // This rank's terms of the Jacobian into J (in its assembly phase).
  void addLocalJacobian(const Vector& xOverlap, FECrsMatrix& J) const;
  // The stress a frozen internal force uses, at the step start, into work_ once: the
  // particles' committed stress (startFromCommittedStress()) or the laws' at du = 0.
  void stressAtStepStart();
  // The largest of the laws' moduli of that kind, made on first use.  Collective.
  double lawModulus(Modulus which = Modulus::largest) const;
  // The diagonal of a prescribed row, made on first use.  Collective.
  double constraintScale() const;
  // Owned local index and prescribed increment of every constrained unknown: the
  // contributions' and the padding's, and the retired nodes' (solver/SystemLayout.hpp).
  // Made once per time, load factor and commit, on which alone the increments depend
  // (solver/Contribution.hpp), not at every evaluation.
  const std::vector<std::pair<LO, double>>& constrainedRows() const;
  std::vector<std::pair<LO, double>> prescribedRows() const;  // the list made afresh
  // Whether a rank has a prescribed unknown, given whether this one has (`mine`).  Asked
  // once: the prescribed unknowns (the contributions' constrained nodes and the padding, see
  // constrainedRows) are the layout's, fixed while the system lives; their increments are
  // not.  Collective the first time.
  bool anyConstrained(bool mine) const;
  // Rows of prescribed unknowns: residual scale (x_i - value), Jacobian row scale e_i.
  void applyConstraints(const Vector& x, Vector* residual, CrsMatrix* jacobian) const;
  // The rows of prescribed unknowns become scale e_i and their columns are zeroed elsewhere,
  // so that a symmetric tangent stays symmetric (for CG).  Exact for iterates that meet the
  // constraints (imposeConstraints), as Newton's do from the guess on: the increments of
  // prescribed unknowns are then zero, and so are the products with their columns.
  // Collective.
  void eliminateConstrained(const std::vector<std::pair<LO, double>>& rows, CrsMatrix& J) const;
  // NumericalError naming the first particle whose trial stress or tangent (where a
  // Jacobian will use it) is NaN or infinite (local).
  void requireFiniteStress() const;
  // NumericalError on every rank naming the first unknown at which the vector, or a row in
  // which the matrix, holds NaN or inf.  Collective.
  void requireFinite(const Vector& v, const std::string& what) const;
  void requireFinite(const CrsMatrix& J) const;
  // "grid node 12 at x = (0.5, 0.25), component y", or the extra unknown it is.
  std::string unknownLabel(GO dof) const;

  std::unique_ptr<DiagonalElimination> explicitElimination_;
  double explicitC0_ = 0.0;  // the c0 it was made with
  const GridGeometry<Dim> grid_;
  Kinematics kinematics_;
  FBar fbar_;
  const ParticleSet<Dim>& particles_;
  const Materials<Dim>& materials_;
  const Contributions& contributions_;
  double time_, loadFactor_;
  ParticleGridMap<Dim> particleGridMap_;
  CellGroups<> cellGroups_;  // F-bar's averaging groups (empty without F-bar)
  double ghostPenalty_;
  GhostFaces ghostFaces_;  // the faces the ghost penalty holds (none without it)
  LayoutCache<Dim> ownLayouts_{false};
  LaidOut<Dim> laidOut_;
  const SystemLayout<Dim>& layout_;
  // The layout's parts, by the names the assembly below uses.
  const std::vector<int>& firstExtra_;
  const DofMap<Dim>& dofs_;
  const EntryDofs<>& entryDofs_;
  const Teuchos::RCP<FECrsGraph>& graph_;
  const Teuchos::RCP<const Import>& importer_;
  Inertia inertia_;
  Teuchos::RCP<const Vector> inertiaOverlap_;  // r on the overlap map (consistent mass only)
  mutable Teuchos::RCP<const Vector> lumpedMass_;
  bool loaded_ = true;  // particlesCarryForces()
  bool frozen_ = false;
  // Whether work_ holds the stress at the step start (du = 0, what a frozen internal force
  // uses): evaluated there, or the particle update's committed by commit().
  bool atStepStart_ = false;
  bool committedStart_ = false;  // startFromCommittedStress()
  // The x of the stress in work_ (null: none, or the materials have committed since), and
  // on the overlap map.
  Teuchos::RCP<const Vector> stressX_, stressXOverlap_;
  GhostFaceDofs<> ghostDofs_;                      // ghostFaces_ as the kernels read them
  mutable std::optional<double> lawModulus_[2];    // lawModulus(largest), lawModulus(young)
  mutable std::optional<double> constraintScale_;  // constraintScale()
  mutable std::optional<bool> anyConstrained_;     // anyConstrained()
  // constrainedRows(); reset by setTime() and commit().
  mutable std::optional<std::vector<std::pair<LO, double>>> constrainedRows_;
  StepWorkspace<Dim> ownWorkspace_;
  typename StepWorkspace<Dim>::Arrays work_;  // trial F, P, A; P, A relative to the step start
  TrialState<Dim> trial_;                     // the materials' trial state
};

}  // namespace impm
