#include "solver/RoundOffTest.hpp"

#include <NOX_Solver_Generic.H>
#include <NOX_Thyra_Group.H>
#include <NOX_Thyra_Vector.H>
#include <Teuchos_CommHelpers.hpp>
#include <Thyra_TpetraThyraWrappers.hpp>

#include <cmath>
#include <limits>
#include <ostream>

#include "core/Types.hpp"

namespace impm {

namespace {

// sum_i ((|A| |x|)_i)^2 over the rows of a local matrix, x on its columns.
template <class ExecSpace, class LocalMatrix, class ColumnView>
double absoluteProductSquares(const LocalMatrix& A, const ColumnView& x) {
  double sum = 0.0;
  Kokkos::parallel_reduce(
      "impm::absoluteProductSquares", Kokkos::RangePolicy<ExecSpace>(0, A.numRows()),
      KOKKOS_LAMBDA(const LO i, double& partial) {
        const auto row = A.rowConst(i);
        double s = 0.0;
        for (LO k = 0; k < row.length; ++k)
          s += Kokkos::Experimental::fabs(row.value(k)) *
               Kokkos::Experimental::fabs(x(row.colidx(k), 0));
        partial += s * s;
      },
      sum);
  return sum;
}

}  // namespace

double absoluteProductNorm(const CrsMatrix& K, const Vector& x) {
  const Vector atColumns = onColumns(K, x);
  const double local = absoluteProductSquares<DefaultExecSpace>(
      K.getLocalMatrixDevice(), atColumns.getLocalViewDevice(Tpetra::Access::ReadOnly));
  double global = 0.0;
  Teuchos::reduceAll(*K.getComm(), Teuchos::REDUCE_SUM, local, Teuchos::outArg(global));
  return std::sqrt(global);
}

NOX::StatusTest::StatusType RoundOffResidual::checkStatus(const NOX::Solver::Generic& solver,
                                                          NOX::StatusTest::CheckType type) {
  status_ = NOX::StatusTest::Unconverged;
  if (type == NOX::StatusTest::None) {
    status_ = NOX::StatusTest::Unevaluated;
    return status_;
  }
  if (solver.getNumIterations() == 0)
    return status_;
  using Extract = Thyra::TpetraOperatorVectorExtraction<double, LO, GO, Node>;
  const auto* group = dynamic_cast<const NOX::Thyra::Group*>(&solver.getSolutionGroup());
  const auto* x = group ? dynamic_cast<const NOX::Thyra::Vector*>(&group->getX()) : nullptr;
  if (!x)
    return status_;
  const auto K = Teuchos::rcp_dynamic_cast<const CrsMatrix>(
      Extract::getConstTpetraOperator(group->getJacobianOperator()));
  if (K.is_null())
    return status_;
  norm_ = group->getNormF();
  floor_ = factor_ * std::numeric_limits<double>::epsilon() *
           (absoluteProductNorm(
                *K, *Extract::getConstTpetraVector(Teuchos::rcpFromRef(x->getThyraVector()))) +
            model_.roundOffScale());
  if (norm_ <= floor_)
    status_ = NOX::StatusTest::Converged;
  return status_;
}

std::ostream& RoundOffResidual::print(std::ostream& out, int indent) const {
  for (int k = 0; k < indent; ++k)
    out << ' ';
  return out << status_ << " ||R|| " << norm_ << " <= round-off floor " << floor_ << "\n";
}

}  // namespace impm
