#pragma once
// CPDI2 weights (Sadeghirad, Brannon & Guilkey 2013): the particle domain is the polygon of
// its tracked corners x_c (2-D: a quadrilateral, counter-clockwise; a triangle is the
// quadrilateral whose last two corners coincide, which gives CPTI), mapped from the square
// [-1, 1]^Dim by the multilinear functions M_c(xi).  The alternative basis interpolates the
// tent N_i between the corners, N*_i = sum_c M_c N_i(x_c), and its average and average
// gradient over the domain are
//   phi_ip = sum_c w_c N_i(x_c),    w_c = (1/V) int M_c dV,
//   G_ip   = sum_c g_c N_i(x_c),    g_c = (1/V) int grad M_c dV,
// with V the polygon's area.  The integrands are polynomials of degree at most 3 in each xi_k
// (M_c det J and cof(J) grad_xi M_c), so 2 Gauss points per direction integrate them exactly.
// For a parallelogram w_c = 2^-Dim and the weights are CPDI's (CpdiWeights); for a collapsed
// quadrilateral M_c are the triangle's barycentric coordinates, w_c = 1/3 and g_c the edge
// normals of CPTI.

#include <Kokkos_Core.hpp>

#include "basis/CpdiWeights.hpp"

namespace impm {

// The particle fields of domains with corners (declared when a body comes from a mesh):
// current corners, reference corners, and per face the bit mask of the side sets holding it.
inline constexpr const char* kCornersField = "corners";
inline constexpr const char* kReferenceCornersField = "corners0";
inline constexpr const char* kFacesField = "faces";

template <int Dim, class Space = DefaultExecSpace>
struct CornerWeights {
  static constexpr int kCorners = 1 << Dim;
  using Table = typename ParticleSet<Dim, Space>::Table;
  GridGeometry<Dim> grid;
  typename ParticleSet<Dim, Space>::Vectors x;
  Table corners;  // (p, c * Dim + d), counter-clockwise (2-D)
  // w_t and g_t of every particle, computed once (evaluate runs for every node).
  Kokkos::View<double* [kCorners], typename Space::memory_space> weight;
  Kokkos::View<double* [kCorners][Dim], typename Space::memory_space> gradientWeight;

  // corners: the current or the reference corners (the map's configuration).
  CornerWeights(const GridGeometry<Dim>& geometry, const ParticleSet<Dim, Space>& ps,
                const Table& c)
      : grid(geometry),
        x(ps.x),
        corners(c),
        weight("CPDI2 w", c.extent(0)),
        gradientWeight("CPDI2 g", c.extent(0)) {
    const CornerWeights self = *this;  // views: a shallow copy for the kernel
    Kokkos::parallel_for(
        "impm::cornerWeights", RangePolicy<Space>(0, c.extent(0)), KOKKOS_LAMBDA(const int p) {
          double wp[kCorners], gp[kCorners][Dim];
          self.cornerWeights(p, wp, gp);
          for (int t = 0; t < kCorners; ++t) {
            self.weight(p, t) = wp[t];
            for (int a = 0; a < Dim; ++a)
              self.gradientWeight(p, t, a) = gp[t][a];
          }
        });
  }

  // The stored (counter-clockwise) index of the tensor corner t, whose bit k is the sign of
  // xi_k: (-,-), (+,-), (-,+), (+,+) are stored 0, 1, 3, 2 (3-D: the same on each face z).
  KOKKOS_INLINE_FUNCTION static int stored(int t) {
    const int b0 = t & 1, b1 = (t >> 1) & 1;
    return (t & ~3) + (b1 ? 3 - b0 : b0);
  }
  KOKKOS_INLINE_FUNCTION static double sign(int t, int k) { return (t >> k) & 1 ? 1.0 : -1.0; }

  // Stored corner c of particle p, in grid units, clipped to the grid (see clipToGrid).
  KOKKOS_INLINE_FUNCTION void corner(int p, int c, double g[Dim]) const {
    for (int d = 0; d < Dim; ++d)
      g[d] = clipToGrid(grid, d, grid.gridCoord(d, corners(p, c * Dim + d)));
  }

  // What every node's weights read of particle p: its index and its corners (grid units,
  // clipped) in tensor order.
  struct Particle {
    int p;
    double g[kCorners][Dim];
  };

  KOKKOS_INLINE_FUNCTION bool nodeBox(int p, Particle& at, int lo[Dim], int hi[Dim],
                                      double tol) const {
    if (!centreOnGrid<Dim>(grid, x, p, tol))
      return false;
    at.p = p;
    for (int t = 0; t < kCorners; ++t)
      corner(p, stored(t), at.g[t]);
    cornerNodeBox<Dim, kCorners>(grid, at.g, lo, hi);
    return true;
  }

  // w[t] and g[t][a] of the tensor corners t (above), by 2^Dim-point Gauss quadrature.
  KOKKOS_INLINE_FUNCTION void cornerWeights(int p, double w[kCorners],
                                            double g[kCorners][Dim]) const {
    const double at = 0.57735026918962576451;  // 1/sqrt(3)
    double volume = 0.0;
    for (int t = 0; t < kCorners; ++t) {
      w[t] = 0.0;
      for (int a = 0; a < Dim; ++a)
        g[t][a] = 0.0;
    }
    for (int q = 0; q < kCorners; ++q) {  // Gauss point q at xi_k = sign(q, k) / sqrt(3)
      double M[kCorners], dM[kCorners][Dim], J[Dim][Dim] = {};
      for (int t = 0; t < kCorners; ++t) {
        M[t] = 1.0;
        for (int k = 0; k < Dim; ++k)
          M[t] *= 0.5 * (1.0 + sign(t, k) * sign(q, k) * at);
        for (int k = 0; k < Dim; ++k)
          dM[t][k] = M[t] * sign(t, k) / (1.0 + sign(t, k) * sign(q, k) * at);
        for (int a = 0; a < Dim; ++a)
          for (int k = 0; k < Dim; ++k)
            J[a][k] += corners(p, stored(t) * Dim + a) * dM[t][k];
      }
      const double det = determinant<Dim>(J);
      double inv[Dim][Dim];
      inverse<Dim>(J, det, inv);
      volume += det;
      for (int t = 0; t < kCorners; ++t) {
        w[t] += M[t] * det;
        for (int a = 0; a < Dim; ++a)  // det grad_x M = det J^-T grad_xi M
          for (int k = 0; k < Dim; ++k)
            g[t][a] += det * inv[k][a] * dM[t][k];
      }
    }
    for (int t = 0; t < kCorners; ++t) {
      w[t] /= volume;
      for (int a = 0; a < Dim; ++a)
        g[t][a] /= volume;
    }
  }

  KOKKOS_INLINE_FUNCTION void evaluate(const Particle& at, const int* /*lo*/, const int node[Dim],
                                       double& phi, double grad[Dim]) const {
    phi = 0.0;
    for (int a = 0; a < Dim; ++a)
      grad[a] = 0.0;
    for (int t = 0; t < kCorners; ++t) {
      double n = 1.0;
      for (int d = 0; d < Dim; ++d)
        n *= tent(at.g[t][d] - node[d]);
      phi += weight(at.p, t) * n;
      for (int a = 0; a < Dim; ++a)
        grad[a] += gradientWeight(at.p, t, a) * n;
    }
  }
};

}  // namespace impm
