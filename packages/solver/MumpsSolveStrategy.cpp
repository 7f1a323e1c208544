#include "solver/MumpsSolveStrategy.hpp"

#include <Teuchos_StandardParameterEntryValidators.hpp>
#include <Thyra_LinearOpWithSolveBase.hpp>
#include <Thyra_TpetraLinearOp.hpp>
#include <Thyra_TpetraThyraWrappers.hpp>

#include <memory>

namespace impm {

namespace {

using Extract = Thyra::TpetraOperatorVectorExtraction<double, LO, GO, Node>;
using LinearOpSource = Thyra::LinearOpSourceBase<double>;

constexpr const char* kSymmetric = "Symmetric";
constexpr const char* kOrdering = "Ordering";
constexpr const char* kWorkspace = "Workspace Increase";

Teuchos::RCP<const CrsMatrix> matrixOf(const LinearOpSource& source) {
  const auto op = source.getOp();
  if (Teuchos::rcp_dynamic_cast<const Thyra::TpetraLinearOp<double, LO, GO, Node>>(op).is_null())
    return Teuchos::null;
  return Teuchos::rcp_dynamic_cast<const CrsMatrix>(Extract::getConstTpetraOperator(op));
}

// A factorised operator: applies the operator it was given and solves with its factors.
class MumpsLinearOpWithSolve : public Thyra::LinearOpWithSolveBase<double> {
 public:
  void initialize(const Teuchos::RCP<const LinearOpSource>& source,
                  std::shared_ptr<MumpsFactorization> factors) {
    source_ = source;
    factors_ = std::move(factors);
  }
  Teuchos::RCP<const LinearOpSource> release() {
    auto source = source_;
    source_ = Teuchos::null;
    return source;
  }
  const std::shared_ptr<MumpsFactorization>& factors() const { return factors_; }

  Teuchos::RCP<const Thyra::VectorSpaceBase<double>> range() const override {
    return source_.is_null() ? Teuchos::null : source_->getOp()->range();
  }
  Teuchos::RCP<const Thyra::VectorSpaceBase<double>> domain() const override {
    return source_.is_null() ? Teuchos::null : source_->getOp()->domain();
  }

 protected:
  bool opSupportedImpl(Thyra::EOpTransp trans) const override {
    return Thyra::opSupported(*source_->getOp(), trans);
  }
  void applyImpl(Thyra::EOpTransp trans, const Thyra::MultiVectorBase<double>& X,
                 const Teuchos::Ptr<Thyra::MultiVectorBase<double>>& Y, double alpha,
                 double beta) const override {
    Thyra::apply(*source_->getOp(), trans, X, Y, alpha, beta);
  }
  bool solveSupportsImpl(Thyra::EOpTransp trans) const override { return trans == Thyra::NOTRANS; }
  bool solveSupportsSolveMeasureTypeImpl(Thyra::EOpTransp trans,
                                         const Thyra::SolveMeasureType&) const override {
    return trans == Thyra::NOTRANS;
  }
  Thyra::SolveStatus<double> solveImpl(
      Thyra::EOpTransp, const Thyra::MultiVectorBase<double>& B,
      const Teuchos::Ptr<Thyra::MultiVectorBase<double>>& X,
      const Teuchos::Ptr<const Thyra::SolveCriteria<double>>) const override {
    const auto b = Extract::getConstTpetraMultiVector(Teuchos::rcpFromRef(B));
    const auto x = Extract::getTpetraMultiVector(Teuchos::rcpFromPtr(X));
    factors_->solve(*b, *x);
    Thyra::SolveStatus<double> status;
    status.solveStatus = Thyra::SOLVE_STATUS_CONVERGED;
    status.message = "MUMPS direct solve";
    // Callers that count iterations (NOX's statistics, impm's history) see one per solve.
    status.extraParameters = Teuchos::rcp(new Teuchos::ParameterList);
    status.extraParameters->set("Iteration Count", 1);
    return status;
  }

