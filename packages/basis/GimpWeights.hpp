#pragma once
// GIMP weights: the exact average of the tent functions over the particle domain
// (eq. 1.33-1.35).  The domain is the axis-aligned box x_p +- l, with half-widths l_d taken
// from the diagonal of the particle's domain tensor (which is F times the initial box, so
// l_d follows the stretch F_dd: "cpGIMP").  Tents are tensor products, so the average over
// a box is the product of 1-D averages, exact for a domain spanning any number of cells.

#include "basis/Tent.hpp"
#include "core/Grid.hpp"
#include "core/ParticleSet.hpp"

namespace impm {

template <int Dim, class Space = DefaultExecSpace>
struct GimpWeights {
  GridGeometry<Dim> grid;
  typename ParticleSet<Dim, Space>::Vectors x;
  typename ParticleSet<Dim, Space>::Tensors domain;

  GimpWeights(const GridGeometry<Dim>& g, const ParticleSet<Dim, Space>& ps)
      : grid(g), x(ps.x), domain(ps.domain) {}

  // Domain ends along d in grid units, clipped to the grid (see clipToGrid).
  KOKKOS_INLINE_FUNCTION void ends(int p, int d, double& a, double& b) const {
    const double l = domain(p, d, d);
    a = clipToGrid(grid, d, grid.gridCoord(d, x(p, d) - l));
    b = clipToGrid(grid, d, grid.gridCoord(d, x(p, d) + l));
  }

  // What every node's weights read of particle p: its domain's ends along each direction,
  // and the reciprocals of its widths in grid units and in length (made once per particle
  // rather than divided by twice per node and direction).
  struct Particle {
    double a[Dim], b[Dim];
    double inverseWidth[Dim], inverseLength[Dim];
  };

  KOKKOS_INLINE_FUNCTION bool nodeBox(int p, Particle& at, int lo[Dim], int hi[Dim],
                                      double tol) const {
    for (int d = 0; d < Dim; ++d) {
      if (!centreInside(grid, d, grid.gridCoord(d, x(p, d)), tol))
        return false;
      ends(p, d, at.a[d], at.b[d]);
      const double width = at.b[d] - at.a[d];
      at.inverseWidth[d] = width > 0 ? 1.0 / width : 0.0;
      at.inverseLength[d] = 1.0 / (width * grid.spacing[d]);
      lo[d] = at.a[d] <= 0 ? 0 : static_cast<int>(Kokkos::Experimental::floor(at.a[d]));
      hi[d] = static_cast<int>(Kokkos::Experimental::ceil(at.b[d]));
      if (hi[d] > grid.cells[d])
        hi[d] = grid.cells[d];
    }
    return true;
  }

  KOKKOS_INLINE_FUNCTION void evaluate(const Particle& at, const int* /*lo*/, const int node[Dim],
                                       double& phi, double grad[Dim]) const {
    double n[Dim], dn[Dim];
    for (int d = 0; d < Dim; ++d) {
      const double a = at.a[d], b = at.b[d];
      n[d] = tentAverage(a - node[d], b - node[d], at.inverseWidth[d]);
      dn[d] = (tent(b - node[d]) - tent(a - node[d])) * at.inverseLength[d];
    }
    tensorProduct<Dim>(n, dn, phi, grad);
  }
};

}  // namespace impm
