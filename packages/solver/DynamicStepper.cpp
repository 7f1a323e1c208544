#include "solver/DynamicStepper.hpp"

#include <algorithm>

#include <Teuchos_CommHelpers.hpp>

#include <cmath>
#include <iomanip>
#include <sstream>

#include "assembly/Energy.hpp"
#include "core/Errors.hpp"
#include "core/Timers.hpp"
#include "solver/DiagonalSolve.hpp"
#include "solver/LinearSolver.hpp"
#include "solver/ParticleAdvance.hpp"

namespace impm {

namespace {

std::string at(double t) {
  std::ostringstream s;
  s << " (at t = " << std::setprecision(8) << t << ")";
  return s.str();
}

// Zero on the extra unknowns (the few rows of boundary forces): no pass over the vector.
void maskExtras(Vector& x, const std::vector<LO>& extraRows) {
  if (extraRows.empty())
    return;
  auto values = x.getLocalViewHost(Tpetra::Access::ReadWrite);
  for (const LO row : extraRows)
    values(row, 0) = 0.0;
}

}  // namespace

template <int Dim>
DynamicStepper<Dim>::DynamicStepper(const DynamicSettings& settings, StepperSetup<Dim> setup)
    : Stepper<Dim>(std::move(setup), settings.timeStep, settings.minTimeStep),
      settings_(settings),
      fixedGrid_(this->setup_.kinematics == Kinematics::totalLagrangian),
      particlesMayWait_(fixedGrid_ && settings.isExplicit() &&
                        !this->setup_.particlesReadEveryStep) {
  if (settings_.isExplicit()) {
    settings_.mass = MassType::lumped;
    this->nodeCoupling_ = NodeCoupling::self;  // the Jacobian is c0 M: diagonal in the nodes
  }
  // Whoever reads the particles between steps brings them up to date first.
  if (particlesMayWait_)
    this->setup_.particles.setCatchUp([this] { syncParticles(); });
}

template <int Dim>
DynamicStepper<Dim>::~DynamicStepper() {
  if (particlesMayWait_)
    this->setup_.particles.setCatchUp(nullptr);
}

template <int Dim>
typename DynamicStepper<Dim>::Acceleration DynamicStepper<Dim>::acceleration(double dt) const {
  switch (settings_.integrator) {
    case DynamicSettings::Integrator::newmark: {
      const double b = settings_.beta;
      return {1.0 / (b * dt * dt), 1.0 / (b * dt), 1.0 / (2.0 * b) - 1.0};
    }
    case DynamicSettings::Integrator::centralDifference:
      return {1.0 / (dt * dt), 1.0 / dt, 0.0};
    case DynamicSettings::Integrator::primerTaylor:
      return {2.0 / (dt * dt), 2.0 / dt, 0.0};
  }
  throw std::logic_error("unknown integrator");
}

template <int Dim>
Teuchos::RCP<GridSystem<Dim>> DynamicStepper<Dim>::systemAt(double time) {
  if (fixedGrid_ && fixedSystem_) {
    fixedSystem_->setTime(time, 1.0);
    return fixedSystem_;
  }
  Teuchos::RCP<GridSystem<Dim>> system;
  try {
    system = this->buildSystem(time, 1.0);
  } catch (const NumericalError& e) {
    throw NumericalError(e.what() + at(time));
  }
  if (fixedGrid_)
    fixedSystem_ = system;
  return system;
}

template <int Dim>
Teuchos::RCP<Vector> DynamicStepper<Dim>::fromParticles(
    GridSystem<Dim>& system, const Vector& mass, const typename ParticleSet<Dim>::Vectors& q) {
  // m_i q_i = sum_p m_p phi_ip q_p (lumped), or M q = that (consistent).
  auto sum = system.particleToGrid(q);
  auto result = Teuchos::rcp(new Vector(system.unknownMap()));
  if (settings_.mass == MassType::consistent) {
    solveLinearSystem(*this->setup_.newton.linearSolveStrategy(), system.consistentMassMatrix(),
                      *sum, *result);
    maskExtras(*result, system.extraRows());
    return result;
  }
  // Nodes whose mass is round-off next to the largest carry no velocity.
  const double tiny = 1e-12 * mass.normInf();
  auto m = mass.getData();
  auto s = sum->getData();
  auto out = result->getDataNonConst();
  for (decltype(m.size()) k = 0; k < m.size(); ++k)
    out[k] = m[k] > tiny ? s[k] / m[k] : 0.0;
  return result;
}

template <int Dim>
void DynamicStepper<Dim>::gridVelocityAndAcceleration(GridSystem<Dim>& system, const Vector& mass,
                                                      const Acceleration& s,
                                                      Teuchos::RCP<Vector>& v,
                                                      Teuchos::RCP<Vector>& a) {
  if (fixedGrid_) {
    v = v_, a = a_;
    return;
  }
  v = fromParticles(system, mass, this->setup_.particles.v);
  const bool used = !settings_.isExplicit() || s.ra != 0.0;  // Newmark's v update reads it
  a = used ? fromParticles(system, mass, this->setup_.particles.a)
           : Teuchos::rcp(new Vector(system.unknownMap()));
}

template <int Dim>
void DynamicStepper<Dim>::startFixedGrid(GridSystem<Dim>& system) {
  // FEM's initial conditions: the deck's fields interpolated at the nodes.
  u_ = Teuchos::rcp(new Vector(system.unknownMap()));
  v_ = Teuchos::rcp(new Vector(system.unknownMap()));
  a_ = Teuchos::rcp(new Vector(system.unknownMap()));
  const auto& map = *system.unknownMap();
  const auto& grid = this->setup_.ownership.grid();
  for (std::size_t k = 0; k < map.getNodeNumElements(); ++k) {
    const GO gid = map.getGlobalElement(static_cast<LO>(k));
    if (system.dofs().isExtraDof(gid))
      continue;
    int idx[Dim];
    grid.nodeIndex(DofMap<Dim>::nodeOf(gid), idx);
    double x[Dim], u[Dim] = {}, v[Dim] = {};
    for (int d = 0; d < Dim; ++d)
      x[d] = grid.nodeCoord(d, idx[d]);
    if (this->setup_.initialNodalState)
      this->setup_.initialNodalState(x, u, v);
    u_->replaceLocalValue(static_cast<LO>(k), u[DofMap<Dim>::componentOf(gid)]);
    v_->replaceLocalValue(static_cast<LO>(k), v[DofMap<Dim>::componentOf(gid)]);
  }
  // The integration points take the initial displacement (F = I + grad u0) and velocity.
  auto& particles = this->setup_.particles;
  if (u_->normInf() > 0) {
    advanceParticles(system, *u_, this->setup_.kinematics, particles);
    system.commitMaterials();
  }
  auto vo = system.toOverlap(*v_);
  const auto view = vo->getLocalViewDevice(Tpetra::Access::ReadOnly);
  gridToParticleVelocity<Dim>(system.particleGridMap(), system.entryDofs(), view, view, view, 0.0,
                              particles);
}

template <int Dim>
StepperState DynamicStepper<Dim>::checkpointState() const {
  StepperState s = this->accepted_;
  if (fixedGrid_ && u_ && s.started)
    saveNodalState(s);
  return s;
}

template <int Dim>
void DynamicStepper<Dim>::saveNodalState(StepperState& s) const {
  const auto& map = *u_->getMap();
  s.nodalDofs.clear(), s.nodalU.clear(), s.nodalV.clear(), s.nodalA.clear();
  auto u = u_->getData(), v = v_->getData(), a = a_->getData();
  const auto& padding = fixedSystem_->dofs().paddingDofs();
  for (std::size_t k = 0; k < map.getNodeNumElements(); ++k) {
    const GO gid = map.getGlobalElement(static_cast<LO>(k));
    if (std::find(padding.begin(), padding.end(), gid) != padding.end())
      continue;  // not an unknown of the problem
    s.nodalDofs.push_back(gid);
    s.nodalU.push_back(u[k]), s.nodalV.push_back(v[k]), s.nodalA.push_back(a[k]);
  }
}

template <int Dim>
void DynamicStepper<Dim>::restoreNodalState(GridSystem<Dim>& system) {
  const auto& s = this->state_;
  u_ = Teuchos::rcp(new Vector(system.unknownMap()));
  v_ = Teuchos::rcp(new Vector(system.unknownMap()));
  a_ = Teuchos::rcp(new Vector(system.unknownMap()));
  // Every rank holds the whole state and takes the unknowns it owns; together they must
  // take all of them, each once.
  const auto& map = *system.unknownMap();
  int taken = 0, all = 0;
  for (std::size_t k = 0; k < s.nodalDofs.size(); ++k) {
    const LO lid = map.getLocalElement(s.nodalDofs[k]);
    if (lid == Teuchos::OrdinalTraits<LO>::invalid())
      continue;
    u_->replaceLocalValue(lid, s.nodalU[k]);
    v_->replaceLocalValue(lid, s.nodalV[k]);
    a_->replaceLocalValue(lid, s.nodalA[k]);
    ++taken;
  }
  Teuchos::reduceAll(*map.getComm(), Teuchos::REDUCE_SUM, taken, Teuchos::outArg(all));
  if (all != static_cast<int>(s.nodalDofs.size()))
    throw std::runtime_error("the restored nodal state does not fit this grid's unknowns (" +
                             std::to_string(all) + " of " + std::to_string(s.nodalDofs.size()) +
                             " found)");
  // From here on u_, v_ and a_ hold it (checkpointState()); the copies of the state that
  // every accepted step makes need not carry it.
  for (StepperState* kept : {&this->state_, &this->accepted_}) {
    kept->nodalDofs.clear(), kept->nodalU.clear(), kept->nodalV.clear(), kept->nodalA.clear();
  }
}

template <int Dim>
Teuchos::RCP<Vector> DynamicStepper<Dim>::equilibriumAcceleration(GridSystem<Dim>& system,
                                                                  const Vector& v, double dt) {
  // a^0 from M a^0 = f_ext - f_int at the start, with the boundary conditions: one central
  // difference step, not taken.
  const Acceleration s{1.0 / (dt * dt), 1.0 / dt, 0.0};
  system.freezeInternalForce(true);
  Teuchos::RCP<Vector> du;
  NewtonReport report;
  Vector zero(system.unknownMap());
  const bool ok = solveStep(system, s, v, zero, dt, du, report);
  system.freezeInternalForce(false);
  if (!ok)
    throw NumericalError("the initial acceleration could not be computed: " + report.failure);
  auto a = Teuchos::rcp(new Vector(system.unknownMap()));
  a->update(s.c0, *du, -s.rv, v, 0.0);
  maskExtras(*a, system.extraRows());
  return a;
}

template <int Dim>
bool DynamicStepper<Dim>::solveStep(GridSystem<Dim>& system, const Acceleration& s, const Vector& v,
                                    const Vector& a, double dt, Teuchos::RCP<Vector>& du,
                                    NewtonReport& report) {
  // Vectors that an operation overwrites whole are not zeroed first (false).
  auto r = Teuchos::rcp(new Vector(system.unknownMap(), false));
  if (s.ra != 0.0)
    r->update(s.rv, v, s.ra, a, 0.0);
  else
    r->scale(s.rv, v);  // central difference: a^n does not enter
  maskExtras(*r, system.extraRows());
  system.setInertia({settings_.mass, s.c0, r});
  du = system.initialGuess();
  // R is affine in du with the diagonal Jacobian: the elimination's result does not depend
  // on the guess.
  if (settings_.isExplicit() && system.hasDiagonalJacobian())
    return eliminate(system, *du, report);
  // Newton's guess: the step's displacement if the acceleration stayed a^n.
  Vector predictor(system.unknownMap(), false);
  predictor.update(dt, v, 0.5 * dt * dt, a, 0.0);
  maskExtras(predictor, system.extraRows());
  du->update(1.0, predictor, 1.0);
  system.imposeConstraints(*du);
  return this->solve(system, *du, report);
}

// The explicit step with the lumped mass: R is affine in du, so du - J^-1 R(du) is its
// solution, found by elimination (solver/DiagonalSolve) after one residual evaluation.
template <int Dim>
bool DynamicStepper<Dim>::eliminate(GridSystem<Dim>& system, Vector& du,
                                    NewtonReport& report) const {
  IMPM_TIMER("explicit update");
  Vector r(system.unknownMap(), false), step(system.unknownMap(), false);
  report = NewtonReport();
  try {
    system.evaluate(du, &r, nullptr);
    report.residualNorms = {r.norm2()};
    system.explicitElimination().solve(r, step);  // J^-1 R: linear, so its sign is taken below
  } catch (const NumericalError& e) {
    report.failure = e.what();
    return false;
  }
  du.update(-1.0, step, 1.0);
  report.linearIterations = {0};
  report.converged = true;
  return true;
}

template <int Dim>
void DynamicStepper<Dim>::gridToParticles(GridSystem<Dim>& system, const Vector& du,
                                          const Vector& v, const Vector& vNew, const Vector& aNew,
                                          const StepRecord& record) {
  if (particlesMayWait_ && !this->recordsEnergies(record) && !system.particlesCarryForces()) {
    this->namingCurrentPositions([&] { Stepper<Dim>::gridToParticles(system, du, 1.0, false); });
    if (pending_.du.is_null())
      pending_.du = Teuchos::rcp(new Vector(du, Teuchos::Copy));
    else
      pending_.du->update(1.0, du, 1.0);
    pending_.step = this->state_.step + 1, pending_.time = record.time;
    return;  // the velocities follow in syncParticles, from the grid's
  }
  syncParticles();  // the steps before first: the body forces' work reads u before this one
  Stepper<Dim>::gridToParticles(system, du, 1.0);
  // Without FLIP the velocity's change is not needed (it enters times 0): the new velocity
  // stands in for the old.
  const double flip = fixedGrid_ ? 0.0 : settings_.flip;
  auto vn = system.toOverlap(vNew), an = system.toOverlap(aNew);
  auto vo = flip == 0.0 ? vn : system.toOverlap(v);
  gridToParticleVelocity<Dim>(system.particleGridMap(), system.entryDofs(),
                              vo->getLocalViewDevice(Tpetra::Access::ReadOnly),
                              vn->getLocalViewDevice(Tpetra::Access::ReadOnly),
                              an->getLocalViewDevice(Tpetra::Access::ReadOnly), flip,
                              this->setup_.particles);
}

template <int Dim>
void DynamicStepper<Dim>::syncParticles() {
  if (!particlesWait())
    return;
  auto& particles = this->setup_.particles;
  moveParticles(*fixedSystem_, *pending_.du, this->setup_.kinematics, particles);
  pending_.du = Teuchos::null;
  // A fixed grid's particle velocities are the grid's (PIC), and v_, a_ are those of the
  // step the waiting increment ends at (run() sets them before it accepts a step).
  auto vo = fixedSystem_->toOverlap(*v_), ao = fixedSystem_->toOverlap(*a_);
  const auto v = vo->getLocalViewDevice(Tpetra::Access::ReadOnly);
  gridToParticleVelocity<Dim>(fixedSystem_->particleGridMap(), fixedSystem_->entryDofs(), v, v,
                              ao->getLocalViewDevice(Tpetra::Access::ReadOnly), 0.0, particles);
  this->requireFiniteMotion(pending_.step, pending_.time);
}

template <int Dim>
void DynamicStepper<Dim>::integrate(const GridSystem<Dim>& system, const Acceleration& s, double h,
                                    const Vector& du, const Vector& v, const Vector& a,
                                    Teuchos::RCP<Vector>& vNew, Teuchos::RCP<Vector>& aNew) const {
  aNew = Teuchos::rcp(new Vector(system.unknownMap(), false));
  aNew->update(s.c0, du, -s.rv, v, 0.0);
  if (s.ra != 0.0)
    aNew->update(-s.ra, a, 1.0);
  maskExtras(*aNew, system.extraRows());
  if (settings_.isExplicit()) {
    vNew = Teuchos::rcp(new Vector(system.unknownMap(), false));
    vNew->update(1.0, v, h, *aNew, 0.0);
  } else {
    vNew = Teuchos::rcp(new Vector(v, Teuchos::Copy));
    vNew->update(h * (1 - settings_.gamma), a, h * settings_.gamma, *aNew, 1.0);
  }
}

template <int Dim>
double DynamicStepper<Dim>::conservedKineticEnergy(const Vector& mass, const Vector& v) const {
  // On a fixed grid with lumped mass the nodal 1/2 v^T M v; otherwise the particles' (equal
  // to it with the consistent mass).
  if (fixedGrid_ && settings_.mass == MassType::lumped)
    return lumpedKineticEnergy(mass, v);
  return kineticEnergy<Dim>(this->setup_.particles, *this->setup_.ownership.comm());
}

template <int Dim>
bool DynamicStepper<Dim>::endsAt(double time) const {
  return time >= settings_.finalTime - 1e-9 * settings_.timeStep;
}

template <int Dim>
bool DynamicStepper<Dim>::finished() const {
  return endsAt(this->accepted_.time);
}

template <int Dim>
void DynamicStepper<Dim>::run(const StepCallback<Dim>& onStep) {
  auto& state = this->state_;
  const double T = settings_.finalTime;
  while (!endsAt(state.time)) {
    // The last step ends at T, unless T is a whole step away up to round-off: then the
    // step keeps its size, so that stopping at T and extending the run later takes the
    // same steps as running on.
    const double t = state.time, dt = this->size();
    const double h = T - t > dt * (1 - 1e-9) ? dt : T - t;
    this->setup_.applyLoads(settings_.isExplicit() ? t : t + h);
    // 1. The particle-grid map (a fixed grid keeps its own), the grid's v^n and a^n.
    auto system = systemAt(t + h);
    if (stressCommitted_ && !fixedGrid_)  // a fixed grid's system keeps its own stress
      system->startFromCommittedStress();
    if (fixedGrid_ && !u_)
      state.started ? restoreNodalState(*system) : startFixedGrid(*system);
    if (!fixedGrid_ || !mass_)  // a fixed grid's particles keep their masses and nodes
      mass_ = system->lumpedMass();
    const auto mass = mass_;
    const Acceleration s = acceleration(h);
    Teuchos::RCP<Vector> v, a;
    gridVelocityAndAcceleration(*system, *mass, s, v, a);
    if (!state.started && !settings_.isExplicit() && settings_.equilibriumInitialAcceleration)
      a = equilibriumAcceleration(*system, *v, h);
    if (fixedGrid_ && !state.started)
      a_ = a;
    state.started = true;
    // 2. Newton on the grid.
    system->freezeInternalForce(settings_.isExplicit());
    Teuchos::RCP<Vector> du;
    NewtonReport report;
    if (!solveStep(*system, s, *v, *a, h, du, report)) {
      state.size = h;
      this->cutBack(
          "time step " + std::to_string(state.step + 1) + " from t = " + std::to_string(t),
          "step " + std::to_string(state.step + 1), "time step", "Minimum Time Step", report);
      continue;
    }
    Teuchos::RCP<Vector> vNew, aNew;
    integrate(*system, s, h, *du, *v, *a, vNew, aNew);
    StepRecord record;
    record.time = t + h;
    record.dt = h;
    record.last = endsAt(t + h);
    record.newton = report;
    // 3. Grid to particles.
    gridToParticles(*system, *du, *v, *vNew, *aNew, record);
    // 4. Accept.
    state.time = t + h;
    if (this->recordsEnergies(record))
      record.kineticEnergy = conservedKineticEnergy(*mass, *vNew);
    if (fixedGrid_) {
      u_->update(1.0, *du, 1.0);
      v_ = vNew, a_ = aNew;
    }
    this->accept(record, StepGrid<Dim>{*system, *du, vNew, mass}, onStep);
    stressCommitted_ = true;
  }
}

template <int Dim>
double DynamicStepper<Dim>::stableTimeStep(const GridGeometry<Dim>& grid,
                                           const ParticleSet<Dim>& particles,
                                           const Materials<Dim>& materials, const Comm& comm) {
  double speed = 0.0;
  for (std::size_t m = 0; m < materials.size(); ++m) {
    const double modulus = maxModulus(particles, materials, static_cast<int>(m), comm);
    speed = std::max(speed, std::sqrt(modulus / materials[m]->density()));
  }
  double h = grid.spacing[0];
  for (int d = 1; d < Dim; ++d)
    h = std::min(h, grid.spacing[d]);
  return speed > 0 ? h / speed : std::numeric_limits<double>::infinity();
}

template class DynamicStepper<1>;
template class DynamicStepper<2>;
template class DynamicStepper<3>;

}  // namespace impm
