#include "solver/DiagonalSolve.hpp"

#include <Teuchos_LAPACK.hpp>

#include <sstream>

#include "core/Errors.hpp"

namespace impm {

namespace {

// The unit vector of global index g (set on the rank that owns it).
Vector unit(const Teuchos::RCP<const Map>& map, GO g) {
  Vector e(map);
  if (map->isNodeGlobalElement(g))
    e.replaceGlobalValue(g, 1.0);
  return e;
}

}  // namespace

DiagonalElimination::DiagonalElimination(const CrsMatrix& J, const Vector& nodal,
                                         const std::vector<GO>& extras)
    : map_(J.getRowMap()),
      extras_(extras),
      nodal_(nodal, Teuchos::Copy),
      dinv_(map_),
      lu_(static_cast<int>(extras.size()), static_cast<int>(extras.size())),
      pivots_(extras.size()) {
  J.getLocalDiagCopy(dinv_);
  {
    auto d = dinv_.getLocalViewHost(Tpetra::Access::ReadWrite);
    auto m = nodal.getLocalViewHost(Tpetra::Access::ReadOnly);
    for (std::size_t i = 0; i < d.extent(0); ++i) {
      if (m(i, 0) == 0.0) {
        d(i, 0) = 0.0;
        continue;
      }
      if (d(i, 0) == 0.0)
        throw NumericalError("the explicit update has a zero diagonal entry (a node without mass)");
      d(i, 0) = 1.0 / d(i, 0);
    }
  }
  const int n = static_cast<int>(extras.size());
  for (int k = 0; k < n; ++k) {
    const Vector e = unit(map_, extras[k]);
    Vector full(map_), row(map_);
    J.apply(e, full);                 // column k of J
    J.apply(e, row, Teuchos::TRANS);  // row k of J
    for (int j = 0; j < n; ++j)
      lu_(j, k) = unit(map_, extras[j]).dot(full);  // E
    column_.emplace_back(map_);
    column_.back().elementWiseMultiply(1.0, nodal, full, 0.0);
    rowScaled_.emplace_back(map_);
    rowScaled_.back().elementWiseMultiply(1.0, dinv_, row, 0.0);
  }
  for (int j = 0; j < n; ++j)
    for (int k = 0; k < n; ++k)
      lu_(j, k) -= rowScaled_[j].dot(column_[k]);
  int info = 0;
  if (n > 0)
    Teuchos::LAPACK<int, double>().GETRF(n, n, lu_.values(), lu_.stride(), pivots_.data(), &info);
  if (info != 0)
    throw NumericalError("the explicit update's boundary-force system is singular");
}

void DiagonalElimination::solve(const Vector& b, Vector& x) const {
  // re - C D^-1 rn, then de from the factored reduced system.
  const int n = static_cast<int>(extras_.size());
  Vector bn(map_);
  bn.elementWiseMultiply(1.0, nodal_, b, 0.0);
  std::vector<double> de(n);
  for (int k = 0; k < n; ++k)
    de[k] = unit(map_, extras_[k]).dot(b) - rowScaled_[k].dot(bn);
  int info = 0;
  if (n > 0)
    Teuchos::LAPACK<int, double>().GETRS('N', n, 1, lu_.values(), lu_.stride(), pivots_.data(),
                                         de.data(), n, &info);
  // dn = D^-1 (bn - sum_k B_k de_k); the extras take de.
  for (int k = 0; k < n; ++k)
    bn.update(-de[k], column_[k], 1.0);
  x.elementWiseMultiply(1.0, dinv_, bn, 0.0);
  for (int k = 0; k < n; ++k)
    if (map_->isNodeGlobalElement(extras_[k]))
      x.replaceGlobalValue(extras_[k], de[k]);
}

}  // namespace impm
