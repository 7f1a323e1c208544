#include "solver/DecoupledRows.hpp"

#include <Thyra_TpetraThyraWrappers.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Operator.hpp>

namespace impm {

namespace {

using Operator = Tpetra::Operator<double, LO, GO, Node>;
using Space = Thyra::VectorSpaceBase<double>;

class DecoupledRowsOperator : public Operator {
 public:
  DecoupledRowsOperator(Teuchos::RCP<const Thyra::LinearOpBase<double>> kept,
                        Teuchos::RCP<const Map> map, Teuchos::RCP<const Space> space,
                        DecoupledRows decoupled)
      : kept_(std::move(kept)),
        map_(std::move(map)),
        space_(std::move(space)),
        decoupled_(std::move(decoupled)) {}

  Teuchos::RCP<const Map> getDomainMap() const override { return map_; }
  Teuchos::RCP<const Map> getRangeMap() const override { return map_; }

  // Y = alpha op(X) + beta Y.
  void apply(const MultiVector& X, MultiVector& Y, Teuchos::ETransp mode, double alpha,
             double beta) const override {
    const auto rows = decoupled_.rows;
    const auto inverse = decoupled_.inverseDiagonal;
    const std::size_t columns = X.getNumVectors();
    // Work vectors kept between applications: fresh ones cost more than the copies (page
    // faults on every Krylov iteration).
    if (coupled_.is_null() || coupled_->getNumVectors() != columns) {
      coupled_ = Teuchos::rcp(new MultiVector(map_, columns, false));
      result_ = Teuchos::rcp(new MultiVector(map_, columns, false));
      coupledThyra_ = Thyra::createConstMultiVector<double, LO, GO, Node>(coupled_, space_);
      resultThyra_ = Thyra::createMultiVector<double, LO, GO, Node>(result_, space_);
    }
    Tpetra::deep_copy(*coupled_, X);
    {
      auto z = coupled_->getLocalViewDevice(Tpetra::Access::ReadWrite);
      Kokkos::parallel_for(
          "impm::leaveOutDecoupledRows", RangePolicy<DefaultExecSpace>(0, rows.extent(0)),
          KOKKOS_LAMBDA(const std::size_t k) {
            for (std::size_t c = 0; c < columns; ++c)
              z(rows(k), c) = 0.0;
          });
    }
    Thyra::apply(*kept_, mode == Teuchos::NO_TRANS ? Thyra::NOTRANS : Thyra::TRANS, *coupledThyra_,
                 resultThyra_.ptr());
    {
      auto y = result_->getLocalViewDevice(Tpetra::Access::ReadWrite);
      auto x = X.getLocalViewDevice(Tpetra::Access::ReadOnly);
      Kokkos::parallel_for(
          "impm::solveDecoupledRows", RangePolicy<DefaultExecSpace>(0, rows.extent(0)),
          KOKKOS_LAMBDA(const std::size_t k) {
            for (std::size_t c = 0; c < columns; ++c)
              y(rows(k), c) = x(rows(k), c) * inverse(k);
          });
    }
    Y.update(alpha, *result_, beta);
  }

 private:
  Teuchos::RCP<const Thyra::LinearOpBase<double>> kept_;
  Teuchos::RCP<const Map> map_;
  Teuchos::RCP<const Space> space_;
  DecoupledRows decoupled_;
  mutable Teuchos::RCP<MultiVector> coupled_, result_;
  mutable Teuchos::RCP<const Thyra::MultiVectorBase<double>> coupledThyra_;
  mutable Teuchos::RCP<Thyra::MultiVectorBase<double>> resultThyra_;
};

}  // namespace

DecoupledRows decoupledRows(const CrsMatrix& matrix) {
  const auto K = matrix.getLocalMatrixDevice();
  const auto rowMap = matrix.getRowMap()->getLocalMap();
  const auto colMap = matrix.getColMap()->getLocalMap();
  const LO n = static_cast<LO>(matrix.getNodeNumRows());
  // The diagonal of row r if it is the row's only non-zero value, else 0.
  auto alone = KOKKOS_LAMBDA(const LO r) {
    const auto row = K.row(r);
    const LO self = colMap.getLocalElement(rowMap.getGlobalElement(r));
    double diagonal = 0.0;
    for (LO k = 0; k < row.length; ++k) {
      if (row.colidx(k) == self)
        diagonal = row.value(k);
      else if (row.value(k) != 0.0)
        return 0.0;
    }
    return diagonal;
  };
  DecoupledRows out{Kokkos::View<LO*, DefaultMemSpace>("decoupled rows", n),
                    Kokkos::View<double*, DefaultMemSpace>("inverse diagonals", n)};
  auto rows = out.rows;
  auto inverse = out.inverseDiagonal;
  LO count = 0;
  Kokkos::parallel_scan(
      "impm::decoupledRows", RangePolicy<DefaultExecSpace>(0, n),
      KOKKOS_LAMBDA(const LO r, LO& found, const bool final) {
        const double diagonal = alone(r);
        if (diagonal == 0.0)
          return;
        if (final) {
          rows(found) = r;
          inverse(found) = 1.0 / diagonal;
        }
        ++found;
      },
      count);
  Kokkos::resize(out.rows, count);
  Kokkos::resize(out.inverseDiagonal, count);
  return out;
}

bool sameRows(const DecoupledRows& a, const DecoupledRows& b) {
  if (a.rows.extent(0) != b.rows.extent(0))
    return false;
  const auto x = a.rows, y = b.rows;
  LO differ = 0;
  Kokkos::parallel_reduce(
      "impm::sameDecoupledRows", RangePolicy<DefaultExecSpace>(0, x.extent(0)),
      KOKKOS_LAMBDA(const std::size_t k, LO& n) { n += x(k) != y(k) ? 1 : 0; }, differ);
  return differ == 0;
}

Teuchos::RCP<Thyra::LinearOpBase<double>> withDecoupledRows(
    Teuchos::RCP<const Thyra::LinearOpBase<double>> kept, Teuchos::RCP<const Map> map,
    DecoupledRows decoupled) {
  auto space = Thyra::tpetraVectorSpace<double>(map);
  Teuchos::RCP<Operator> op =
      Teuchos::rcp(new DecoupledRowsOperator(std::move(kept), map, space, std::move(decoupled)));
  return Thyra::tpetraLinearOp<double, LO, GO, Node>(space, space, op);
}

}  // namespace impm
