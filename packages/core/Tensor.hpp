#pragma once
// Small dense Dim x Dim matrices as kernels use them (a particle's F, its domain vectors R):
// the determinant and the inverse, written once for every dimension impm supports.  A
// dimension without its formula stops the build here instead of borrowing the 2-D one.

#include <Kokkos_Core.hpp>

namespace impm {

template <int Dim>
KOKKOS_INLINE_FUNCTION double determinant(const double a[Dim][Dim]) {
  static_assert(Dim >= 1 && Dim <= 3, "determinant: add the formula of this dimension");
  if constexpr (Dim == 1)
    return a[0][0];
  else if constexpr (Dim == 2)
    return a[0][0] * a[1][1] - a[0][1] * a[1][0];
  else
    return a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1]) -
           a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0]) +
           a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0]);
}

// The determinant of row p of a view of Dim x Dim matrices (F(p, a, b)).
template <int Dim, class View>
KOKKOS_INLINE_FUNCTION double determinant(const View& a, int p) {
  double m[Dim][Dim];
  for (int i = 0; i < Dim; ++i)
    for (int j = 0; j < Dim; ++j)
      m[i][j] = a(p, i, j);
  return determinant<Dim>(m);
}

// inv = a^-1, given det = determinant(a) (non-zero).
template <int Dim>
KOKKOS_INLINE_FUNCTION void inverse(const double a[Dim][Dim], double det, double inv[Dim][Dim]) {
  static_assert(Dim >= 1 && Dim <= 3, "inverse: add the formula of this dimension");
  if constexpr (Dim == 1) {
    inv[0][0] = 1.0 / det;
  } else if constexpr (Dim == 2) {
    inv[0][0] = a[1][1] / det, inv[0][1] = -a[0][1] / det;
    inv[1][0] = -a[1][0] / det, inv[1][1] = a[0][0] / det;
  } else {
    // The adjugate: inv_ij = cofactor_ji / det, with cyclic indices.
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {
        const int j1 = (j + 1) % 3, j2 = (j + 2) % 3, i1 = (i + 1) % 3, i2 = (i + 2) % 3;
        inv[i][j] = (a[j1][i1] * a[j2][i2] - a[j1][i2] * a[j2][i1]) / det;
      }
  }
}

}  // namespace impm
