#include "solver/DiagonalSolve.hpp"

#include <Teuchos_SerialDenseMatrix.hpp>
#include <Teuchos_SerialDenseSolver.hpp>

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

void solveDiagonalWithExtras(const CrsMatrix& J, const Vector& nodal, const std::vector<GO>& extras,
                             const Vector& b, Vector& x) {
  const auto map = J.getRowMap();
  // D^-1 on the nodal rows, 0 elsewhere.
  Vector dinv(map);
  J.getLocalDiagCopy(dinv);
  {
    auto d = dinv.getLocalViewHost(Tpetra::Access::ReadWrite);
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
  std::vector<Vector> column, rowScaled;  // B_k (nodal part), D^-1 C_k^T
  Teuchos::SerialDenseMatrix<int, double> S(n, n);
  Teuchos::SerialDenseMatrix<int, double> rhs(n, 1), de(n, 1);
  Vector bn(map);
  bn.elementWiseMultiply(1.0, nodal, b, 0.0);
  for (int k = 0; k < n; ++k) {
    const Vector e = unit(map, extras[k]);
    Vector full(map), row(map);
    J.apply(e, full);                 // column k of J
    J.apply(e, row, Teuchos::TRANS);  // row k of J
    for (int j = 0; j < n; ++j)
      S(j, k) = unit(map, extras[j]).dot(full);  // E
    column.emplace_back(map);
    column.back().elementWiseMultiply(1.0, nodal, full, 0.0);
    rowScaled.emplace_back(map);
    rowScaled.back().elementWiseMultiply(1.0, dinv, row, 0.0);
    rhs(k, 0) = e.dot(b) - rowScaled.back().dot(bn);
  }
  for (int j = 0; j < n; ++j)
    for (int k = 0; k < n; ++k)
      S(j, k) -= rowScaled[j].dot(column[k]);
  if (n > 0) {
    Teuchos::SerialDenseSolver<int, double> solver;
    solver.setMatrix(Teuchos::rcpFromRef(S));
    solver.setVectors(Teuchos::rcpFromRef(de), Teuchos::rcpFromRef(rhs));
    if (solver.factor() != 0 || solver.solve() != 0)
      throw NumericalError("the explicit update's boundary-force system is singular");
  }
  // dn = D^-1 (bn - sum_k B_k de_k); the extras take de.
  Vector rest(bn, Teuchos::Copy);
  for (int k = 0; k < n; ++k)
    rest.update(-de(k, 0), column[k], 1.0);
  x.elementWiseMultiply(1.0, dinv, rest, 0.0);
  for (int k = 0; k < n; ++k)
    if (map->isNodeGlobalElement(extras[k]))
      x.replaceGlobalValue(extras[k], de(k, 0));
}

}  // namespace impm
