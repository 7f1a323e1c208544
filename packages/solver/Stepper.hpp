#pragma once
// What the quasi-static and the dynamic steppers share.  Each of their steps reads as the
// primer's loop (1.5.3, 1.6.2):
//   1. buildSystem     the particle-grid map at the particles' positions, the unknowns;
//   2. solve           Newton on the grid: particle to grid (mass, forces) in every
//                      evaluation of the residual and its Jacobian;
//   3. gridToParticles the particles take the step's displacement, deformation and stress;
//                      the materials and the boundary conditions commit their state;
//   4. accept          record the step, report it (output, checkpoints), migrate the
//                      particles to their cells' ranks, let a cut step size grow back.
// A step whose Newton solve fails is cut back instead of 3-4: nothing was committed, so the
// particles and the materials' state are those of the last accepted step.

#include <iosfwd>
#include <string>

#include "solver/StepperSetup.hpp"

namespace impm {

template <int Dim>
class Stepper {
 public:
  // nominal: the step size the deck asks for; minimum: the smallest a cutback may reach.
  // `retireNodes`: whether a step may keep a layout whose nodes the particles partly left
  // (static steps: solver/SystemLayout.hpp).
  Stepper(StepperSetup<Dim> setup, double nominal, double minimum, bool retireNodes = false);
  virtual ~Stepper() = default;

  // Runs the steps left (all, or those after a restored state); calls onStep after each
  // accepted one.  Throws NumericalError when a step fails at the smallest size.
  virtual void run(const StepCallback<Dim>& onStep) = 0;
  // Whether the state holds no step to take (a restart from the end of a run, or from a
  // time past the deck's Final Time).
  virtual bool finished() const = 0;

  // The state carried between steps as it was when the last step was accepted (what a
  // checkpoint saves, also when the run stops in the middle of the next step: nothing of a
  // step is committed before it is accepted), and its restoration before run().
  const StepperState& state() const { return accepted_; }
  // The same with what a stepper keeps elsewhere and saves only when asked (the nodal state
  // of a fixed grid): what a checkpoint writes.
  virtual StepperState checkpointState() const { return accepted_; }
  void restore(const StepperState& state) { state_ = accepted_ = state; }
  // The system of the next step, built ahead of it (a run's set-up builds it to find deck
  // errors before anything is written: NumericalError when a particle lies outside the grid
  // or a boundary condition reaches no integration point).  Its layout stays in the cache,
  // so the step takes it over unless a repartition came between.  Collective.
  void buildNextSystem() { buildSystem(state_.time, state_.loadFactor); }
  // The next step builds its layout and preconditioner from scratch (at checkpoints: both
  // are caches, and a restarted run starts without them; a kept layout that covers the next
  // map is not the layout built for it, nor is its halo, core/DofMap.hpp).
  void forgetCaches() {
    layouts_.forget();
    setup_.newton.forgetPreconditioner();
  }
  // How often a step's unknowns and graph were built and reused (with retired nodes).
  const LayoutCache<Dim>& layouts() const { return layouts_; }

 protected:
  // The size of the next step (after cutbacks and regrowth).
  double size() const { return state_.size > 0 ? state_.size : nominal_; }

  // 1. The system of a step at `time` with load factor `loadFactor`.  Collective.
  Teuchos::RCP<GridSystem<Dim>> buildSystem(double time, double loadFactor);

  // 2. Newton from the guess in du; true when it converged.
  bool solve(GridSystem<Dim>& system, Vector& du, NewtonReport& report) const;

  // The step of size size() failed: the next attempt takes half of it, or, when that is
  // below the minimum, NumericalError says "<step> failed: <why>; |R| history ...; the
  // <quantity> cannot be cut below <minimum parameter> = ...".  `logged` names the step in
  // the log line.
  void cutBack(const std::string& step, const std::string& logged, const std::string& quantity,
               const std::string& minimumParameter, const NewtonReport& report);

  // 3. Grid to particles and commit; the body forces' work over the step (times workScale,
  // the mean load factor of a static step) is added, and the supports' reactions at the
  // converged increment are kept for the step's record.  With `move` false the particles
  // take the step's deformation only, and the caller moves them later (their displacement
  // then waits: particlesWait(); never when they carry forces, whose work needs it).
  void gridToParticles(GridSystem<Dim>& system, const Vector& du, double workScale,
                       bool move = true);

  // Whether the record of the step being accepted (number state_.step + 1, before accept
  // counts it) carries the energies: every energiesEvery-th step and the last.  The same
  // answer on every rank: the energies are sums over all of them.
  bool recordsEnergies(const StepRecord& record) const {
    return record.last || (state_.step + 1) % setup_.energiesEvery == 0;
  }

  // NumericalError (on every rank) when a particle's position, velocity, F or stress, or an
  // energy of the record, is NaN or infinite after the update (the position and velocity
  // where they are up to date: while they wait, syncParticles checks them).  Collective.
  void requireFiniteParticles(const StepRecord& record) const;
  // The same for the positions and velocities alone, as they are at step `step`, time `time`.
  void requireFiniteMotion(int step, double time) const;
  // Whether the particles' displacement, position and velocity wait for syncParticles.
  virtual bool particlesWait() const { return false; }
  // Brings the particles' displacement, position and velocity up to the grid's where the
  // stepper let them wait (explicit steps on a fixed grid: DynamicStepper, which has the
  // particle set run it for every reader between steps, ParticleSet::bringUpToDate).
  // NumericalError when one is not finite.  Collective.
  virtual void syncParticles() {}
  // Runs `phase`.  When it throws NumericalError while the particles' motion waits, the
  // position by which its message names a particle is not the particle's: syncParticles,
  // and the phase again, which fails alike (a failing phase commits nothing) and names the
  // particle where it is.  Collective.
  void namingCurrentPositions(const std::function<void()>& phase);

  // 4. The step is accepted: fills the record's step, attempts and, where recordsEnergies,
  // energies (the kinetic energy is the caller's), regrows the step size, reports, migrates.
  void accept(StepRecord& record, const StepGrid<Dim>& grid, const StepCallback<Dim>& onStep);

  StepperSetup<Dim> setup_;
  // The graph's node pairs: a stepper whose Jacobians are all diagonal in the nodes (an
  // explicit one) asks for NodeCoupling::self.
  NodeCoupling nodeCoupling_ = NodeCoupling::shared;
  StepperState state_;     // as the step under way changes it
  StepperState accepted_;  // at the last accepted step
  std::ostream* log_;      // rank 0: the progress log; elsewhere null

 private:
  double nominal_, minimum_;
  StepWorkspace<Dim> workspace_;
  LayoutCache<Dim> layouts_;
  // Kept from step to step, see firstRows: u before the step, the energy densities.
  typename ParticleSet<Dim>::Vectors uBefore_;
  typename ParticleSet<Dim>::Scalars energyDensity_, dissipationDensity_;
  std::vector<double> supportForces_;  // of the step being accepted

  // requireFiniteMotion's check on this rank (not collective).
  void throwIfMotionNotFinite(const std::string& when) const;
};

}  // namespace impm
