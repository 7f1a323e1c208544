#include "solver/DynamicStepper.hpp"

#include <Teuchos_CommHelpers.hpp>

#include <cmath>
#include <iomanip>
#include <iostream>
#include <sstream>

#include "assembly/Energy.hpp"
#include "core/Errors.hpp"
#include "core/Migration.hpp"
#include "core/Timers.hpp"
#include "solver/LinearSolver.hpp"
#include "solver/ParticleAdvance.hpp"

namespace impm {

namespace {

std::string at(double t) {
  std::ostringstream s;
  s << " (at t = " << std::setprecision(8) << t << ")";
  return s.str();
}

// x = a * x elementwise with the nodal mask (zero on extra unknowns).
void maskExtras(Vector& x, const Vector& mask) {
  x.elementWiseMultiply(1.0, mask, x, 0.0);
}

}  // namespace

template <int Dim>
DynamicStepper<Dim>::DynamicStepper(const DynamicSettings& settings, StepperContext<Dim> context)
    : settings_(settings),
      ctx_(std::move(context)),
      fixedGrid_(ctx_.kinematics == Kinematics::totalLagrangian),
      log_(ctx_.ownership.comm()->getRank() == 0 ? &std::cout : nullptr) {
  if (settings_.isExplicit())
    settings_.mass = MassType::lumped;
}

template <int Dim>
typename DynamicStepper<Dim>::Scheme DynamicStepper<Dim>::scheme(double dt) const {
  switch (settings_.scheme) {
    case DynamicSettings::Scheme::newmark: {
      const double b = settings_.beta;
      return {1.0 / (b * dt * dt), 1.0 / (b * dt), 1.0 / (2.0 * b) - 1.0};
    }
    case DynamicSettings::Scheme::centralDifference:
      return {1.0 / (dt * dt), 1.0 / dt, 0.0};
    case DynamicSettings::Scheme::primerTaylor:
      return {2.0 / (dt * dt), 2.0 / dt, 0.0};
  }
  throw std::logic_error("unknown scheme");
}

template <int Dim>
Teuchos::RCP<GridSystem<Dim>> DynamicStepper<Dim>::systemAt(double time) {
  if (fixedGrid_ && fixedSystem_) {
    fixedSystem_->setTime(time, 1.0);
    return fixedSystem_;
  }
  Teuchos::RCP<GridSystem<Dim>> system;
  try {
    system = Teuchos::rcp(new GridSystem<Dim>(ctx_.ownership, ctx_.method, ctx_.kinematics,
                                              ctx_.particles, ctx_.materials, ctx_.contributions,
                                              time, 1.0));
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
  auto result = Teuchos::rcp(new Vector(system.map()));
  if (settings_.mass == MassType::consistent) {
    solveLinearSystem(*ctx_.newton.linearSolveStrategy(), system.massMatrix(MassType::consistent),
                      *sum, *result);
    maskExtras(*result, system.nodalMask());
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
                                                      Teuchos::RCP<Vector>& v,
                                                      Teuchos::RCP<Vector>& a) {
  if (fixedGrid_) {
    v = v_, a = a_;
    return;
  }
  v = fromParticles(system, mass, ctx_.particles.v);
  a = fromParticles(system, mass, ctx_.particles.a);
}

template <int Dim>
void DynamicStepper<Dim>::startFixedGrid(GridSystem<Dim>& system) {
  // FEM's initial conditions: the deck's fields interpolated at the nodes.
  u_ = Teuchos::rcp(new Vector(system.map()));
  v_ = Teuchos::rcp(new Vector(system.map()));
  a_ = Teuchos::rcp(new Vector(system.map()));
  const auto& map = *system.map();
  const auto& grid = ctx_.ownership.grid();
  for (std::size_t k = 0; k < map.getNodeNumElements(); ++k) {
    const GO gid = map.getGlobalElement(static_cast<LO>(k));
    if (system.dofs().isExtraDof(gid))
      continue;
    int idx[Dim];
    grid.nodeIndex(gid / Dim, idx);
    double x[Dim], u[Dim] = {}, v[Dim] = {};
    for (int d = 0; d < Dim; ++d)
      x[d] = grid.nodeCoord(d, idx[d]);
    if (ctx_.initialNodalState)
      ctx_.initialNodalState(x, u, v);
    u_->replaceLocalValue(static_cast<LO>(k), u[gid % Dim]);
    v_->replaceLocalValue(static_cast<LO>(k), v[gid % Dim]);
  }
  // The integration points take the initial displacement (F = I + grad u0) and velocity.
  if (u_->normInf() > 0)
    advanceParticles(system, *u_, ctx_.kinematics, ctx_.particles);
  auto vo = system.toOverlap(*v_);
  const auto view = vo->getLocalViewDevice(Tpetra::Access::ReadOnly);
  gridToParticleVelocity<Dim>(system.particleGridMap(), system.entryDofs(), view, view, view, 0.0,
                              ctx_.particles);
}

template <int Dim>
Teuchos::RCP<Vector> DynamicStepper<Dim>::equilibriumAcceleration(GridSystem<Dim>& system,
                                                                  const Vector& v, double dt) {
  // a^0 from M a^0 = f_ext - f_int at the start, with the boundary conditions: one central
  // difference step, not taken.
  const Scheme s{1.0 / (dt * dt), 1.0 / dt, 0.0};
  system.freezeInternalForce(true);
  Teuchos::RCP<Vector> du;
  NewtonReport report;
  Vector zero(system.map());
  const bool ok = solveStep(system, s, v, zero, dt, du, report);
  system.freezeInternalForce(false);
  if (!ok)
    throw NumericalError("the initial acceleration could not be computed: " + report.failure);
  auto a = Teuchos::rcp(new Vector(system.map()));
  a->update(s.c0, *du, -s.rv, v, 0.0);
  maskExtras(*a, system.nodalMask());
  return a;
}

template <int Dim>
bool DynamicStepper<Dim>::solveStep(GridSystem<Dim>& system, const Scheme& s, const Vector& v,
                                    const Vector& a, double dt, Teuchos::RCP<Vector>& du,
                                    NewtonReport& report) {
  auto r = Teuchos::rcp(new Vector(system.map()));
  r->update(s.rv, v, s.ra, a, 0.0);
  maskExtras(*r, system.nodalMask());
  system.setInertia({settings_.mass, s.c0, r});
  // Guess: the step's displacement if the acceleration stayed a^n.
  du = system.initialGuess();
  Vector predictor(system.map());
  predictor.update(dt, v, 0.5 * dt * dt, a, 0.0);
  maskExtras(predictor, system.nodalMask());
  du->update(1.0, predictor, 1.0);
  IMPM_TIMER("Newton solve");
  report = ctx_.newton.solve(Teuchos::rcpFromRef<ResidualModel>(system), *du);
  return report.converged;
}

template <int Dim>
void DynamicStepper<Dim>::run(const StepCallback<Dim>& onStep) {
  const Comm& comm = *ctx_.ownership.comm();
  const double T = settings_.finalTime;
  double t = 0.0, dt = settings_.timeStep;
  int step = 0, attempts = 0;
  while (t < T - 1e-9 * settings_.timeStep) {
    const double h = std::min(dt, T - t);
    ++attempts;
    ctx_.applyLoads(settings_.isExplicit() ? t : t + h);
    auto system = systemAt(t + h);
    if (fixedGrid_ && !started_)
      startFixedGrid(*system);
    auto mass = system->lumpedMass();
    Teuchos::RCP<Vector> v, a;
    gridVelocityAndAcceleration(*system, *mass, v, a);
    if (!started_ && !settings_.isExplicit() && settings_.equilibriumInitialAcceleration)
      a = equilibriumAcceleration(*system, *v, h);
    started_ = true;
    system->freezeInternalForce(settings_.isExplicit());
    const Scheme s = scheme(h);
    Teuchos::RCP<Vector> du;
    NewtonReport report;
    if (!solveStep(*system, s, *v, *a, h, du, report)) {
      if (h / 2 < settings_.minTimeStep * (1 - 1e-12))
        throw NumericalError("time step " + std::to_string(step + 1) +
                             " from t = " + std::to_string(t) + " failed: " + report.failure +
                             "; the time step cannot be cut below Minimum Time Step = " +
                             std::to_string(settings_.minTimeStep));
      if (log_)
        *log_ << "  step " << step + 1 << " failed (" << report.failure
              << "): cutting the time step to " << h / 2 << "\n";
      dt = h / 2;
      continue;
    }
    // The scheme's accelerations and the new velocities.
    auto aNew = Teuchos::rcp(new Vector(system->map()));
    aNew->update(s.c0, *du, -s.rv, *v, 0.0);
    aNew->update(-s.ra, *a, 1.0);
    maskExtras(*aNew, system->nodalMask());
    auto vNew = Teuchos::rcp(new Vector(*v, Teuchos::Copy));
    if (settings_.isExplicit()) {
      vNew->update(h, *aNew, 1.0);
    } else {
      vNew->update(h * (1 - settings_.gamma), *a, h * settings_.gamma, *aNew, 1.0);
    }
    system->commit(*du);
    typename ParticleSet<Dim>::Vectors uBefore("u before", ctx_.particles.size());
    Kokkos::deep_copy(uBefore, ctx_.particles.u);
    advanceParticles(*system, *du, ctx_.kinematics, ctx_.particles);
    {
      auto vo = system->toOverlap(*v), vn = system->toOverlap(*vNew), an = system->toOverlap(*aNew);
      gridToParticleVelocity<Dim>(system->particleGridMap(), system->entryDofs(),
                                  vo->getLocalViewDevice(Tpetra::Access::ReadOnly),
                                  vn->getLocalViewDevice(Tpetra::Access::ReadOnly),
                                  an->getLocalViewDevice(Tpetra::Access::ReadOnly),
                                  fixedGrid_ ? 0.0 : settings_.flip, ctx_.particles);
    }
    bodyWork_ += bodyForceWork<Dim>(ctx_.particles, uBefore, 1.0, comm);

    StepRecord record;
    record.step = ++step;
    t += h;
    record.time = t;
    record.dt = h;
    record.attempts = attempts;
    record.last = t >= T - 1e-9 * settings_.timeStep;
    record.newton = report;
    // The energy the scheme conserves: on a fixed grid with lumped mass the nodal
    // 1/2 v^T M v; otherwise the particles' (equal to it with the consistent mass).
    if (fixedGrid_ && settings_.mass == MassType::lumped) {
      Vector mv(system->map());
      mv.elementWiseMultiply(1.0, *mass, *vNew, 0.0);
      record.kineticEnergy = 0.5 * mv.dot(*vNew);
    } else {
      record.kineticEnergy = kineticEnergy<Dim>(ctx_.particles, comm);
    }
    record.strainEnergy = strainEnergy<Dim>(ctx_.particles, ctx_.materials, comm);
    record.externalWork = bodyWork_ + contributionWork<Dim>(ctx_.contributions);
    if (fixedGrid_) {
      u_->update(1.0, *du, 1.0);
      v_ = vNew, a_ = aNew;
    }
    attempts = 0;
    onStep(record, StepGrid<Dim>{*system, *du, vNew.get(), mass.get()});
    if (!fixedGrid_) {
      IMPM_TIMER("migration");
      migrateToOwners(ctx_.particles, ctx_.ownership.decomposition(), comm);
    }
    dt = std::min(2 * dt, settings_.timeStep);  // grow back after a cutback
  }
}

template <int Dim>
double DynamicStepper<Dim>::stableTimeStep(
    const GridGeometry<Dim>& grid, const ParticleSet<Dim>& particles,
    const std::vector<std::shared_ptr<Material<Dim>>>& materials, const Comm& comm) {
  double speed = 0.0;
  for (std::size_t m = 0; m < materials.size(); ++m) {
    double local = materials[m]->maxModulus(particles, static_cast<int>(m)), modulus = 0.0;
    Teuchos::reduceAll(comm, Teuchos::REDUCE_MAX, local, Teuchos::outArg(modulus));
    speed = std::max(speed, std::sqrt(modulus / materials[m]->density()));
  }
  double h = grid.spacing[0];
  for (int d = 1; d < Dim; ++d)
    h = std::min(h, grid.spacing[d]);
  return speed > 0 ? h / speed : std::numeric_limits<double>::infinity();
}

template class DynamicStepper<1>;
template class DynamicStepper<2>;

}  // namespace impm
