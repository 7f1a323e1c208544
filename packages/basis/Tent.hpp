#pragma once
// The 1-D tent function of a uniform grid (the classical FEM nodal basis, primer Fig. 1.3),
// in grid units: node i sits at xi = i, and N_i(xi) = tent(xi - i).  Multi-dimensional tents
// are tensor products of these.

#include <Kokkos_Core.hpp>

namespace impm {

// N(s) = max(0, 1 - |s|).
KOKKOS_INLINE_FUNCTION double tent(double s) {
  const double a = s < 0 ? -s : s;
  return a < 1.0 ? 1.0 - a : 0.0;
}

// Integral of the tent from -infinity to s: 0, (1+s)^2/2, 1-(1-s)^2/2, 1.  Used for the
// exact average of N_i over a particle domain (eq. 1.33-1.35).
KOKKOS_INLINE_FUNCTION double tentIntegral(double s) {
  if (s <= -1.0)
    return 0.0;
  if (s <= 0.0)
    return 0.5 * (1.0 + s) * (1.0 + s);
  if (s < 1.0)
    return 1.0 - 0.5 * (1.0 - s) * (1.0 - s);
  return 1.0;
}

// Multi-dimensional weights from per-direction ones: the tents are tensor products, so
// phi = prod_d n_d and grad_d = dn_d prod_(e != d) n_e.
template <int Dim>
KOKKOS_INLINE_FUNCTION void tensorProduct(const double n[Dim], const double dn[Dim], double& phi,
                                          double grad[Dim]) {
  phi = 1.0;
  for (int d = 0; d < Dim; ++d)
    phi *= n[d];
  for (int d = 0; d < Dim; ++d) {
    grad[d] = dn[d];
    for (int e = 0; e < Dim; ++e)
      if (e != d)
        grad[d] *= n[e];
  }
}

// A particle domain that reaches past the edge of the grid is clipped to it: the grid's
// edge bounds the material (it is where rollers and walls act), and a domain updated with
// F pokes past a boundary that the material only touches by O(h^2) (problem P2's particles
// next to a roller).  Grid units: the grid spans [0, cells].  A particle has left the grid
// only when its centre has.
template <class Grid>
KOKKOS_INLINE_FUNCTION double clipToGrid(const Grid& grid, int d, double g) {
  return g < 0.0 ? 0.0 : (g > grid.cells[d] ? double(grid.cells[d]) : g);
}
template <class Grid>
KOKKOS_INLINE_FUNCTION bool centreInside(const Grid& grid, int d, double g, double tol) {
  return g >= -tol && g <= grid.cells[d] + tol;
}

// Average of the tent over [a, b] (grid units) given 1 / (b - a); the tent value itself
// when b == a.  (The reciprocal is the caller's: a particle's is the same for every node.)
KOKKOS_INLINE_FUNCTION double tentAverage(double a, double b, double inverseWidth) {
  return b > a ? (tentIntegral(b) - tentIntegral(a)) * inverseWidth : tent(a);
}
KOKKOS_INLINE_FUNCTION double tentAverage(double a, double b) {
  return tentAverage(a, b, b > a ? 1.0 / (b - a) : 0.0);
}

}  // namespace impm
