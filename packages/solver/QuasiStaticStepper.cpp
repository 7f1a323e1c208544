#include "solver/QuasiStaticStepper.hpp"

#include <iomanip>
#include <iostream>
#include <sstream>

#include "assembly/Energy.hpp"
#include "core/Errors.hpp"
#include "core/Migration.hpp"
#include "core/Timers.hpp"
#include "solver/ParticleAdvance.hpp"

namespace impm {

template <int Dim>
QuasiStaticStepper<Dim>::QuasiStaticStepper(const Teuchos::ParameterList& params,
                                            StepperContext<Dim> context)
    : ctx_(std::move(context)),
      steps_(params.get<int>("Load Steps")),
      minIncrement_(params.get<double>("Minimum Load Increment")),
      time_(params.get<double>("Final Time")),
      log_(ctx_.ownership.comm()->getRank() == 0 ? &std::cout : nullptr) {}

template <int Dim>
void QuasiStaticStepper<Dim>::run(const StepCallback<Dim>& onStep) {
  const double nominal = 1.0 / steps_;
  double loadFactor = 0.0, increment = nominal;
  int step = 0, attempts = 0;
  while (loadFactor < 1.0 - 1e-12) {
    ctx_.applyLoads(time_);  // at the particles' positions at the start of the step
    increment = std::min(increment, 1.0 - loadFactor);
    const double target = loadFactor + increment;
    ++attempts;
    auto system = Teuchos::rcp(new GridSystem<Dim>(ctx_.ownership, ctx_.method, ctx_.kinematics,
                                                   ctx_.particles, ctx_.materials,
                                                   ctx_.contributions, time_, target));
    auto du = system->initialGuess();
    NewtonReport report;
    {
      IMPM_TIMER("Newton solve");
      report = ctx_.newton.solve(system, *du);
    }
    if (!report.converged) {
      std::ostringstream history;
      for (double r : report.residualNorms)
        history << " " << std::scientific << std::setprecision(2) << r;
      if (increment / 2 < minIncrement_ * (1 - 1e-12))
        throw NumericalError("load step " + std::to_string(step + 1) + " (load factor " +
                             std::to_string(loadFactor) + " -> " + std::to_string(target) +
                             ") failed: " + report.failure + "; |R| history:" + history.str() +
                             "; the increment cannot be cut below Minimum Load Increment = " +
                             std::to_string(minIncrement_));
      if (log_)
        *log_ << "  load step " << step + 1 << " failed (" << report.failure
              << "): cutting the load increment to " << increment / 2 << "\n";
      increment /= 2;
      continue;
    }
    system->commit(*du);
    typename ParticleSet<Dim>::Vectors uBefore("u before", ctx_.particles.size());
    Kokkos::deep_copy(uBefore, ctx_.particles.u);
    advanceParticles(*system, *du, ctx_.kinematics, ctx_.particles);
    const Comm& comm = *ctx_.ownership.comm();
    bodyWork_ += bodyForceWork<Dim>(ctx_.particles, uBefore, 0.5 * (loadFactor + target), comm);
    loadFactor = target;
    StepRecord record;
    record.step = ++step;
    record.time = time_ * loadFactor;  // pseudo-time: the load factor scaled to Final Time
    record.loadFactor = loadFactor;
    record.attempts = attempts;
    record.last = loadFactor >= 1.0 - 1e-12;
    record.newton = report;
    record.strainEnergy = strainEnergy<Dim>(ctx_.particles, ctx_.materials, comm);
    record.externalWork = bodyWork_ + contributionWork<Dim>(ctx_.contributions);
    attempts = 0;
    onStep(record, StepGrid<Dim>{*system, *du, nullptr, nullptr});
    if (ctx_.kinematics == Kinematics::updatedLagrangian) {
      IMPM_TIMER("migration");  // particles live on the rank that owns their cell
      migrateToOwners(ctx_.particles, ctx_.ownership.decomposition(), comm);
    }
    increment = std::min(2 * increment, nominal);  // grow back after a cutback
  }
}

template class QuasiStaticStepper<1>;
template class QuasiStaticStepper<2>;

}  // namespace impm
