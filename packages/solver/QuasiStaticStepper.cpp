#include "solver/QuasiStaticStepper.hpp"

#include "core/Parameters.hpp"
#include "core/Timers.hpp"

namespace impm {

namespace {

// The stepper's state.loadFactor is the pseudo-time s; the loads are scaled by lambda(s).
bool fullyLoaded(double s) {
  return s >= 1.0 - 1e-12;
}

}  // namespace

template <int Dim>
QuasiStaticStepper<Dim>::QuasiStaticStepper(const Teuchos::ParameterList& params,
                                            StepperSetup<Dim> setup)
    : Stepper<Dim>(std::move(setup), 1.0 / params.get<int>("Load Steps"),
                   params.get<double>("Minimum Load Increment"),
                   true),  // no inertia: a node the particles left holds nothing
      time_(params.get<double>("Final Time")),
      loadPath_(formulaText(params, "Load Path"), {"s"}) {}

template <int Dim>
void QuasiStaticStepper<Dim>::run(const StepCallback<Dim>& onStep) {
  auto& state = this->state_;
  while (!fullyLoaded(state.loadFactor)) {
    this->setup_.applyLoads(time_);  // at the particles' positions at the start of the step
    state.size = std::min(this->size(), 1.0 - state.loadFactor);
    const double from = state.loadFactor, to = from + state.size;
    const double lambdaFrom = loadPath_(from), lambdaTo = loadPath_(to);
    auto system = this->buildSystem(time_, lambdaTo);
    auto du = system->initialGuess();
    NewtonReport report;
    if (!this->solve(*system, *du, report)) {
      const std::string step = "load step " + std::to_string(state.step + 1);
      this->cutBack(step + " (load factor " + std::to_string(lambdaFrom) + " -> " +
                        std::to_string(lambdaTo) + ")",
                    step, "load increment", "Minimum Load Increment", report);
      continue;
    }
    this->gridToParticles(*system, *du, 0.5 * (lambdaFrom + lambdaTo));
    state.loadFactor = to;
    state.time = time_ * to;  // pseudo-time: the load factor scaled to Final Time
    StepRecord record;
    record.time = state.time;
    record.loadFactor = lambdaTo;
    record.last = fullyLoaded(to);
    record.newton = report;
    this->accept(record, StepGrid<Dim>{*system, *du, Teuchos::null, Teuchos::null}, onStep);
  }
}

template class QuasiStaticStepper<1>;
template class QuasiStaticStepper<2>;

}  // namespace impm
