#pragma once
// Everything a time stepper works on (the grid and its ownership, the discretisation, the
// particles with their materials, the extra terms, the Newton solver, the loads), the state
// it carries between steps, and what it reports after every accepted step.

#include <functional>
#include <memory>
#include <vector>

#include "assembly/Kinematics.hpp"
#include "basis/Method.hpp"
#include "solver/GridSystem.hpp"
#include "solver/NewtonSolver.hpp"

namespace impm {

template <int Dim>
struct StepperSetup {
  const NodeOwnership<Dim>& ownership;
  Method method;
  Kinematics kinematics;
  FBar fbar;            // the laws' F averaged over each cell (assembly/FBar.hpp)
  double ghostPenalty;  // gamma of the cut cells' face penalty (assembly/GhostPenalty.hpp)
  ParticleSet<Dim>& particles;
  const Materials<Dim>& materials;
  const std::vector<std::shared_ptr<Contribution<Dim>>>& contributions;
  const NewtonSolver& newton;
  // Sets particles.force (the full external force at `time`).
  std::function<void(double time)> applyLoads;
  // Total-Lagrangian dynamics keeps nodal values (FEM): their initial displacement and
  // velocity at node position x (the deck's fields interpolated at the nodes).
  std::function<void(const double* x, double* u, double* v)> initialNodalState;
  // Called after each accepted step's migration (updated Lagrangian): the load balance may
  // repartition the cells and move the particles again.  May be empty.
  std::function<void(int step)> afterMigration;
  // Keep a step's unknowns and graph for the next steps while the (particle, node) pairs
  // stay the same (solver/SystemLayout.hpp); false: build them every step.
  bool reuseLayout = true;
  // The steps whose record carries the energies: every this many and the last (the history's
  // rows).  Each costs passes over the particles and reductions, as much as half a residual
  // evaluation of an explicit step.
  int energiesEvery = 1;
  // Whether the loads (a formula, which may read x) or a boundary condition read the
  // particles' positions every step; if not, explicit steps on a fixed grid may let the
  // particles' motion wait (solver/DynamicStepper.hpp).
  bool particlesReadEveryStep = true;
};

// What a stepper carries from one step to the next: all a restart needs to continue as if
// the run had not stopped (checkpoints save it).
struct StepperState {
  int step = 0;             // accepted steps
  double time = 0.0;        // dynamic: the time reached; static: Final Time x load factor
  double loadFactor = 0.0;  // static: the load factor reached
  double size = 0.0;        // the next step's size (load increment or time step), after
                            // cutbacks and regrowth; 0: the nominal size
  int attempts = 0;         // failed attempts of the step under way
  double bodyWork = 0.0;    // work of the body forces so far
  bool started = false;     // dynamic: the initial state (acceleration) is set up
  // By global unknown (owned ones; all of them on every rank once restored): dynamic runs
  // on a fixed grid, the nodal u, v, a; static runs, the predictor's last increment per unit
  // load factor in nodalU (solver/QuasiStaticStepper.hpp).
  std::vector<GO> nodalDofs;
  std::vector<double> nodalU, nodalV, nodalA;
};

struct StepRecord {
  int step = 0;
  double time = 0.0;
  double dt = 0.0;
  double loadFactor = 1.0;
  int attempts = 1;   // 1 + number of cutbacks before this step was accepted
  bool last = false;  // the run ends with this step
  NewtonReport newton;
  double kineticEnergy = 0.0, strainEnergy = 0.0, dissipation = 0.0, externalWork = 0.0;
  // Whether kineticEnergy, strainEnergy and dissipation were computed for this step
  // (StepperSetup::energiesEvery); the external work always is.
  bool hasEnergies = true;
  // The reaction of every support that reports one (Contribution::reactionName), in order.
  std::vector<double> supportForces;
};

// The grid solution of an accepted step, for output (vectors on system.unknownMap()).
template <int Dim>
struct StepGrid {
  const GridSystem<Dim>& system;
  const Vector& du;
  Teuchos::RCP<const Vector> velocity;  // null in static steps
  Teuchos::RCP<const Vector> mass;      // lumped nodal mass; null in static steps
};

template <int Dim>
using StepCallback = std::function<void(const StepRecord&, const StepGrid<Dim>&)>;

// The work of the contributions (boundary forces) so far.
template <int Dim>
double contributionWork(const std::vector<std::shared_ptr<Contribution<Dim>>>& contributions) {
  double work = 0.0;
  for (const auto& c : contributions)
    work += c->work();
  return work;
}

}  // namespace impm
