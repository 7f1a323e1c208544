#include "app/Simulation.hpp"

#include "basis/CornerWeights.hpp"

#include <Teuchos_CommHelpers.hpp>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <limits>
#include <sstream>

#include "app/BoundaryConditions.hpp"
#include "app/GridFields.hpp"
#include "app/History.hpp"
#include "app/TimeIntegration.hpp"
#include "assembly/DomainDistortion.hpp"
#include "assembly/Energy.hpp"
#include "assembly/ParticleUpdate.hpp"
#include "bc/RobinEnd.hpp"
#include "core/Collective.hpp"
#include "core/Errors.hpp"
#include "core/Migration.hpp"
#include "core/StopRequest.hpp"
#include "core/Timers.hpp"
#include "io/InputDeck.hpp"
#include "io/OutputLock.hpp"
#include "io/Version.hpp"
#include "material/MaterialFactory.hpp"
#include "solver/DynamicStepper.hpp"
#include "solver/QuasiStaticStepper.hpp"

namespace impm {

namespace {

template <int Dim>
GridGeometry<Dim> readGrid(const Teuchos::ParameterList& p) {
  const auto& cells = p.get<Teuchos::Array<int>>("Cells");
  const auto& length = p.get<Teuchos::Array<double>>("Length");
  const auto& origin = p.get<Teuchos::Array<double>>("Origin");
  if (static_cast<int>(length.size()) != Dim)
    throw InputError("Grid/Length", "has " + std::to_string(length.size()) +
                                        " entries but Grid/Cells has " + std::to_string(Dim));
  if (!origin.empty() && static_cast<int>(origin.size()) != Dim)
    throw InputError("Grid/Origin", "has " + std::to_string(origin.size()) +
                                        " entries but Grid/Cells has " + std::to_string(Dim));
  std::array<double, Dim> o, l;
  std::array<int, Dim> n;
  for (int d = 0; d < Dim; ++d)
    o[d] = origin.empty() ? 0.0 : origin[d], l[d] = length[d], n[d] = cells[d];
  return makeGridGeometry<Dim>(o, l, n);
}

Kinematics readKinematics(const Teuchos::ParameterList& p, Method method) {
  const auto& k = p.get<std::string>("Kinematics");
  if (k == "auto")
    return method == Method::fem ? Kinematics::totalLagrangian : Kinematics::updatedLagrangian;
  if (k == "updated Lagrangian" && method == Method::fem)
    throw InputError("Discretization/Kinematics",
                     "fem integrates on the grid as a fixed mesh: use total Lagrangian");
  return k == "total Lagrangian" ? Kinematics::totalLagrangian : Kinematics::updatedLagrangian;
}

std::string format(double v) {
  std::ostringstream s;
  s << std::setprecision(8) << v;
  return s.str();
}

}  // namespace

template <int Dim>
Simulation<Dim>::Simulation(const Teuchos::ParameterList& deck, const std::string& deckFile,
                            const std::string& outputDirectory,
                            const Teuchos::RCP<const Comm>& comm, const std::string& restartFile,
                            Verbosity verbosity, bool allowPhysicsChange)
    : comm_(comm),
      deck_(deck),
      deckFile_(deckFile),
      outputDirectory_(outputDirectory),
      verbosity_(verbosity) {
  IMPM_TIMER("set-up");
  // Local checks first, agreed on by every rank; then the collective set-up.
  collectively(*comm_, [&] { setUp(deck_); });
  collectively(*comm_, [&] { checkExplicitTimeStep(); });
  collectively(*comm_, [&] {
    newton_ = std::make_unique<NewtonSolver>(deck_.sublist("Solver"), comm_, operatorKind(), Dim);
    const bool iterations =
        verbosity_ == Verbosity::verbose ||
        (verbosity_ == Verbosity::normal && deck_.sublist("Solver").get<bool>("Print Iterations"));
    newton_->setLog(iterations ? &std::cout : nullptr, "    ");
  });
  const GlobalId local = particles_.size();
  Teuchos::reduceAll(*comm_, Teuchos::REDUCE_SUM, local, Teuchos::outArg(totalParticles_));
  identity_ = runIdentity<Dim>(deck_, ownership_->grid(), particles_, totalParticles_, *comm_);
  identity_.allowPhysicsChange = allowPhysicsChange;
  const auto& ti = deck_.sublist("Time Integration");
  gridFields_ = std::make_unique<GridFields<Dim>>(
      *ownership_, isStatic(ti) || kinematics_ == Kinematics::totalLagrangian, !isStatic(ti));
  loadBalance_ = std::make_unique<LoadBalance<Dim>>(
      deck_.sublist("Load Balance"),
      kinematics_ == Kinematics::updatedLagrangian && comm_->getSize() > 1);
  if (!restartFile.empty())
    restart(restartFile);
  // The first step's system, built now: particles outside the grid, or boundary conditions
  // on nodes no integration point reaches, are deck errors.  The stepper keeps its layout
  // for the first step.
  stepper_ = makeStepper();
  try {
    stepper_->buildNextSystem();
  } catch (const NumericalError& e) {
    throw InputError("Bodies", e.what());
  }
  // So are loads that are not finite (a formula NaN at some particles) when the run starts;
  // static runs evaluate them at Final Time.
  const double loadTime = isStatic(ti) ? ti.get<double>("Final Time")
                          : restored_  ? restored_->stepper.time
                                       : 0.0;
  collectively(*comm_, [&] { bodies_->applyLoads(particles_, loadTime); });
}

template <int Dim>
Simulation<Dim>::~Simulation() = default;

template <int Dim>
void Simulation<Dim>::setUp(const Teuchos::ParameterList& deck) {
  const auto& output = deck.sublist("Output");
  prefix_ = output.get<std::string>("Prefix").empty() ? deckStem(deckFile_)
                                                      : output.get<std::string>("Prefix");
  // A path in the prefix put files outside the locked output directory ("../x") or in a
  // directory that the checkpoint series did not scan (Checkpoints Kept was not applied).
  if (prefix_.find('/') != std::string::npos || prefix_ == "." || prefix_ == "..")
    throw InputError("Output/Prefix", "'" + prefix_ +
                                          "' is a path; the prefix is a file name (the "
                                          "directory is Output/Directory or --output-dir)");
  if (outputDirectory_.empty())
    outputDirectory_ = output.get<std::string>("Directory");
  const auto grid = readGrid<Dim>(deck.sublist("Grid"));
  ownership_ = std::make_unique<NodeOwnership<Dim>>(grid, comm_);
  method_ = parseMethod(deck.sublist("Discretization").get<std::string>("Method"));
  kinematics_ = readKinematics(deck.sublist("Discretization"), method_);
  fbar_ = parseFBar(deck.sublist("Discretization").get<std::string>("F-bar"));

  const auto& materials = deck.sublist("Materials");
  for (auto it = materials.begin(); it != materials.end(); ++it) {
    materialNames_.push_back(materials.name(it));
    materials_.push_back(
        createMaterial<Dim>(materials.name(it), materials.sublist(materials.name(it))));
  }
  bodies_ = std::make_unique<Bodies<Dim>>(deck, materialNames_, grid);
  particles_ = bodies_->createParticles(method_, ownership_->decomposition(), comm_->getRank(),
                                        materials_, kinematics_ == Kinematics::updatedLagrangian);
  declareFBarFields(particles_, fbar_, kinematics_);
  // Bodies are seeded on the owner of X; an updated-Lagrangian map starts from x = X + u0,
  // and F-bar needs every particle on the owner of that cell (assembly/FBar.hpp).
  if (fbar_ != FBar::none && kinematics_ == Kinematics::updatedLagrangian && comm_->getSize() > 1)
    migrateToOwners(particles_, ownership_->decomposition(), *comm_);
  declareMaterialVariables(particles_, materials_);
  initializeMaterials(particles_, materials_, true);
  addDerivedFields();
  outputColumns(particles_, outputFields(output));  // Output/Fields names output fields
  conditions_ = createBoundaryConditions<Dim>(deck, *bodies_, grid, method_, kinematics_);
  if constexpr (Dim == 1) {
    for (const auto& c : conditions_) {
      auto robin = std::dynamic_pointer_cast<RobinEnd>(c);
      if (!robin)
        continue;
      if (robin->isLeft() && !left_)
        left_ = robin;
      if (!robin->isLeft() && !right_)
        right_ = robin;
    }
  }
  verification_ = std::make_unique<Verification>(deck.sublist("Verification"));
}

template <int Dim>
void Simulation<Dim>::addDerivedFields() {
  // Total Lagrangian: the map stays on the reference domains; the deformed ones are drawn.
  if (kinematics_ == Kinematics::totalLagrangian)
    particles_.addDerivation([](ParticleSet<Dim>& ps) { followDeformation<Dim>(ps); });
  particles_.addDerivation([this](ParticleSet<Dim>& ps) {  // sigma_zz, an output-only field
    for (std::size_t m = 0; m < materials_.size(); ++m)
      materials_[m]->outOfPlaneStress(evaluationOf(ps, materials_, static_cast<int>(m), ps.F),
                                      ps.stressZZ);
  });
}

template <int Dim>
void Simulation<Dim>::restart(const std::string& file) {
  IMPM_TIMER("checkpoint read");
  restorePartition(file);
  // The particles the deck makes identified the problem; the checkpoint's replace them.
  particles_ = ParticleSet<Dim>();
  bodies_->declareFields(particles_, method_);
  declareFBarFields(particles_, fbar_, kinematics_);
  declareMaterialVariables(particles_, materials_);
  restored_ = std::make_unique<RunState<Dim>>(readCheckpoint<Dim>(
      file, identity_, ownership_->decomposition(), kinematics_ == Kinematics::totalLagrangian,
      particles_, gridFields_->values(), comm_));
  collectively(*comm_, [&] {
    initializeMaterials(particles_, materials_, false);
    if (restored_->contributions.size() != conditions_.size())
      throw FileError(
          file, "holds the state of " + std::to_string(restored_->contributions.size()) +
                    " boundary conditions; this deck has " + std::to_string(conditions_.size()));
    for (std::size_t c = 0; c < conditions_.size(); ++c) {
      try {
        conditions_[c]->restore(restored_->contributions[c]);
      } catch (const std::invalid_argument& e) {
        throw FileError(file, std::string("boundary condition state: ") + e.what());
      }
    }
  });
  addDerivedFields();
  // The uninterrupted run balanced the ranks after the checkpoint's step (the checkpoint was
  // written before): so does the continued one.
  balanceAfterStep(restored_->stepper.step);
}

template <int Dim>
void Simulation<Dim>::restorePartition(const std::string& file) {
  const auto partition = readPartition(file, *comm_);
  if (partition.ranks != comm_->getSize() || partition.cellOwners.empty())
    return;  // blocks, or another number of ranks: the load balance starts afresh
  collectively(*comm_, [&] {
    try {
      ownership_->repartition(
          Decomposition<Dim>(ownership_->grid(), comm_->getSize(), partition.cellOwners));
    } catch (const std::invalid_argument& e) {
      throw FileError(file, std::string("its partition of the cells does not fit: ") + e.what());
    }
  });
  gridFields_->redistribute(ownership_->nodeMap());
  loadBalance_->restore(partition.imbalanceAfterRepartition);
}

template <int Dim>
void Simulation<Dim>::balanceAfterStep(int step) {
  const bool log = comm_->getRank() == 0 && verbosity_ != Verbosity::quiet;
  loadBalance_->afterStep(step, *ownership_, particles_, *gridFields_, log ? &std::cout : nullptr);
}

template <int Dim>
void Simulation<Dim>::writeCheckpoint(CheckpointSeries& series, int step, Stepper<Dim>& stepper,
                                      const Output<Dim>& output) const {
  IMPM_TIMER("checkpoint");
  RunState<Dim> state{stepper.checkpointState(), {}, output.exodusSteps(), {}, {}};
  state.partition = {comm_->getSize(), ownership_->decomposition().cellOwners(),
                     loadBalance_->imbalanceAfterRepartition()};
  for (const auto& c : conditions_)
    state.contributions.push_back(c->state());
  impm::writeCheckpoint<Dim>(series.pathOf(step), identity_, particles_, totalParticles_, state,
                             gridFields_->values());
  if (comm_->getRank() == 0)
    series.written(step);
  stepper.forgetCaches();
}

// Below this many grid nodes a system takes the small-system default (MUMPS).  The crossover
// with the iterative defaults was measured: in 2-D near 4000 nodes; in 3-D, where a node has
// 3 unknowns coupled to 27 nodes and a factorisation fills in faster, between 153 nodes (MUMPS
// 2x faster on the column) and 400 (MueLu 1.4x; 4.4x at 1836 nodes).
constexpr GlobalId smallGridNodes(int dim) {
  return dim == 3 ? 300 : 4000;
}

// The kind of operator the Newton solves meet, which picks the default linear solver
// (solver/LinearSolver.hpp).  A Newmark step's operator M / (beta dt^2) + K is
// mass-dominated when dt is short against the wave transit time of a cell h/c: the ratio of
// K's diagonal to the mass term's is about (c dt / h)^2 beta, so Jacobi leaves a condition
// number of about 1 + 2 (c dt / h)^2 to CG, a handful of iterations below Courant number 2.

template <int Dim>
OperatorKind Simulation<Dim>::operatorKind() const {
  if (Dim == 1)
    return OperatorKind::small;
  // Below a few thousand nodes a sparse direct factorisation costs milliseconds, whatever
  // the operator (stiffness or mass dominated, symmetric or not).
  if (ownership_->grid().numNodes() < smallGridNodes(Dim))
    return OperatorKind::small;
  const auto& ti = deck_.sublist("Time Integration");
  const auto& type = ti.get<std::string>("Type");
  if (type == "explicit")
    return OperatorKind::massDominated;
  if (type != "static") {
    const double transit =
        DynamicStepper<Dim>::stableTimeStep(ownership_->grid(), particles_, materials_, *comm_);
    if (ti.get<double>("Time Step") <= 2.0 * transit)
      return OperatorKind::massDominated;
  }
  // F-bar's tangent is not symmetric, whatever the laws' (assembly/FBar.hpp).
  const bool symmetric =
      fbar_ == FBar::none && std::all_of(materials_.begin(), materials_.end(),
                                         [](const auto& m) { return m->hasSymmetricTangent(); });
  return symmetric ? OperatorKind::symmetricStiffness : OperatorKind::stiffness;
}

template <int Dim>
void Simulation<Dim>::checkExplicitTimeStep() const {
  const auto& ti = deck_.sublist("Time Integration");
  if (ti.get<std::string>("Type") != "explicit")
    return;
  const double limit =
      DynamicStepper<Dim>::stableTimeStep(ownership_->grid(), particles_, materials_, *comm_);
  const double dt = ti.get<double>("Time Step");
  std::ostringstream why;
  why << "Time Step = " << dt << " exceeds the explicit stability limit h/c = " << limit
      << " (h the cell size, c the largest wave speed sqrt(E/rho))";
  if (dt > limit && !ti.get<bool>("Allow Unstable Time Step"))
    throw InputError("Time Integration/Time Step",
                     why.str() + "; reduce it, or set Allow Unstable Time Step to run anyway");
  if (comm_->getRank() != 0)
    return;
  if (dt > limit)
    std::cout << "impm: warning: " << why.str() << "; running as asked\n";
  if (ti.get<std::string>("Position Update") == "primer")
    std::cout << "impm: warning: the primer's position update (eq. 1.53 as printed) is "
                 "unconditionally unstable: errors grow by sqrt(1 + (w dt)^2 / 2) per step\n";
}

template <int Dim>
bool Simulation<Dim>::particlesReadEveryStep() const {
  return bodies_->loadsReadPositions() ||
         std::any_of(conditions_.begin(), conditions_.end(),
                     [](const auto& c) { return c->readsParticleMotion(); });
}

template <int Dim>
void Simulation<Dim>::applyLoads(double time) {
  try {
    collectively(*comm_, [&] { bodies_->applyLoads(particles_, time); });
  } catch (const InputError& e) {  // a load formula that became NaN or inf during the run
    throw NumericalError(e.what());
  }
}

template <int Dim>
std::vector<double> Simulation<Dim>::reactions() const {
  const double none = std::numeric_limits<double>::quiet_NaN();
  return {left_ ? left_->force() : none, right_ ? right_->force() : none};
}

template <int Dim>
void Simulation<Dim>::printHeader() const {
  if (comm_->getRank() != 0 || verbosity_ == Verbosity::quiet)
    return;
  const auto& grid = ownership_->grid();
  const auto& ti = deck_.sublist("Time Integration");
  std::cout << versionLine() << "\n";  // which impm made the results (io/Version.hpp)
  std::cout << "impm: " << deckFile_ << ": " << Dim << "-D, " << methodName(method_) << ", "
            << (kinematics_ == Kinematics::totalLagrangian ? "total" : "updated") << " Lagrangian, "
            << (fbar_ == FBar::none ? "" : "F-bar, ") << ti.get<std::string>("Type") << ", "
            << totalParticles_ << " integration points, " << grid.cells[0];
  for (int d = 1; d < Dim; ++d)
    std::cout << " x " << grid.cells[d];
  std::cout << " cells, " << comm_->getSize() << " rank" << (comm_->getSize() > 1 ? "s" : "")
            << ", " << newton_->linearSolverName() << "\n";
}

template <int Dim>
void Simulation<Dim>::printProgress(const StepRecord& r, const std::vector<double>& F) const {
  const auto& ti = deck_.sublist("Time Integration");
  const double fraction = progressFraction(r.time, r.loadFactor);
  if (!progress_->due(r.last) || comm_->getRank() != 0)
    return;
  std::cout << "  step " << r.step;
  if (isStatic(ti)) {
    std::cout << "  load " << std::setprecision(8) << r.loadFactor;
  } else {
    std::cout << "  t " << std::setprecision(6) << r.time << "  dt " << r.dt;
    if (r.hasEnergies)
      std::cout << "  energy " << std::setprecision(8)
                << r.kineticEnergy + r.strainEnergy + r.dissipation;
  }
  const double residual = r.newton.residualNorms.empty() ? 0.0 : r.newton.residualNorms.back();
  std::cout << "  newton " << r.newton.iterations() << "  linear "
            << r.newton.totalLinearIterations() << "  |R| " << std::scientific
            << std::setprecision(2) << residual << std::defaultfloat;
  if (left_)
    std::cout << "  F0 " << format(F[0]);
  if (right_)
    std::cout << "  FL " << format(F[1]);
  std::cout << progress_->timing(fraction) << "\n";
}

// How much of the run is done: the load factor of a static run, the time over the final
// time of a dynamic one.
template <int Dim>
double Simulation<Dim>::progressFraction(double time, double loadFactor) const {
  const auto& ti = deck_.sublist("Time Integration");
  return isStatic(ti) ? loadFactor : time / ti.get<double>("Final Time");
}

template <int Dim>
std::unique_ptr<Output<Dim>> Simulation<Dim>::startOutput(const History<Dim>& history) {
  // The files' creation and the initial state are output time, as the steps' writes are.
  IMPM_TIMER("output");
  using Domains = typename Output<Dim>::Domains;
  const Domains domains = particles_.has(kCornersField) ? Domains::corners
                          : method_ == Method::cpdi     ? Domains::parallelogram
                          : method_ == Method::gimp     ? Domains::box
                                                        : Domains::none;
  particles_.bringUpToDate();
  OutputResume resume{
      restored_ ? restored_->stepper.step : 0, restored_ ? restored_->exodusSteps : 0, {}};
  if (restored_)  // the changes --allow-physics-change let through, where the rows change
    for (const auto& change : restored_->physicsChanges)
      resume.notes.push_back("restart at step " + std::to_string(resume.step) + " changes " +
                             change + " (--allow-physics-change)");
  std::unique_ptr<Output<Dim>> output;
  collectively(*comm_, [&] {
    output = std::make_unique<Output<Dim>>(
        deck_.sublist("Output"), outputDirectory_, prefix_, *ownership_, particles_,
        totalParticles_, history.columns(), gridFields_->names(),
        std::vector<std::string>{"F0", "FL"}, domains, restored_ ? &resume : nullptr);
  });
  if (restored_)
    return output;  // the initial state is in the files already
  StepRecord initial;
  initial.kineticEnergy = kineticEnergy<Dim>(particles_, *comm_);
  {
    const typename ParticleSet<Dim>::Scalars W("W", particles_.size()), D("D", particles_.size());
    const auto energies = materialEnergies<Dim>(particles_, materials_, *comm_, W, D);
    initial.strainEnergy = energies.strain;
    initial.dissipation = energies.dissipated;
  }
  initial.loadFactor = isStatic(deck_.sublist("Time Integration")) ? 0.0 : 1.0;
  const auto F0 = reactions();
  output->appendHistory(history.row(initial, F0[0], F0[1], particles_, *comm_));
  collectively(*comm_, [&] { output->writeInitialFields(0.0, gridFields_->values(), F0); });
  return output;
}

template <int Dim>
void Simulation<Dim>::warnOfDistortedDomains(int step) {
  // Updated-Lagrangian gimp and cpdi domains follow F; the first step past the mark says so.
  if (distortionWarned_ || kinematics_ != Kinematics::updatedLagrangian ||
      (method_ != Method::gimp && method_ != Method::cpdi))
    return;
  const auto d = domainDistortion(particles_, *comm_);
  if (d.worst <= kDistortionWarning)
    return;
  distortionWarned_ = true;
  if (comm_->getRank() == 0)
    std::cout << "impm: warning: step " << step << ": the domain of particle " << d.particle
              << " has lost its shape: |D| |D^-1| / Dim = " << std::setprecision(3) << d.worst
              << " (D maps its initial domain onto the current one; 1: the initial shape, "
              << kDistortionWarning << ": about ten times longer than wide; smallest det D "
              << d.smallestJ
              << "); such domains reach far through cells whose nodes they barely cover, and "
                 "the results there lose accuracy (doc/theory.md).  Warned once\n"
              << std::setprecision(6);
}

template <int Dim>
double Simulation<Dim>::ghostPenalty() const {
  // Both kinematics: on the reference grid of total-Lagrangian steps a sliver makes the
  // stiffness as nearly singular, and the answer then depended on the rank count (doc/theory.md).
  return deck_.sublist("Discretization").get<double>("Ghost Penalty");
}

template <int Dim>
std::unique_ptr<Stepper<Dim>> Simulation<Dim>::makeStepper() {
  StepperSetup<Dim> setup{
      *ownership_,
      method_,
      kinematics_,
      fbar_,
      ghostPenalty(),
      particles_,
      materials_,
      conditions_,
      *newton_,
      [this](double t) { applyLoads(t); },
      [this](const double* x, double* u, double* v) { bodies_->initialNodalState(x, u, v); },
      [this](int step) { balanceAfterStep(step); },
      deck_.sublist("Solver").get<bool>("Graph Reuse"),
      deck_.sublist("Output").get<int>("History Every"),
      particlesReadEveryStep()};
  const auto& timeIntegration = deck_.sublist("Time Integration");
  std::unique_ptr<Stepper<Dim>> stepper;
  if (isStatic(timeIntegration))
    stepper = std::make_unique<QuasiStaticStepper<Dim>>(timeIntegration, setup);
  else
    stepper = std::make_unique<DynamicStepper<Dim>>(dynamicSettings(timeIntegration), setup);
  if (restored_)
    stepper->restore(restored_->stepper);
  return stepper;
}

template <int Dim>
std::vector<std::string> Simulation<Dim>::run() {
  printHeader();
  std::vector<std::string> supports;
  for (const auto& c : conditions_)
    if (!c->reactionName().empty())
      supports.push_back(c->reactionName());
  History<Dim> history(bodies_->columnNames(), supports);
  if (restored_ && stepper_->finished()) {
    // Nothing to continue: the directory stays as the run that wrote the checkpoint left it
    // (continuing the files would cut them back to the checkpoint's step).
    if (comm_->getRank() == 0)
      std::cout << "impm: the checkpoint is at the end of the run (step " << stepper_->state().step
                << ", t = " << stepper_->state().time
                << "): no step to take, nothing written; raise Time Integration/Final Time to "
                   "continue it\n";
    return {};
  }
  if (!restored_)
    balanceAfterStep(0);  // the bodies may lie in some ranks' cells only
  // One writer per output directory, from its first file to the last (io/OutputLock.hpp).
  const OutputLock lock(outputDirectory_, *comm_);
  const auto output = startOutput(history);
  CheckpointSeries checkpoints(deck_.sublist("Output"), outputDirectory_, prefix_);
  int checkpointed = -1;      // the step of the last checkpoint written
  bool betweenSteps = false;  // the stop came after an accepted step, not inside one
  double finalTime = stepper_->state().time;
  progress_ = std::make_unique<ProgressLog>(
      verbosity_, progressFraction(stepper_->state().time, stepper_->state().loadFactor));
  const StepCallback<Dim> onStep = [&](const StepRecord& r, const StepGrid<Dim>& step) {
    gridFields_->update(step);
    const auto F = reactions();
    if (r.hasEnergies)  // the history's steps (Output/History Every)
      output->appendHistory(history.row(r, F[0], F[1], particles_, *comm_));
    printProgress(r, F);
    warnOfDistortedDomains(r.step);
    if (output->writesFields() && (output->due(r.step) || r.last)) {
      IMPM_TIMER("output");
      particles_.bringUpToDate();
      collectively(*comm_,
                   [&] { output->writeFields(r.time, particles_, gridFields_->values(), F); });
    }
    if (checkpoints.due(r.step, r.last)) {
      particles_.bringUpToDate();  // the drawn domains too, as the outputs have them
      writeCheckpoint(checkpoints, r.step, *stepper_, *output);
      checkpointed = r.step;
    }
    finalTime = r.time;
    if (!r.last && stopAgreed(*comm_)) {
      betweenSteps = true;
      throw StopRequest();
    }
  };
  try {
    stepper_->run(onStep);
  } catch (const StopRequest&) {
    // After an accepted step, or in the middle of one (abandoned: nothing of it was
    // committed): the checkpoint is of the last accepted step.
    const auto& state = stepper_->state();
    if (checkpointed != state.step) {
      particles_.bringUpToDate();
      writeCheckpoint(checkpoints, state.step, *stepper_, *output);
    }
    throw RunStopped(state.step, state.time, !betweenSteps, checkpoints.pathOf(state.step));
  }
  particles_.bringUpToDate();  // for the verification
  return finish(finalTime, output->files(), stepper_->layouts());
}

template <int Dim>
std::vector<std::string> Simulation<Dim>::finish(double finalTime,
                                                 const std::vector<std::string>& files,
                                                 const LayoutCache<Dim>& layouts) const {
  const auto F = reactions();
  const auto result = verification_->check<Dim>(particles_, comm_, finalTime, F[0], F[1]);
  const auto counts = newton_->preconditionerCounts();
  const std::string path = outputDirectory_ + "/" + prefix_ + "_verification.csv";
  collectively(*comm_, [&] {
    if (comm_->getRank() != 0)
      return;
    if (counts.builds + counts.reuses > 0)
      std::cout << "  preconditioner: built " << counts.builds << " times, reused " << counts.reuses
                << " times\n";
    if (layouts.built() + layouts.reused() > 1)
      std::cout << "  graph: built " << layouts.built() << " times, reused " << layouts.reused()
                << " times (" << layouts.reusedRetiring()
                << " of them with nodes that no particle reaches any more)"
                << (layouts.builtRetiring() > 0 ? "; " + std::to_string(layouts.builtRetiring()) +
                                                      " new ones kept such nodes as unknowns"
                                                : std::string())
                << "\n";
    if (loadBalance_->repartitions() > 0)
      std::cout << "  load balance: the cells were repartitioned " << loadBalance_->repartitions()
                << " times\n";
    for (const auto& line : result.report)
      std::cout << "  verification: " << line << "\n";
    writeCsvTable(path, {"cells", "points", "rms_error", "max_error", "F0", "FL"},
                  {{double(ownership_->grid().cells[0])},
                   {double(totalParticles_)},
                   {result.hasExact ? result.rmsError : std::nan("")},
                   {result.hasExact ? result.maxError : std::nan("")},
                   {F[0]},
                   {F[1]}});
    std::cout << "impm: wrote";
    for (const auto& f : files)
      std::cout << " " << f;
    std::cout << " " << path << "\n";
  });
  if (deck_.sublist("Output").get<bool>("Timers"))
    Teuchos::TimeMonitor::summarize(comm_.ptr(), std::cout, false, true, false, Teuchos::Union,
                                    "impm: ");
  return result.failures;
}

template class Simulation<1>;
template class Simulation<2>;
template class Simulation<3>;

}  // namespace impm
