#pragma once
// Transient steps (primer 1.2, 1.5.3): M a + f_int = f_ext + boundary forces, stepped in
// time on the grid.  Every integrator is written as a step of the grid system with the inertia
// term M a, where the integrator's acceleration is linear in the step's displacement du:
//   Newmark (beta, gamma):      a^(n+1) = (du - dt v^n - dt^2 (1/2 - beta) a^n) / (beta dt^2)
//   explicit, central difference: a^n = (du - dt v^n) / dt^2        (u^(n+1) = u^n + dt v^(n+1))
//   explicit, primer eq. 1.53:    a^n = 2 (du - dt v^n) / dt^2       (u^(n+1) = u^n + dt v^n
//                                                                       + dt^2 a^n / 2)
// Explicit integrators take the internal force at the start of the step (eq. 1.51) and lumped
// mass; their velocity update is v^(n+1) = v^n + dt a^n (eq. 1.52); Newmark's is
// v^(n+1) = v^n + dt ((1 - gamma) a^n + gamma a^(n+1)).  The primer's position update, as
// printed, is unconditionally unstable (|amplification|^2 = 1 + (w dt)^2 / 2); it is kept
// for study and central difference is the default.
//
// Total-Lagrangian runs keep the grid fixed and its nodal u, v, a from step to step (FEM);
// updated-Lagrangian runs reset the grid every step: nodal v^n, a^n come from the particles
// (mass-weighted, eq. 1.49, or projected with the consistent mass) and go back to them by
// FLIP/PIC, and particles that change cell migrate to the rank that owns it.
//
// On a fixed grid the particles' u, x and v are the grid's, mapped with weights that do not
// change, and no explicit step reads them: it takes F from the grid's increment at the
// reference positions, its force from the stress, and v^n, a^n from the nodes.  An explicit
// step there commits F and the stress and lets the displacement and velocity wait, summing
// the grid's increments, until a step whose record carries the energies, an output, a
// checkpoint or the run's end reads them (ParticleSet::bringUpToDate): one mapping for the steps
// between, where each step made one (doc/design.md).  Not when the particles carry forces (the
// forces' work needs u every step), nor when the loads or a boundary condition read the
// particles' positions (StepperSetup::particlesReadEveryStep).

#include <Teuchos_ParameterList.hpp>

#include "solver/Stepper.hpp"

namespace impm {

struct DynamicSettings {
  enum class Integrator { newmark, centralDifference, primerTaylor };
  Integrator integrator = Integrator::newmark;
  double timeStep = 0.0, finalTime = 0.0, minTimeStep = 0.0;
  double beta = 0.25, gamma = 0.5;
  double flip = 1.0;  // FLIP fraction of the particle velocity update (0: PIC)
  MassType mass = MassType::lumped;
  bool equilibriumInitialAcceleration = true;
  bool isExplicit() const { return integrator != Integrator::newmark; }
};

template <int Dim>
class DynamicStepper : public Stepper<Dim> {
 public:
  DynamicStepper(const DynamicSettings& settings, StepperSetup<Dim> setup);
  ~DynamicStepper() override;

  // Steps to the final time (from t = 0, or from a restored state); calls onStep after each
  // accepted step.  A step whose Newton solve fails is retried with half the time step, down
  // to the minimum.  Throws NumericalError (with the time) when that fails or a particle
  // leaves the grid.
  void run(const StepCallback<Dim>& onStep) override;
  bool finished() const override;
  StepperState checkpointState() const override;

  // The explicit stability limit h / c, c the largest wave speed sqrt(E / rho).  Collective.
  static double stableTimeStep(const GridGeometry<Dim>& grid, const ParticleSet<Dim>& particles,
                               const Materials<Dim>& materials, const Comm& comm);

 private:
  // Whether a step ending at `time` reaches Final Time (up to round-off of the step).
  bool endsAt(double time) const;
  // The integrator's acceleration a(du) = c0 du - (rv v^n + ra a^n) for a step of size dt.
  struct Acceleration {
    double c0, rv, ra;
  };
  Acceleration acceleration(double dt) const;
  Teuchos::RCP<GridSystem<Dim>> systemAt(double time);
  // v^n and a^n on the grid; a^n is zero when the integrator does not use it (the explicit
  // updates, whose s.ra is 0), which saves a particle-to-grid sum.
  void gridVelocityAndAcceleration(GridSystem<Dim>& system, const Vector& mass,
                                   const Acceleration& s, Teuchos::RCP<Vector>& v,
                                   Teuchos::RCP<Vector>& a);
  Teuchos::RCP<Vector> fromParticles(GridSystem<Dim>& system, const Vector& mass,
                                     const typename ParticleSet<Dim>::Vectors& q);
  void startFixedGrid(GridSystem<Dim>& system);
  // Fixed grid: the nodal u, v, a to and from the stepper's state (checkpoints).  Saved
  // only for a checkpoint: u_, v_ and a_ change only when a step is accepted.
  void saveNodalState(StepperState& s) const;
  void restoreNodalState(GridSystem<Dim>& system);
  Teuchos::RCP<Vector> equilibriumAcceleration(GridSystem<Dim>& system, const Vector& v, double dt);
  bool solveStep(GridSystem<Dim>& system, const Acceleration& s, const Vector& v, const Vector& a,
                 double dt, Teuchos::RCP<Vector>& du, NewtonReport& report);
  // The explicit step with the lumped mass: du -= J^-1 R(du) by elimination, no Krylov solve.
  bool eliminate(GridSystem<Dim>& system, Vector& du, NewtonReport& report) const;
  // The integrator's new grid acceleration and velocity after a step du of size h.
  void integrate(const GridSystem<Dim>& system, const Acceleration& s, double h, const Vector& du,
                 const Vector& v, const Vector& a, Teuchos::RCP<Vector>& vNew,
                 Teuchos::RCP<Vector>& aNew) const;
  // The kinetic energy the integrator conserves, at the new grid velocity v.
  double conservedKineticEnergy(const Vector& mass, const Vector& v) const;
  // 3 of a dynamic step: particles, then their velocities (FLIP/PIC) from v, vNew, aNew.
  // Where the run lets the particles' motion wait and the step's record (its time, whether
  // it carries the energies) does not read it, only their deformation is committed and du
  // joins what waits.
  void gridToParticles(GridSystem<Dim>& system, const Vector& du, const Vector& v,
                       const Vector& vNew, const Vector& aNew, const StepRecord& record);
  bool particlesWait() const override { return !pending_.du.is_null(); }
  // Maps what waits (the particles' ParticleSet::bringUpToDate runs it for every reader).
  void syncParticles() override;

  DynamicSettings settings_;
  bool fixedGrid_;
  bool particlesMayWait_;  // explicit steps on a fixed grid (above)
  // The grid increment the particles' motion waits for (null: none), summed up to the step
  // and time it brings them to.
  struct Waiting {
    Teuchos::RCP<Vector> du;
    int step = 0;
    double time = 0.0;
  } pending_;
  Teuchos::RCP<GridSystem<Dim>> fixedSystem_;
  Teuchos::RCP<Vector> u_, v_, a_;   // nodal state of a fixed grid
  Teuchos::RCP<const Vector> mass_;  // the step's lumped mass (a fixed grid's, kept)
  // Whether the particles' stress is what a step of this run committed (not the initial or
  // a restart's): a moving-grid explicit step then starts from it.
  bool stressCommitted_ = false;
};

}  // namespace impm
