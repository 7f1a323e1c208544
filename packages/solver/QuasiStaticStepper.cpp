#include "solver/QuasiStaticStepper.hpp"

#include "core/Timers.hpp"

namespace impm {

namespace {

bool fullyLoaded(double loadFactor) {
  return loadFactor >= 1.0 - 1e-12;
}

}  // namespace

template <int Dim>
QuasiStaticStepper<Dim>::QuasiStaticStepper(const Teuchos::ParameterList& params,
                                            StepperSetup<Dim> setup)
    : Stepper<Dim>(std::move(setup), 1.0 / params.get<int>("Load Steps"),
                   params.get<double>("Minimum Load Increment")),
      time_(params.get<double>("Final Time")) {}

template <int Dim>
void QuasiStaticStepper<Dim>::run(const StepCallback<Dim>& onStep) {
  auto& state = this->state_;
  while (!fullyLoaded(state.loadFactor)) {
    this->setup_.applyLoads(time_);  // at the particles' positions at the start of the step
    state.size = std::min(this->size(), 1.0 - state.loadFactor);
    const double from = state.loadFactor, to = from + state.size;
    auto system = this->buildSystem(time_, to);
    auto du = system->initialGuess();
    NewtonReport report;
    if (!this->solve(*system, *du, report)) {
      const std::string step = "load step " + std::to_string(state.step + 1);
      this->cutBack(
          step + " (load factor " + std::to_string(from) + " -> " + std::to_string(to) + ")", step,
          "load increment", "Minimum Load Increment", report);
      continue;
    }
    this->gridToParticles(*system, *du, 0.5 * (from + to));
    state.loadFactor = to;
    state.time = time_ * to;  // pseudo-time: the load factor scaled to Final Time
    StepRecord record;
    record.time = state.time;
    record.loadFactor = to;
    record.last = fullyLoaded(to);
    record.newton = report;
    this->accept(record, StepGrid<Dim>{*system, *du, nullptr, nullptr}, onStep);
  }
}

template class QuasiStaticStepper<1>;
template class QuasiStaticStepper<2>;

}  // namespace impm
