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

// Whether particle p's centre x(p) lies on the grid (up to tol cells).
template <int Dim, class Vectors>
KOKKOS_INLINE_FUNCTION bool centreOnGrid(const GridGeometry<Dim>& grid, const Vectors& x, int p,
                                         double tol) {
  for (int d = 0; d < Dim; ++d)
    if (!centreInside(grid, d, grid.gridCoord(d, x(p, d)), tol))
      return false;
  return true;
}

// The nodes a domain with corners g (grid units, clipped) touches: those whose tents are
// non-zero at some corner (eq. 1.40), nodes floor(g) to ceil(g) of each corner along each
// axis.  A corner within kOnNode of a node (a domain's side on a grid line, up to round-off)
// touches that node only: the next node's weights there are below 1e-14, which the map
// leaves out anyway, and counting it would make the map reserve up to 3^Dim nodes for 2^Dim
// (then copy them together; in 3-D half the memory of a step's map).
template <int Dim, int Corners>
KOKKOS_INLINE_FUNCTION void cornerNodeBox(const GridGeometry<Dim>& grid,
                                          const double g[Corners][Dim], int lo[Dim], int hi[Dim]) {
  constexpr double kOnNode = 1e-14;
  for (int d = 0; d < Dim; ++d) {
    lo[d] = grid.cells[d];
    hi[d] = 0;
  }
  for (int c = 0; c < Corners; ++c)
    for (int d = 0; d < Dim; ++d) {
      const int first = static_cast<int>(Kokkos::Experimental::floor(g[c][d] + kOnNode));
      const int last = static_cast<int>(Kokkos::Experimental::ceil(g[c][d] - kOnNode));
      if (first < lo[d])
        lo[d] = first;
      if (last > hi[d])
        hi[d] = last;
    }
  for (int d = 0; d < Dim; ++d) {
    lo[d] = lo[d] < 0 ? 0 : (lo[d] > grid.cells[d] ? grid.cells[d] : lo[d]);
    hi[d] = hi[d] > grid.cells[d] ? grid.cells[d] : (hi[d] < lo[d] ? lo[d] : hi[d]);
  }
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

  // What every node's weights read of particle p: its corners (grid units, clipped) and
  // R^-1.
  struct Particle {
    double g[kCorners][Dim];
    double Rinv[Dim][Dim];
  };

  KOKKOS_INLINE_FUNCTION bool nodeBox(int p, Particle& at, int lo[Dim], int hi[Dim],
                                      double tol) const {
    if (!centreOnGrid<Dim>(grid, x, p, tol))
      return false;
    for (int c = 0; c < kCorners; ++c)
      corner(p, c, at.g[c]);
    cornerNodeBox<Dim, kCorners>(grid, at.g, lo, hi);
    double R[Dim][Dim];
    for (int a = 0; a < Dim; ++a)
      for (int k = 0; k < Dim; ++k)
        R[a][k] = domain(p, a, k);
    inverse<Dim>(R, determinant<Dim>(R), at.Rinv);
    return true;
  }

  KOKKOS_INLINE_FUNCTION void evaluate(const Particle& at, const int* /*lo*/, const int node[Dim],
                                       double& phi, double grad[Dim]) const {
    double gxi[Dim] = {};
    phi = 0.0;
    for (int c = 0; c < kCorners; ++c) {
      double n = 1.0;
      for (int d = 0; d < Dim; ++d)
        n *= tent(at.g[c][d] - node[d]);
      phi += n;
      for (int k = 0; k < Dim; ++k)
        gxi[k] += sign(c, k) * n;
    }
    const double scale = 1.0 / kCorners;
    phi *= scale;
    // grad = R^-T gxi.
    for (int d = 0; d < Dim; ++d) {
      grad[d] = 0.0;
      for (int k = 0; k < Dim; ++k)
        grad[d] += scale * at.Rinv[k][d] * gxi[k];
    }
  }
};

}  // namespace impm
