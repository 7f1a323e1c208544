#include "solver/QuasiStaticStepper.hpp"

#include <algorithm>

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
      loadPath_(formulaText(params, "Load Path"), {"s"}),
      extrapolate_(params.get<std::string>("Predictor") == "extrapolate") {}

template <int Dim>
Teuchos::RCP<Vector> QuasiStaticStepper<Dim>::guess(GridSystem<Dim>& system, double dLambda) {
  auto du = system.initialGuess();
  auto& s = this->state_;
  if (!extrapolate_ || dLambda == 0.0)
    return du;
  if (rate_.is_null() && !s.nodalDofs.empty()) {
    // Restored from a checkpoint: every rank holds the whole rate; rank 0 gives it.
    const auto& comm = system.unknownMap()->getComm();
    const bool root = comm->getRank() == 0;
    const auto none = Teuchos::OrdinalTraits<Tpetra::global_size_t>::invalid();
    auto map = Teuchos::rcp(new Map(
        none, root ? Teuchos::ArrayView<const GO>(s.nodalDofs) : Teuchos::ArrayView<const GO>(), 0,
        comm));
    rate_ = Teuchos::rcp(new Vector(map));
    for (std::size_t k = 0; root && k < s.nodalDofs.size(); ++k)
      rate_->replaceLocalValue(static_cast<LO>(k), s.nodalU[k]);
    s.nodalDofs.clear(), s.nodalU.clear(), s.nodalV.clear(), s.nodalA.clear();
  }
  if (rate_.is_null())
    return du;
  Vector rate(du->getMap());
  if (rate_->getMap()->isSameAs(*du->getMap()))
    Tpetra::deep_copy(rate, *rate_);
  else
    rate.doImport(*rate_, Import(rate_->getMap(), du->getMap()), Tpetra::INSERT);
  {
    auto values = rate.getLocalViewHost(Tpetra::Access::ReadWrite);
    for (const LO row : system.extraRows())
      if (row >= 0)
        values(row, 0) = 0.0;  // the extras' own guesses stand
  }
  du->update(dLambda, rate, 1.0);
  system.imposeConstraints(*du);
  return du;
}

template <int Dim>
void QuasiStaticStepper<Dim>::keepRate(const GridSystem<Dim>& system, const Vector& du,
                                       double dLambda) {
  if (!extrapolate_ || dLambda == 0.0) {
    rate_ = Teuchos::null;
    return;
  }
  rate_ = Teuchos::rcp(new Vector(du, Teuchos::Copy));
  rate_->scale(1.0 / dLambda);
  // The padding is no unknown of the problem: checkpoints leave it out, so the guess does too.
  ratePadding_ = system.dofs().paddingDofs();
  for (const GO gid : ratePadding_)
    if (const LO lid = rate_->getMap()->getLocalElement(gid);
        lid != Teuchos::OrdinalTraits<LO>::invalid())
      rate_->replaceLocalValue(lid, 0.0);
}

template <int Dim>
StepperState QuasiStaticStepper<Dim>::checkpointState() const {
  StepperState s = this->accepted_;
  s.nodalDofs.clear(), s.nodalU.clear(), s.nodalV.clear(), s.nodalA.clear();
  if (rate_.is_null())
    return s;
  const auto& map = *rate_->getMap();
  const auto rate = rate_->getData();
  for (std::size_t k = 0; k < map.getNodeNumElements(); ++k) {
    const GO gid = map.getGlobalElement(static_cast<LO>(k));
    if (std::find(ratePadding_.begin(), ratePadding_.end(), gid) != ratePadding_.end())
      continue;  // not an unknown of the problem
    s.nodalDofs.push_back(gid);
    s.nodalU.push_back(rate[k]), s.nodalV.push_back(0.0), s.nodalA.push_back(0.0);
  }
  return s;
}

template <int Dim>
bool QuasiStaticStepper<Dim>::finished() const {
  return fullyLoaded(this->accepted_.loadFactor);
}

template <int Dim>
void QuasiStaticStepper<Dim>::run(const StepCallback<Dim>& onStep) {
  auto& state = this->state_;
  while (!fullyLoaded(state.loadFactor)) {
    this->setup_.applyLoads(time_);  // at the particles' positions at the start of the step
    state.size = std::min(this->size(), 1.0 - state.loadFactor);
    const double from = state.loadFactor, to = from + state.size;
    const double lambdaFrom = loadPath_(from), lambdaTo = loadPath_(to);
    auto system = this->buildSystem(time_, lambdaTo);
    auto du = guess(*system, lambdaTo - lambdaFrom);
    NewtonReport report;
    if (!this->solve(*system, *du, report)) {
      const std::string step = "load step " + std::to_string(state.step + 1);
      this->cutBack(step + " (load factor " + std::to_string(lambdaFrom) + " -> " +
                        std::to_string(lambdaTo) + ")",
                    step, "load increment", "Minimum Load Increment", report);
      continue;
    }
    keepRate(*system, *du, lambdaTo - lambdaFrom);
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
template class QuasiStaticStepper<3>;

}  // namespace impm
