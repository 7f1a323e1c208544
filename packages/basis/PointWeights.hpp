#pragma once
// Single-point weights (eq. 1.29): phi_ip = N_i(x_p), G_ip = grad N_i(x_p).  Used by classic
// MPM at particle centres and by FEM at Gauss points.  At a cell face the gradient of the
// tent is taken from the cell that contains the point (left-closed).

#include "basis/Tent.hpp"
#include "core/Grid.hpp"
#include "core/ParticleSet.hpp"

namespace impm {

template <int Dim, class Space = DefaultExecSpace>
struct PointWeights {
  GridGeometry<Dim> grid;
  typename ParticleSet<Dim, Space>::Vectors x;

  PointWeights(const GridGeometry<Dim>& g, const ParticleSet<Dim, Space>& ps) : grid(g), x(ps.x) {}

  // What every node's weights read of particle p: its position in grid units.
  struct Particle {
    double g[Dim];
  };

  // The cell holding the point; false when the point is outside the grid.
  KOKKOS_INLINE_FUNCTION bool nodeBox(int p, Particle& at, int lo[Dim], int hi[Dim],
                                      double tol) const {
    for (int d = 0; d < Dim; ++d) {
      at.g[d] = grid.gridCoord(d, x(p, d));
      if (!(at.g[d] >= -tol && at.g[d] <= grid.cells[d] + tol))
        return false;
      lo[d] = grid.cellAlong(d, x(p, d));
      hi[d] = lo[d] + 1;
    }
    return true;
  }

  KOKKOS_INLINE_FUNCTION void evaluate(const Particle& at, const int lo[Dim], const int node[Dim],
                                       double& phi, double grad[Dim]) const {
    double n[Dim], dn[Dim];
    for (int d = 0; d < Dim; ++d) {
      const double s = at.g[d] - lo[d];  // local coordinate in [0, 1]
      const bool left = node[d] == lo[d];
      n[d] = left ? 1.0 - s : s;
      dn[d] = (left ? -1.0 : 1.0) / grid.spacing[d];
    }
    tensorProduct<Dim>(n, dn, phi, grad);
  }
};

}  // namespace impm
