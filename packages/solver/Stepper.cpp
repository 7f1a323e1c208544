#include "solver/Stepper.hpp"

#include <cmath>
#include <iomanip>
#include <iostream>
#include <iterator>
#include <sstream>
#include <stdexcept>

#include "assembly/Energy.hpp"
#include "core/Collective.hpp"
#include "core/Diagnostics.hpp"
#include "core/Errors.hpp"
#include "core/Migration.hpp"
#include "core/Timers.hpp"
#include "solver/ParticleAdvance.hpp"

namespace impm {

template <int Dim>
Stepper<Dim>::Stepper(StepperSetup<Dim> setup, double nominal, double minimum, bool retireNodes)
    : setup_(std::move(setup)),
      log_(setup_.ownership.comm()->getRank() == 0 ? &std::cout : nullptr),
      nominal_(nominal),
      minimum_(minimum),
      layouts_(setup_.reuseLayout, retireNodes) {
  layouts_.setOnNewUnknowns(
      [newton = &setup_.newton](const Map& next) { newton->releasePreconditionerUnlessFor(next); });
  if (setup_.newton.preconditionerServesRetiredNodes())
    layouts_.setKeepUnknowns(true);
  else
    layouts_.setOnRetiredNodes([newton = &setup_.newton] { newton->releasePreconditioner(); });
}

template <int Dim>
Teuchos::RCP<GridSystem<Dim>> Stepper<Dim>::buildSystem(double time, double loadFactor) {
  return Teuchos::rcp(new GridSystem<Dim>(setup_.ownership, setup_.method, setup_.kinematics,
                                          setup_.particles, setup_.materials, setup_.contributions,
                                          time, loadFactor, &workspace_, &layouts_, nodeCoupling_,
                                          setup_.fbar, setup_.ghostPenalty));
}

template <int Dim>
bool Stepper<Dim>::solve(GridSystem<Dim>& system, Vector& du, NewtonReport& report) const {
  IMPM_TIMER("Newton solve");
  report = setup_.newton.solve(Teuchos::rcpFromRef<ResidualModel>(system), du);
  return report.converged;
}

template <int Dim>
void Stepper<Dim>::cutBack(const std::string& step, const std::string& logged,
                           const std::string& quantity, const std::string& minimumParameter,
                           const NewtonReport& report) {
  const double half = size() / 2;
  if (half < minimum_ * (1 - 1e-12)) {
    std::ostringstream history;
    for (double r : report.residualNorms)
      history << " " << std::scientific << std::setprecision(2) << r;
    throw NumericalError(step + " failed: " + report.failure + "; |R| history:" + history.str() +
                         "; the " + quantity + " cannot be cut below " + minimumParameter + " = " +
                         std::to_string(minimum_));
  }
  if (log_)
    *log_ << "  " << logged << " failed (" << report.failure << "): cutting the " << quantity
          << " to " << half << "\n";
  state_.size = half;
  ++state_.attempts;
}

template <int Dim>
void Stepper<Dim>::gridToParticles(GridSystem<Dim>& system, const Vector& du, double workScale,
                                   bool move) {
  auto& particles = setup_.particles;
  supportForces_ = system.supportForces(du);  // before the particles move
  // The body forces' work over the step needs u before it, unless the rank's particles
  // carry no force (no loads): then the copy and the sum, which cost as much as a quarter
  // of an explicit step, are not made.
  const bool loaded = system.particlesCarryForces();
  const auto uBefore = firstRows(uBefore_, "u before the step", loaded ? particles.size() : 0);
  if (loaded)
    Kokkos::deep_copy(uBefore, particles.u);
  if (!move && loaded)
    throw std::logic_error("the displacement of particles that carry forces cannot wait");
  if (move)
    advanceParticles(system, du, setup_.kinematics, particles);
  else
    deformParticles(system, du, setup_.kinematics, particles);
  system.commit(du);
  state_.bodyWork +=
      bodyForceWork<Dim>(particles, uBefore, loaded, workScale, *setup_.ownership.comm());
}

namespace {

// NumericalError naming the first particle whose `name` (a field of ps) is not finite.
template <int Dim, class View>
void throwIfNotFinite(const ParticleSet<Dim>& ps, const std::string& when, const char* name,
                      const View& field) {
  const long p = firstNonFiniteRow(field, ps.size());
  if (p >= 0)
    throw NumericalError(when + ": " + particleLabel(ps, p) + " has a " + name +
                         " that is not finite after the particle update");
}

// How the particle checks' messages name a step.
std::string stepLabel(int step, double time) {
  std::ostringstream s;
  s << "step " << step << " (t = " << time << ")";
  return s.str();
}

}  // namespace

template <int Dim>
void Stepper<Dim>::namingCurrentPositions(const std::function<void()>& phase) {
  try {
    phase();
  } catch (const NumericalError&) {
    if (!particlesWait())
      throw;
    syncParticles();
    phase();
    throw;
  }
}

template <int Dim>
void Stepper<Dim>::requireFiniteMotion(int step, double time) const {
  collectively(*setup_.ownership.comm(), [&] { throwIfMotionNotFinite(stepLabel(step, time)); });
}

template <int Dim>
void Stepper<Dim>::throwIfMotionNotFinite(const std::string& when) const {
  const auto& ps = setup_.particles;
  throwIfNotFinite(ps, when, "position", ps.x);
  throwIfNotFinite(ps, when, "velocity", ps.v);
}

template <int Dim>
void Stepper<Dim>::requireFiniteParticles(const StepRecord& record) const {
  const auto& ps = setup_.particles;
  const std::string when = stepLabel(state_.step + 1, record.time);
  collectively(*setup_.ownership.comm(), [&] {
    if (!particlesWait())  // otherwise syncParticles checks them
      throwIfMotionNotFinite(when);
    throwIfNotFinite(ps, when, "deformation gradient", ps.F);
    throwIfNotFinite(ps, when, "stress", ps.stress);
  });
  // The external work is summed every step, the other energies only where the record has
  // them (Stepper::recordsEnergies).
  const std::pair<const char*, double> energies[] = {{"external work", record.externalWork},
                                                     {"strain energy", record.strainEnergy},
                                                     {"kinetic energy", record.kineticEnergy},
                                                     {"dissipated energy", record.dissipation}};
  const std::size_t computed = record.hasEnergies ? std::size(energies) : 1;
  for (std::size_t k = 0; k < computed; ++k)
    if (!std::isfinite(energies[k].second))
      throw NumericalError(when + ": the " + energies[k].first + " is not finite");
}

template <int Dim>
void Stepper<Dim>::accept(StepRecord& record, const StepGrid<Dim>& grid,
                          const StepCallback<Dim>& onStep) {
  const Comm& comm = *setup_.ownership.comm();
  const std::size_t n = setup_.particles.size();
  record.hasEnergies = recordsEnergies(record);
  if (record.hasEnergies) {
    const auto energies = materialEnergies<Dim>(setup_.particles, setup_.materials, comm,
                                                firstRows(energyDensity_, "W", n),
                                                firstRows(dissipationDensity_, "D", n));
    record.strainEnergy = energies.strain;
    record.dissipation = energies.dissipated;
  }
  record.externalWork = state_.bodyWork + contributionWork<Dim>(setup_.contributions);
  // Nothing that is not finite reaches the outputs.
  namingCurrentPositions([&] { requireFiniteParticles(record); });
  record.step = ++state_.step;
  record.attempts = state_.attempts + 1;
  record.supportForces = supportForces_;
  state_.attempts = 0;
  state_.size = std::min(2 * size(), nominal_);  // grows back after a cutback
  if (state_.size >= nominal_)
    state_.size = 0.0;
  accepted_ = state_;
  onStep(record, grid);
  if (setup_.kinematics == Kinematics::updatedLagrangian) {
    IMPM_TIMER("migration");  // particles live on the rank that owns their cell
    migrateToOwners(setup_.particles, setup_.ownership.decomposition(), comm);
    if (setup_.afterMigration)
      setup_.afterMigration(record.step);
  }
}

template class Stepper<1>;
template class Stepper<2>;
template class Stepper<3>;

}  // namespace impm
