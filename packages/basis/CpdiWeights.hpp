#pragma once
// CPDI weights (eq. 1.36-1.38): the alternative basis N*_i interpolates the tent N_i
// (multi)linearly between the particle's corners, so over the particle
//   phi_ip = 2^-Dim sum_c N_i(x_c),
//   G_ip   = R^-T 2^-Dim sum_c s_c N_i(x_c),
// where the domain is x_p + sum_k xi_k r_k, xi in [-1, 1]^Dim, R = [r_1 ... r_Dim], corner
// c has signs s_c in {-1, +1}^Dim and x_c = x_p + R s_c.  A particle touches only the nodes
// of the cells holding its corners, however many cells it spans (eq. 1.40).

#include "basis/Tent.hpp"
#include "core/Grid.hpp"
#include "core/ParticleSet.hpp"
#include "core/Tensor.hpp"

namespace impm {

// The nodes a domain with corners touches: those of the cells that hold its corners (eq.
// 1.40), found from weights.corner(p, c, g) (grid units, clipped).  False when the
// particle's centre x(p) has left the grid.
template <int Dim, class Vectors, class Weights>
KOKKOS_INLINE_FUNCTION bool cornerNodeBox(const GridGeometry<Dim>& grid, const Vectors& x, int p,
                                          int corners, const Weights& weights, int lo[Dim],
                                          int hi[Dim], double tol) {
  for (int d = 0; d < Dim; ++d) {
    if (!centreInside(grid, d, grid.gridCoord(d, x(p, d)), tol))
      return false;
    lo[d] = grid.cells[d];
    hi[d] = 0;
  }
  for (int c = 0; c < corners; ++c) {
    double g[Dim];
    weights.corner(p, c, g);
    for (int d = 0; d < Dim; ++d) {
      int cell = static_cast<int>(Kokkos::Experimental::floor(g[d]));
      cell = cell < 0 ? 0 : (cell >= grid.cells[d] ? grid.cells[d] - 1 : cell);
      if (cell < lo[d])
        lo[d] = cell;
      if (cell + 1 > hi[d])
        hi[d] = cell + 1;
    }
  }
  return true;
}

template <int Dim, class Space = DefaultExecSpace>
struct CpdiWeights {
  static constexpr int kCorners = 1 << Dim;
  GridGeometry<Dim> grid;
  typename ParticleSet<Dim, Space>::Vectors x;
  typename ParticleSet<Dim, Space>::Tensors domain;

  CpdiWeights(const GridGeometry<Dim>& g, const ParticleSet<Dim, Space>& ps)
      : grid(g), x(ps.x), domain(ps.domain) {}

  KOKKOS_INLINE_FUNCTION static double sign(int c, int k) { return (c >> k) & 1 ? 1.0 : -1.0; }

  // Corner c of particle p, in grid units, clipped to the grid (see clipToGrid).
  KOKKOS_INLINE_FUNCTION void corner(int p, int c, double g[Dim]) const {
    for (int d = 0; d < Dim; ++d) {
      double xc = x(p, d);
      for (int k = 0; k < Dim; ++k)
        xc += sign(c, k) * domain(p, d, k);
      g[d] = clipToGrid(grid, d, grid.gridCoord(d, xc));
    }
  }

  KOKKOS_INLINE_FUNCTION bool nodeBox(int p, int lo[Dim], int hi[Dim], double tol) const {
    return cornerNodeBox<Dim>(grid, x, p, kCorners, *this, lo, hi, tol);
  }

  KOKKOS_INLINE_FUNCTION void evaluate(int p, const int* /*lo*/, const int node[Dim], double& phi,
                                       double grad[Dim]) const {
    double gxi[Dim] = {};
    phi = 0.0;
    for (int c = 0; c < kCorners; ++c) {
      double g[Dim];
      corner(p, c, g);
      double n = 1.0;
      for (int d = 0; d < Dim; ++d)
        n *= tent(g[d] - node[d]);
      phi += n;
      for (int k = 0; k < Dim; ++k)
        gxi[k] += sign(c, k) * n;
    }
    const double scale = 1.0 / kCorners;
    phi *= scale;
    // grad = R^-T gxi.
    double R[Dim][Dim], Rinv[Dim][Dim];
    for (int a = 0; a < Dim; ++a)
      for (int k = 0; k < Dim; ++k)
        R[a][k] = domain(p, a, k);
    inverse<Dim>(R, determinant<Dim>(R), Rinv);
    for (int d = 0; d < Dim; ++d) {
      grad[d] = 0.0;
      for (int k = 0; k < Dim; ++k)
        grad[d] += scale * Rinv[k][d] * gxi[k];
    }
  }
};

}  // namespace impm
