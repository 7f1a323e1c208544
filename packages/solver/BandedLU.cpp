#include "solver/BandedLU.hpp"

#include <Teuchos_CommHelpers.hpp>
#include <Teuchos_LAPACK.hpp>
#include <Teuchos_StandardParameterEntryValidators.hpp>
#include <Thyra_DefaultPreconditioner.hpp>
#include <Thyra_TpetraLinearOp.hpp>
#include <Thyra_TpetraThyraWrappers.hpp>

#include <limits>

#include "core/Errors.hpp"

// BLAS's banded triangular solve (Teuchos::BLAS has none), with gfortran's hidden lengths
// of the three character arguments.
extern "C" void dtbsv_(const char* uplo, const char* trans, const char* diag, const int* n,
                       const int* k, const double* a, const int* lda, double* x, const int* incx,
                       std::size_t, std::size_t, std::size_t);

namespace impm {

namespace {

constexpr LO kNoRow = -1;
constexpr const char* kAcrossRanks = "Across Ranks";

// For each local column of A, the local row of the same unknown on this rank, or kNoRow (a
// column of another rank's unknown: block Jacobi leaves it out).  A column map that begins
// with the row map (impm's Jacobians) needs no look-up.
std::vector<LO> rowsOfColumns(const CrsMatrix& A) {
  const Map& rows = *A.getRowMap();
  const Map& columns = *A.getColMap();
  const LO n = static_cast<LO>(rows.getNodeNumElements());
  const LO m = static_cast<LO>(columns.getNodeNumElements());
  std::vector<LO> row(m, kNoRow);
  const bool fitted = columns.isLocallyFitted(rows);
  for (LO c = 0; c < m; ++c)
    row[c] = fitted ? (c < n ? c : kNoRow) : rows.getLocalElement(columns.getGlobalElement(c));
  for (auto& r : row)
    if (r == Teuchos::OrdinalTraits<LO>::invalid())
      r = kNoRow;
  return row;
}

Teuchos::RCP<const CrsMatrix> matrixOf(const Thyra::LinearOpSourceBase<double>& source) {
  using Extract = Thyra::TpetraOperatorVectorExtraction<double, LO, GO, Node>;
  const auto op = source.getOp();
  if (Teuchos::rcp_dynamic_cast<const Thyra::TpetraLinearOp<double, LO, GO, Node>>(op).is_null())
    return Teuchos::null;
  return Teuchos::rcp_dynamic_cast<const CrsMatrix>(Extract::getConstTpetraOperator(op));
}

}  // namespace

BandedLU::BandedLU(const CrsMatrix& A, bool acrossRanks)
    : domain_(A.getDomainMap()),
      range_(A.getRangeMap()),
      n_(static_cast<int>(A.getRowMap()->getNodeNumElements())) {
  const auto local = A.getLocalMatrixHost();
  const auto rowOf = rowsOfColumns(A);
  // The bandwidths first, then the band: LAPACK wants kl more rows above it for the fill-in
  // of the row exchanges, so it is 2 kl + ku + 1 rows tall.
  for (int i = 0; i < n_; ++i)
    for (auto k = local.graph.row_map(i); k < local.graph.row_map(i + 1); ++k)
      if (const LO j = rowOf[local.graph.entries(k)]; j != kNoRow) {
        kl_ = std::max(kl_, i - j);
        ku_ = std::max(ku_, j - i);
      }
  const int ldab = 2 * kl_ + ku_ + 1;
  band_.assign(static_cast<std::size_t>(ldab) * n_, 0.0);
  for (int i = 0; i < n_; ++i)
    for (auto k = local.graph.row_map(i); k < local.graph.row_map(i + 1); ++k)
      if (const LO j = rowOf[local.graph.entries(k)]; j != kNoRow)
        band_[static_cast<std::size_t>(j) * ldab + kl_ + ku_ + i - j] += local.values(k);
  pivots_.resize(n_);
  int info = 0;
  if (n_ > 0)
    Teuchos::LAPACK<int, double>().GBTRF(n_, n_, kl_, ku_, band_.data(), ldab, pivots_.data(),
                                         &info);
  for (int i = 0; i < n_ && !interchanged_; ++i)
    interchanged_ = pivots_[i] != i + 1;
  if (info < 0)
    throw std::logic_error("dgbtrf: argument " + std::to_string(-info) + " is invalid");
  // Every rank learns of a singular block (the lowest zero pivot's unknown), so that none
  // waits in a collective call for the ones that throw.
  const GO none = std::numeric_limits<GO>::max();
  GO zeroPivot = none;
  Teuchos::reduceAll<int, GO>(*A.getComm(), Teuchos::REDUCE_MIN,
                              info > 0 ? A.getRowMap()->getGlobalElement(info - 1) : none,
                              Teuchos::outArg(zeroPivot));
  if (zeroPivot != none)
    throw NumericalError(
        "the banded LU of the matrix's diagonal blocks is singular: zero pivot "
        "at unknown " +
        std::to_string(zeroPivot));
  if (acrossRanks && A.getComm()->getSize() > 1)
    coupling_ = std::make_unique<RankCoupling>(
        A, rowOf, [this](double* B, int nrhs) { solveBlock(B, nrhs); });
}

void BandedLU::apply(const MultiVector& X, MultiVector& Y, Teuchos::ETransp mode, double alpha,
                     double beta) const {
  if (mode != Teuchos::NO_TRANS)
    throw std::logic_error("BandedLU::apply: only the operator itself, not its transpose");
  if (X.getLocalLength() != static_cast<std::size_t>(n_))
    throw std::logic_error("BandedLU::apply: the vector's rows are not the matrix's");
  if (beta == 0.0) {  // the Krylov solvers' case: solved in Y's own storage, nothing allocated
    Tpetra::deep_copy(Y, X);
    solveInPlace(Y);
    if (alpha != 1.0)
      Y.scale(alpha);
    return;
  }
  MultiVector Z(X, Teuchos::Copy);
  solveInPlace(Z);
  Y.update(alpha, Z, beta);
}

void BandedLU::solveInPlace(MultiVector& B) const {
  for (std::size_t v = 0; v < B.getNumVectors() && n_ > 0; ++v)
    solveBlock(B.getDataNonConst(v).getRawPtr(), 1);
  if (coupling_)
    coupling_->correct(B);
}

void BandedLU::solveBlock(double* B, int nrhs) const {
  const int ldab = 2 * kl_ + ku_ + 1;
  if (!interchanged_) {
    // Without row exchanges L is a plain unit lower band, held below U's diagonal in the
    // same storage, and each factor is one banded triangular solve.  dgbtrs applies L a
    // column at a time, one BLAS call (dger) per row, which on a band this narrow costs more
    // than the arithmetic (doc/performance.md).
    const int one = 1, upper = kl_ + ku_;
    for (int r = 0; r < nrhs; ++r) {
      double* x = B + static_cast<std::size_t>(r) * n_;
      dtbsv_("L", "N", "U", &n_, &kl_, band_.data() + upper, &ldab, x, &one, 1, 1, 1);
      dtbsv_("U", "N", "N", &n_, &upper, band_.data(), &ldab, x, &one, 1, 1, 1);
    }
    return;
  }
  int info = 0;
  Teuchos::LAPACK<int, double>().GBTRS('N', n_, kl_, ku_, nrhs, band_.data(), ldab, pivots_.data(),
                                       B, n_, &info);
  if (info != 0)
    throw std::logic_error("dgbtrs: argument " + std::to_string(-info) + " is invalid");
}

bool BandedLUFactory::isCompatible(const Thyra::LinearOpSourceBase<double>& fwdOpSrc) const {
  return !matrixOf(fwdOpSrc).is_null();
}

Teuchos::RCP<Thyra::PreconditionerBase<double>> BandedLUFactory::createPrec() const {
  return Teuchos::rcp(new Thyra::DefaultPreconditioner<double>);
}

void BandedLUFactory::initializePrec(
    const Teuchos::RCP<const Thyra::LinearOpSourceBase<double>>& fwdOpSrc,
    Thyra::PreconditionerBase<double>* prec, Thyra::ESupportSolveUse /*supportSolveUse*/) const {
  const auto A = matrixOf(*fwdOpSrc);
  auto* target = dynamic_cast<Thyra::DefaultPreconditioner<double>*>(prec);
  if (A.is_null() || !target)
    throw std::logic_error("Banded LU: the operator is not a Tpetra::CrsMatrix");
  const auto& list = list_.is_null() ? *getValidParameters() : *list_;
  const bool exact = list.get<std::string>(kAcrossRanks) == "exact";
  Teuchos::RCP<Tpetra::Operator<double, LO, GO, Node>> op = Teuchos::rcp(new BandedLU(*A, exact));
  target->initializeUnspecified(Thyra::createLinearOp(op));
}

void BandedLUFactory::uninitializePrec(
    Thyra::PreconditionerBase<double>* prec,
    Teuchos::RCP<const Thyra::LinearOpSourceBase<double>>* fwdOpSrc,
    Thyra::ESupportSolveUse* supportSolveUse) const {
  if (auto* target = dynamic_cast<Thyra::DefaultPreconditioner<double>*>(prec))
    target->uninitialize();
  if (fwdOpSrc)
    *fwdOpSrc = Teuchos::null;
  if (supportSolveUse)
    *supportSolveUse = Thyra::SUPPORT_SOLVE_UNSPECIFIED;
}

void BandedLUFactory::setParameterList(const Teuchos::RCP<Teuchos::ParameterList>& list) {
  list->validateParametersAndSetDefaults(*getValidParameters());
  list_ = list;
}

Teuchos::RCP<Teuchos::ParameterList> BandedLUFactory::unsetParameterList() {
  auto old = list_;
  list_ = Teuchos::null;
  return old;
}

Teuchos::RCP<const Teuchos::ParameterList> BandedLUFactory::getValidParameters() const {
  static const auto valid = [] {
    auto p = Teuchos::rcp(new Teuchos::ParameterList("Banded LU"));
    Teuchos::setStringToIntegralParameter<int>(
        kAcrossRanks, "exact",
        "How the ranks' blocks couple on several ranks: \"exact\" restores the couplings (the "
        "operator is the matrix's inverse on any number of ranks), \"block Jacobi\" leaves "
        "them out",
        Teuchos::tuple<std::string>("exact", "block Jacobi"), p.get());
    return p;
  }();
  return valid;
}

}  // namespace impm