 private:
  Teuchos::RCP<const LinearOpSource> source_;
  std::shared_ptr<MumpsFactorization> factors_;
};

}  // namespace

bool MumpsSolveStrategy::isCompatible(const LinearOpSource& fwdOpSrc) const {
  return !matrixOf(fwdOpSrc).is_null();
}

Teuchos::RCP<Thyra::LinearOpWithSolveBase<double>> MumpsSolveStrategy::createOp() const {
  return Teuchos::rcp(new MumpsLinearOpWithSolve);
}

void MumpsSolveStrategy::initializeOp(const Teuchos::RCP<const LinearOpSource>& fwdOpSrc,
                                      Thyra::LinearOpWithSolveBase<double>* op,
                                      Thyra::ESupportSolveUse) const {
  const auto A = matrixOf(*fwdOpSrc);
  TEUCHOS_TEST_FOR_EXCEPTION(A.is_null(), std::invalid_argument,
                             "MUMPS solves Tpetra::CrsMatrix operators only");
  auto& lows = Teuchos::dyn_cast<MumpsLinearOpWithSolve>(*op);
  auto factors = lows.factors();
  if (!factors)
    factors = std::make_shared<MumpsFactorization>(A->getComm(), options_);
  factors->factor(*A);
  lows.initialize(fwdOpSrc, factors);
}

void MumpsSolveStrategy::initializePreconditionedOp(
    const Teuchos::RCP<const LinearOpSource>& fwdOpSrc,
    const Teuchos::RCP<const Thyra::PreconditionerBase<double>>&,
    Thyra::LinearOpWithSolveBase<double>* op, Thyra::ESupportSolveUse supportSolveUse) const {
  initializeOp(fwdOpSrc, op, supportSolveUse);
}

void MumpsSolveStrategy::initializeApproxPreconditionedOp(
    const Teuchos::RCP<const LinearOpSource>& fwdOpSrc, const Teuchos::RCP<const LinearOpSource>&,
    Thyra::LinearOpWithSolveBase<double>* op, Thyra::ESupportSolveUse supportSolveUse) const {
  initializeOp(fwdOpSrc, op, supportSolveUse);
}

void MumpsSolveStrategy::uninitializeOp(Thyra::LinearOpWithSolveBase<double>* op,
                                        Teuchos::RCP<const LinearOpSource>* fwdOpSrc,
                                        Teuchos::RCP<const Thyra::PreconditionerBase<double>>* prec,
                                        Teuchos::RCP<const LinearOpSource>* approxFwdOpSrc,
                                        Thyra::ESupportSolveUse* supportSolveUse) const {
  auto source = Teuchos::dyn_cast<MumpsLinearOpWithSolve>(*op).release();
  if (fwdOpSrc)
    *fwdOpSrc = source;
  if (prec)
    *prec = Teuchos::null;
  if (approxFwdOpSrc)
    *approxFwdOpSrc = Teuchos::null;
  if (supportSolveUse)
    *supportSolveUse = Thyra::SUPPORT_SOLVE_UNSPECIFIED;
}

void MumpsSolveStrategy::setParameterList(const Teuchos::RCP<Teuchos::ParameterList>& list) {
  list->validateParametersAndSetDefaults(*getValidParameters());
  list_ = list;
  options_.symmetric = list->get<bool>(kSymmetric);
  options_.ordering = list->get<std::string>(kOrdering);
  options_.workspaceIncrease = list->get<int>(kWorkspace);
}

Teuchos::RCP<Teuchos::ParameterList> MumpsSolveStrategy::unsetParameterList() {
  auto old = list_;
  list_ = Teuchos::null;
  options_ = MumpsOptions{};
  return old;
}

Teuchos::RCP<const Teuchos::ParameterList> MumpsSolveStrategy::getValidParameters() const {
  static const auto valid = [] {
    auto p = Teuchos::rcp(new Teuchos::ParameterList("MUMPS"));
    const MumpsOptions defaults;
    p->set(kSymmetric, defaults.symmetric,
           "Factorise as LDL^T from the lower triangle (symmetric matrices only: hyperelastic "
           "static steps) instead of LU");
    p->set(kOrdering, defaults.ordering,
           "The fill-reducing ordering: automatic, amd, amf, qamd, pord, scotch or metis",
           Teuchos::rcp(new Teuchos::StringValidator(Teuchos::tuple<std::string>(
               "automatic", "amd", "amf", "qamd", "pord", "scotch", "metis"))));
    p->set(kWorkspace, defaults.workspaceIncrease,
           "Working space over MUMPS's estimate, percent (doubled and retried when it runs out)",
           Teuchos::rcp(new Teuchos::EnhancedNumberValidator<int>(0, 10000, 10)));
    return p;
  }();
  return valid;
}

}  // namespace impm
