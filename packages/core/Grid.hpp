#pragma once
// The background grid: a uniform rectilinear mesh of cells (BAR2 in 1-D, QUAD4 in 2-D) with
// nodes numbered lexicographically, x fastest.  The grid carries no history between steps
// (primer 1.6.2: "the grid is reset"); its nodal views hold the last solution for output.

#include <array>
#include <cmath>

#include "core/Types.hpp"

namespace impm {

// Plain geometry, cheap to copy into kernels.
template <int Dim>
struct GridGeometry {
  double origin[Dim];
  double spacing[Dim];
  int cells[Dim];

  KOKKOS_INLINE_FUNCTION GlobalId numNodes() const {
    GlobalId n = 1;
    for (int d = 0; d < Dim; ++d)
      n *= cells[d] + 1;
    return n;
  }
  KOKKOS_INLINE_FUNCTION GlobalId numCells() const {
    GlobalId n = 1;
    for (int d = 0; d < Dim; ++d)
      n *= cells[d];
    return n;
  }
  KOKKOS_INLINE_FUNCTION double upper(int d) const { return origin[d] + cells[d] * spacing[d]; }

  // Node id from per-direction node indices (x fastest).
  KOKKOS_INLINE_FUNCTION GlobalId nodeId(const int idx[Dim]) const {
    GlobalId id = 0;
    for (int d = Dim - 1; d >= 0; --d)
      id = id * (cells[d] + 1) + idx[d];
    return id;
  }
  KOKKOS_INLINE_FUNCTION void nodeIndex(GlobalId id, int idx[Dim]) const {
    for (int d = 0; d < Dim; ++d) {
      idx[d] = static_cast<int>(id % (cells[d] + 1));
      id /= (cells[d] + 1);
    }
  }
  KOKKOS_INLINE_FUNCTION GlobalId cellId(const int idx[Dim]) const {
    GlobalId id = 0;
    for (int d = Dim - 1; d >= 0; --d)
      id = id * cells[d] + idx[d];
    return id;
  }
  KOKKOS_INLINE_FUNCTION void cellIndex(GlobalId id, int idx[Dim]) const {
    for (int d = 0; d < Dim; ++d) {
      idx[d] = static_cast<int>(id % cells[d]);
      id /= cells[d];
    }
  }
  KOKKOS_INLINE_FUNCTION double nodeCoord(int d, int i) const { return origin[d] + i * spacing[d]; }
  // Grid coordinate of x along direction d: node i sits at i.
  KOKKOS_INLINE_FUNCTION double gridCoord(int d, double x) const {
    return (x - origin[d]) / spacing[d];
  }
  // Cell containing x along d (left-closed), clamped so the upper boundary is in the last cell.
  KOKKOS_INLINE_FUNCTION int cellAlong(int d, double x) const {
    int c = static_cast<int>(Kokkos::Experimental::floor(gridCoord(d, x)));
    return c < 0 ? 0 : (c >= cells[d] ? cells[d] - 1 : c);
  }
  KOKKOS_INLINE_FUNCTION bool inside(int d, double x) const {
    return x >= origin[d] && x <= upper(d);
  }
};

template <int Dim>
GridGeometry<Dim> makeGridGeometry(const std::array<double, Dim>& origin,
                                   const std::array<double, Dim>& length,
                                   const std::array<int, Dim>& cells) {
  GridGeometry<Dim> g;
  for (int d = 0; d < Dim; ++d) {
    g.origin[d] = origin[d];
    g.cells[d] = cells[d];
    g.spacing[d] = length[d] / cells[d];
  }
  return g;
}

}  // namespace impm
