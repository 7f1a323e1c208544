#include "solver/PreconditionerReuse.hpp"

#include <algorithm>
#include <cmath>

#include <Thyra_DefaultPreconditioner.hpp>
#include <Thyra_TpetraThyraWrappers.hpp>

#include "core/Collective.hpp"
#include "core/Timers.hpp"
#include "solver/FinestLevel.hpp"

namespace impm {

ReusingPreconditionerFactory::ReusingPreconditionerFactory(
    Teuchos::RCP<Thyra::PreconditionerFactoryBase<double>> inner, bool muelu,
    const ReuseRules& rules)
    : inner_(std::move(inner)), muelu_(muelu), rules_(rules) {}

namespace {

// The decades a solve's residual must fall, at least one: a Krylov solve's iterations grow
// with them, so solves to different tolerances compare by iterations per decade.
double decades(double tolerance) {
  return std::max(1.0, -std::log10(tolerance));
}

}  // namespace

void ReusingPreconditionerFactory::recordSolve(int iterations, bool converged, double tolerance) {
  lastIterations_ = iterations;
  lastDecades_ = decades(tolerance);
  lastConverged_ = converged;
  if (firstIterations_ < 0) {
    firstIterations_ = iterations;
    firstDecades_ = lastDecades_;
  }
  if (carry_.judging) {
    carry_.judging = false;
    carry_.stopped = worthRebuilding();
  }
}

void ReusingPreconditionerFactory::startOver(Thyra::PreconditionerBase<double>* prec) const {
  if (auto* defaultPrec = dynamic_cast<Thyra::DefaultPreconditioner<double>*>(prec))
    defaultPrec->uninitialize();
  kept_ = Teuchos::null;
}

DecoupledRows ReusingPreconditionerFactory::decoupledRowsOf(
    const Tpetra::Operator<double, LO, GO, Node>& op) {
  const auto* matrix = dynamic_cast<const CrsMatrix*>(&op);
  return matrix ? decoupledRows(*matrix) : DecoupledRows{};
}

void ReusingPreconditionerFactory::serveKept(const Tpetra::Operator<double, LO, GO, Node>& op,
                                             Thyra::PreconditionerBase<double>* prec) const {
  // Where rows were decoupled since the build (retired nodes), the decoupled rows are
  // solved exactly and the others by the kept preconditioner (solver/DecoupledRows.hpp).
  // Decided on every rank alike: the wrapped preconditioner's applications are collective
  // in another way than the kept one's (Thyra compares the vector spaces).
  auto decoupled = decoupledRowsOf(op);
  const auto& map = op.getRangeMap();
  serve(onEveryRank(sameRows(decoupled, builtDecoupled_), *map->getComm())
            ? kept_
            : withDecoupledRows(kept_, map, std::move(decoupled)),
        prec);
}

void ReusingPreconditionerFactory::serve(const Teuchos::RCP<Thyra::LinearOpBase<double>>& op,
                                         Thyra::PreconditionerBase<double>* prec) {
  if (auto* defaultPrec = dynamic_cast<Thyra::DefaultPreconditioner<double>*>(prec))
    defaultPrec->initializeUnspecified(op);
}

bool ReusingPreconditionerFactory::worthRebuilding() const {
  if (!lastConverged_ || firstIterations_ < 0)
    return true;
  // The first solve's count at the last solve's tolerance (itself when they are the same).
  const double expected = firstIterations_ * (lastDecades_ / firstDecades_);
  const double limit =
      rules_.rebuildFactor * std::max(expected, static_cast<double>(rules_.minimumIterations));
  return lastIterations_ > limit;
}

bool ReusingPreconditionerFactory::isCompatible(
    const Thyra::LinearOpSourceBase<double>& fwdOpSrc) const {
  return inner_->isCompatible(fwdOpSrc);
}

Teuchos::RCP<Thyra::PreconditionerBase<double>> ReusingPreconditionerFactory::createPrec() const {
  return inner_->createPrec();
}

void ReusingPreconditionerFactory::initializePrec(
    const Teuchos::RCP<const Thyra::LinearOpSourceBase<double>>& fwdOpSrc,
    Thyra::PreconditionerBase<double>* prec, Thyra::ESupportSolveUse supportSolveUse) const {
  using Extract = Thyra::TpetraOperatorVectorExtraction<double, LO, GO, Node>;
  auto op = Extract::getConstTpetraOperator(fwdOpSrc->getOp());
  const auto map = op->getRangeMap();
  // Collective (every rank asks for the preconditioner together).
  const bool sameUnknowns = !map_.is_null() && map->isSameAs(*map_);
  const bool built = !prec->getUnspecifiedPrecOp().is_null();
  bool keep = sameUnknowns && built && !worthRebuilding();
  if (solveStarted_) {  // the first request of a Newton solve: a carry
    solveStarted_ = false;
    keep = keep && !carry_.stopped;
    carry_.judging = keep;
  }
  if (keep) {
    ++counts_.reuses;
    if (muelu_) {  // the only kind kept across retired nodes (Stepper)
      try {
        moveFinestLevelTo(*kept_, Teuchos::rcp_dynamic_cast<const CrsMatrix>(op));
      } catch (...) {
        map_ = Teuchos::null;  // the hierarchy may be half changed: the next request starts over
        throw;
      }
      serveKept(*op, prec);
    }
    return;
  }
  // MueLu refreshes the hierarchy it finds in prec: its own, not the wrapped one.  (None
  // is kept after a build that threw.)
  if (built && !kept_.is_null()) {
    serve(kept_, prec);
    kept_ = Teuchos::null;  // not held beside the new one while it is built
  }
  if (!sameUnknowns) {
    // Start over: a hierarchy (or factorisation) of other unknowns cannot be refreshed.
    startOver(prec);
    if (muelu_ && nullSpace_)
      inner_->getNonconstParameterList()->set("Nullspace", nullSpace_());
  }
  // A build that throws leaves `prec` half made (MueLu's levels lose data it refreshes
  // from): the next request, a cut-back step's, then starts over instead of refreshing it.
  map_ = Teuchos::null;
  {
    IMPM_TIMER("preconditioner");
    inner_->initializePrec(fwdOpSrc, prec, supportSolveUse);
  }
  kept_ = prec->getNonconstUnspecifiedPrecOp();
  if (muelu_)
    builtDecoupled_ = decoupledRowsOf(*op);
  map_ = map;
  firstIterations_ = -1;
  lastConverged_ = true;
  ++counts_.builds;
}

void ReusingPreconditionerFactory::releaseUnlessFor(const Map& next,
                                                    Thyra::PreconditionerBase<double>* prec) const {
  if (!map_.is_null() && next.isSameAs(*map_))
    return;
  release(prec);
}

void ReusingPreconditionerFactory::endSolve() noexcept {
  if (!muelu_ || kept_.is_null())
    return;
  try {
    releaseFinestLevel(*kept_);
  } catch (...) {
    map_ = Teuchos::null;  // the hierarchy may be half changed: the next request starts over
  }
}

void ReusingPreconditionerFactory::release(Thyra::PreconditionerBase<double>* prec) const {
  startOver(prec);
  map_ = Teuchos::null;
}

void ReusingPreconditionerFactory::uninitializePrec(
    Thyra::PreconditionerBase<double>* prec,
    Teuchos::RCP<const Thyra::LinearOpSourceBase<double>>* fwdOpSrc,
    Thyra::ESupportSolveUse* supportSolveUse) const {
  inner_->uninitializePrec(prec, fwdOpSrc, supportSolveUse);
  map_ = Teuchos::null;
  kept_ = Teuchos::null;
}

void ReusingPreconditionerFactory::setParameterList(
    const Teuchos::RCP<Teuchos::ParameterList>& list) {
  inner_->setParameterList(list);
}

Teuchos::RCP<Teuchos::ParameterList> ReusingPreconditionerFactory::getNonconstParameterList() {
  return inner_->getNonconstParameterList();
}

Teuchos::RCP<Teuchos::ParameterList> ReusingPreconditionerFactory::unsetParameterList() {
  return inner_->unsetParameterList();
}

}  // namespace impm
