#include "solver/DecoupledRows.hpp"

#include <Thyra_TpetraThyraWrappers.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Operator.hpp>

namespace impm {

namespace {

using Operator = Tpetra::Operator<double, LO, GO, Node>;

class DecoupledRowsOperator : public Operator {
 public:
  DecoupledRowsOperator(Teuchos::RCP<const Thyra::LinearOpBase<double>> kept,
                        Teuchos::RCP<const Map> map, DecoupledRows decoupled)
      : kept_(std::move(kept)),
        map_(std::move(map)),
        space_(Thyra::tpetraVectorSpace<double>(map_)),
        decoupled_(std::move(decoupled)) {}

  Teuchos::RCP<const Map> getDomainMap() const override { return map_; }
  Teuchos::RCP<const Map> getRangeMap() const override { return map_; }

  // Y = alpha op(X) + beta Y.
  void apply(const MultiVector& X, MultiVector& Y, Teuchos::ETransp mode, double alpha,
             double beta) const override {
    const auto& rows = decoupled_.rows;
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
      auto z = coupled_->getLocalViewHost(Tpetra::Access::ReadWrite);
      for (std::size_t c = 0; c < columns; ++c)
        for (LO r : rows)
          z(r, c) = 0.0;
    }
    Thyra::apply(*kept_, mode == Teuchos::NO_TRANS ? Thyra::NOTRANS : Thyra::TRANS, *coupledThyra_,
                 resultThyra_.ptr());
    {
      auto y = result_->getLocalViewHost(Tpetra::Access::ReadWrite);
      auto x = X.getLocalViewHost(Tpetra::Access::ReadOnly);
      for (std::size_t c = 0; c < columns; ++c)
        for (std::size_t k = 0; k < rows.size(); ++k)
          y(rows[k], c) = x(rows[k], c) * decoupled_.inverseDiagonal[k];
    }
    Y.update(alpha, *result_, beta);
  }

 private:
  Teuchos::RCP<const Thyra::LinearOpBase<double>> kept_;
  Teuchos::RCP<const Map> map_;
  Teuchos::RCP<const Thyra::VectorSpaceBase<double>> space_;
  DecoupledRows decoupled_;
  mutable Teuchos::RCP<MultiVector> coupled_, result_;
  mutable Teuchos::RCP<const Thyra::MultiVectorBase<double>> coupledThyra_;
  mutable Teuchos::RCP<Thyra::MultiVectorBase<double>> resultThyra_;
};

}  // namespace

DecoupledRows decoupledRows(const CrsMatrix& matrix) {
  DecoupledRows out;
  const auto& rowMap = *matrix.getRowMap();
  const auto& colMap = *matrix.getColMap();
  CrsMatrix::local_inds_host_view_type columns;
  CrsMatrix::values_host_view_type values;
  for (LO r = 0; r < static_cast<LO>(matrix.getNodeNumRows()); ++r) {
    matrix.getLocalRowView(r, columns, values);
    const GO self = rowMap.getGlobalElement(r);
    double diagonal = 0.0;
    bool offDiagonal = false;
    for (std::size_t k = 0; k < columns.extent(0) && !offDiagonal; ++k) {
      if (colMap.getGlobalElement(columns(k)) == self)
        diagonal = values(k);
      else
        offDiagonal = values(k) != 0.0;
    }
    if (!offDiagonal && diagonal != 0.0) {
      out.rows.push_back(r);
      out.inverseDiagonal.push_back(1.0 / diagonal);
    }
  }
  return out;
}

Teuchos::RCP<Thyra::LinearOpBase<double>> withDecoupledRows(
    Teuchos::RCP<const Thyra::LinearOpBase<double>> kept, Teuchos::RCP<const Map> map,
    DecoupledRows decoupled) {
  auto space = Thyra::tpetraVectorSpace<double>(map);
  Teuchos::RCP<Operator> op =
      Teuchos::rcp(new DecoupledRowsOperator(std::move(kept), map, std::move(decoupled)));
  return Thyra::tpetraLinearOp<double, LO, GO, Node>(space, space, op);
}

}  // namespace impm
