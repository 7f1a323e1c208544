#pragma once
// Sums values into one row of a local CRS matrix whose columns arrive mostly in increasing
// order, as a particle's do: the map lists a particle's nodes in increasing node order
// (BuildMap.hpp), and the rows' column indices are sorted.  The search for a column goes on
// from where the last one was found and wraps around once, so a row costs about its length
// instead of a search per value (KokkosSparse's sumIntoValues searches from the start).
// Columns that are not in the row are ignored, as sumIntoValues ignores them.

#include <KokkosSparse_CrsMatrix.hpp>
#include <Kokkos_Core.hpp>
#include <utility>

namespace impm {

template <class Matrix>
class RowAccumulator {
 public:
  using Ordinal = typename Matrix::ordinal_type;

  KOKKOS_INLINE_FUNCTION RowAccumulator(const Matrix& K, Ordinal row) : row_(K.row(row)) {}

  // Returns the column's position in the row, or -1 if the row does not hold it.
  KOKKOS_INLINE_FUNCTION Ordinal add(Ordinal column, double value) {
    const Ordinal length = row_.length;
    for (Ordinal tried = 0; tried < length; ++tried) {
      if (row_.colidx(cursor_) == column) {
        Kokkos::atomic_add(&row_.value(cursor_), value);
        return cursor_;
      }
      if (++cursor_ == length)
        cursor_ = 0;
    }
    return -1;
  }

  // add(), looking first at position `at` (where another row with the same columns has it).
  KOKKOS_INLINE_FUNCTION void addAt(Ordinal at, Ordinal column, double value) {
    if (at >= 0 && at < row_.length && row_.colidx(at) == column) {
      Kokkos::atomic_add(&row_.value(at), value);
      cursor_ = at;
    } else {
      add(column, value);
    }
  }

 private:
  KokkosSparse::SparseRowView<Matrix> row_;
  Ordinal cursor_ = 0;
};

// Sums into the Dim rows of one node (row, row + 1, ...: its unknowns), which as a rule have
// the same columns, since the graph couples nodes (assembly/Graph.hpp).  A column is searched
// for in the first row only and the other rows are looked at in the same position, so a 2-D
// node's pair costs one search instead of two.  A row whose columns differ there (an extra
// unknown's couplings can lengthen one row) is searched as usual.
template <class Matrix, int Dim>
class NodeRowsAccumulator {
 public:
  using Ordinal = typename Matrix::ordinal_type;

  KOKKOS_INLINE_FUNCTION NodeRowsAccumulator(const Matrix& K, Ordinal firstRow)
      : rows_(make(K, firstRow, std::make_integer_sequence<Ordinal, Dim>())) {}

  // values[a] to row firstRow + a.
  KOKKOS_INLINE_FUNCTION void add(Ordinal column, const double (&values)[Dim]) {
    const Ordinal at = rows_[0].add(column, values[0]);
    for (int a = 1; a < Dim; ++a)
      rows_[a].addAt(at, column, values[a]);
  }

 private:
  using Rows = Kokkos::Array<RowAccumulator<Matrix>, Dim>;
  template <Ordinal... a>
  static KOKKOS_INLINE_FUNCTION Rows make(const Matrix& K, Ordinal firstRow,
                                          std::integer_sequence<Ordinal, a...>) {
    return Rows{RowAccumulator<Matrix>(K, firstRow + a)...};
  }

  Rows rows_;
};

}  // namespace impm
