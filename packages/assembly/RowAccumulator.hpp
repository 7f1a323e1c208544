#pragma once
// Sums values into one row of a local CRS matrix whose columns arrive mostly in increasing
// order, as a particle's do: the map lists a particle's nodes in increasing node order
// (BuildMap.hpp), and the rows' column indices are sorted.  The search for a column goes on
// from where the last one was found and wraps around once, so a row costs about its length
// instead of a search per value (KokkosSparse's sumIntoValues searches from the start).
// Columns that are not in the row are ignored, as sumIntoValues ignores them.

#include <KokkosSparse_CrsMatrix.hpp>
#include <Kokkos_Core.hpp>

namespace impm {

template <class Matrix>
class RowAccumulator {
 public:
  using Ordinal = typename Matrix::ordinal_type;

  KOKKOS_INLINE_FUNCTION RowAccumulator(const Matrix& K, Ordinal row) : row_(K.row(row)) {}

  KOKKOS_INLINE_FUNCTION void add(Ordinal column, double value) {
    const Ordinal length = row_.length;
    for (Ordinal tried = 0; tried < length; ++tried) {
      if (row_.colidx(cursor_) == column) {
        Kokkos::atomic_add(&row_.value(cursor_), value);
        return;
      }
      if (++cursor_ == length)
        cursor_ = 0;
    }
  }

 private:
  KokkosSparse::SparseRowView<Matrix> row_;
  Ordinal cursor_ = 0;
};

}  // namespace impm
