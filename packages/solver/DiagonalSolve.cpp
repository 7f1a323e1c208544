#include "solver/DiagonalSolve.hpp"

#include <Teuchos_CommHelpers.hpp>
#include <Teuchos_LAPACK.hpp>

#include <algorithm>
#include <sstream>

#include "core/Errors.hpp"
#include "core/Types.hpp"

namespace impm {

namespace {

// The unit vector of global index g (set on the rank that owns it).
Vector unit(const Teuchos::RCP<const Map>& map, GO g) {
  Vector e(map);
  if (map->isNodeGlobalElement(g))
    e.replaceGlobalValue(g, 1.0);
  return e;
}

// J's diagonal.  A grid system's column map begins with its row map (assembly/Graph.hpp),
// so row r's diagonal entry is in column r: one search of the row, where Tpetra's copy looks
// every row's column up in the column map's hash table (a twentieth of an explicit gimp
// step).  Other matrices take Tpetra's copy.
void diagonalOf(const CrsMatrix& J, Vector& d) {
  if (!J.getColMap()->isLocallyFitted(*J.getRowMap())) {
    J.getLocalDiagCopy(d);
    return;
  }
  const auto K = J.getLocalMatrixDevice();
  auto out = d.getLocalViewDevice(Tpetra::Access::OverwriteAll);
  Kokkos::parallel_for(
      "impm::diagonalOf", RangePolicy<DefaultExecSpace>(0, K.numRows()), KOKKOS_LAMBDA(const LO r) {
        const auto row = K.row(r);
        out(r, 0) = 0.0;
        for (LO k = 0; k < row.length; ++k)
          if (row.colidx(k) == r)
            out(r, 0) = row.value(k);
      });
}

}  // namespace

DiagonalElimination::DiagonalElimination(const CrsMatrix& J, const Vector& nodal,
                                         const std::vector<GO>& extras)
    : map_(J.getRowMap()),
      extras_(extras),
      dinv_(map_),
      lu_(static_cast<int>(extras.size()), static_cast<int>(extras.size())),
      pivots_(extras.size()) {
  diagonalOf(J, dinv_);
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
  for (int k = 0; k < n; ++k)
    extraRows_.push_back(map_->getLocalElement(extras[k]));
  // Column and row k of J by products with the unit vector of extra k: E's column k from
  // the rows of the extras, B_k and D^-1 C_k^T kept by their few nonzeros.  Each rank adds
  // its part of E - C D^-1 B, summed over the ranks once.
  std::vector<double> local(static_cast<std::size_t>(n) * n, 0.0);  // column-major, as lu_
  for (int k = 0; k < n; ++k) {
    const Vector e = unit(map_, extras[k]);
    Vector full(map_, false), row(map_, false);  // overwritten whole by apply
    J.apply(e, full);                            // column k of J
    J.apply(e, row, Teuchos::TRANS);             // row k of J
    {
      auto f = full.getLocalViewHost(Tpetra::Access::ReadOnly);
      for (int j = 0; j < n; ++j)
        if (extraRows_[j] >= 0)
          local[j + n * k] += f(extraRows_[j], 0);  // E
    }
    column_.push_back(nonzeros(full, nodal));
    rowScaled_.push_back(nonzeros(row, dinv_));
  }
  for (int j = 0; j < n; ++j)
    for (int k = 0; k < n; ++k)
      local[j + n * k] -= dot(rowScaled_[j], column_[k]);
  if (n > 0)
    Teuchos::reduceAll(*map_->getComm(), Teuchos::REDUCE_SUM, n * n, local.data(), lu_.values());
  int info = 0;
  if (n > 0)
    Teuchos::LAPACK<int, double>().GETRF(n, n, lu_.values(), lu_.stride(), pivots_.data(), &info);
  if (info != 0)
    throw NumericalError("the explicit update's boundary-force system is singular");
  // What solve() needs: the rows of every B_k, each once.
  for (int k = 0; k < n; ++k)
    touched_.insert(touched_.end(), column_[k].rows.begin(), column_[k].rows.end());
  std::sort(touched_.begin(), touched_.end());
  touched_.erase(std::unique(touched_.begin(), touched_.end()), touched_.end());
}

DiagonalElimination::Sparse DiagonalElimination::nonzeros(const Vector& v, const Vector& scale) {
  Sparse out;
  auto values = v.getLocalViewHost(Tpetra::Access::ReadOnly);
  auto factors = scale.getLocalViewHost(Tpetra::Access::ReadOnly);
  for (std::size_t i = 0; i < values.extent(0); ++i)
    if (const double x = factors(i, 0) * values(i, 0); x != 0.0)
      out.rows.push_back(static_cast<LO>(i)), out.values.push_back(x);
  return out;
}

double DiagonalElimination::dot(const Sparse& a, const Sparse& b) {
  double sum = 0.0;  // both lists are in the order of their rows
  for (std::size_t i = 0, j = 0; i < a.rows.size() && j < b.rows.size();) {
    if (a.rows[i] < b.rows[j])
      ++i;
    else if (b.rows[j] < a.rows[i])
      ++j;
    else
      sum += a.values[i++] * b.values[j++];
  }
  return sum;
}

void DiagonalElimination::solve(const Vector& b, Vector& x) const {
  // re - C D^-1 rn, summed over the ranks, then de from the factored reduced system.
  const int n = static_cast<int>(extras_.size());
  auto bv = b.getLocalViewHost(Tpetra::Access::ReadOnly);
  std::vector<double> local(n, 0.0), de(n, 0.0);
  for (int k = 0; k < n; ++k) {
    if (extraRows_[k] >= 0)
      local[k] = bv(extraRows_[k], 0);
    const Sparse& c = rowScaled_[k];
    for (std::size_t e = 0; e < c.rows.size(); ++e)
      local[k] -= c.values[e] * bv(c.rows[e], 0);  // D^-1 is 0 off the nodal rows
  }
  if (n > 0)
    Teuchos::reduceAll(*map_->getComm(), Teuchos::REDUCE_SUM, n, local.data(), de.data());
  int info = 0;
  if (n > 0)
    Teuchos::LAPACK<int, double>().GETRS('N', n, 1, lu_.values(), lu_.stride(), pivots_.data(),
                                         de.data(), n, &info);
  // dn = D^-1 (rn - sum_k B_k de_k) (D^-1 is 0 on the rows that are not nodal); the extras
  // take de.
  x.elementWiseMultiply(1.0, dinv_, b, 0.0);
  auto xv = x.getLocalViewHost(Tpetra::Access::ReadWrite);
  auto dv = dinv_.getLocalViewHost(Tpetra::Access::ReadOnly);
  std::vector<double> rn(touched_.size());
  for (std::size_t t = 0; t < touched_.size(); ++t)
    rn[t] = bv(touched_[t], 0);
  for (int k = 0; k < n; ++k) {
    const Sparse& c = column_[k];
    for (std::size_t e = 0; e < c.rows.size(); ++e) {
      const auto t =
          std::lower_bound(touched_.begin(), touched_.end(), c.rows[e]) - touched_.begin();
      rn[t] -= de[k] * c.values[e];
    }
  }
  for (std::size_t t = 0; t < touched_.size(); ++t)
    xv(touched_[t], 0) = dv(touched_[t], 0) * rn[t];
  for (int k = 0; k < n; ++k)
    if (extraRows_[k] >= 0)
      xv(extraRows_[k], 0) = de[k];
}

}  // namespace impm
