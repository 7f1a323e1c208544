#include "assembly/CornerMotion.hpp"

#include "basis/CornerWeights.hpp"
#include "basis/Tent.hpp"

namespace impm {

template <int Dim, class Space>
void moveCorners(Kinematics kinematics, const GridGeometry<Dim>& grid,
                 const ParticleGridMap<Dim, Space>& map, const EntryDofs<Space>& entryDofs,
                 const LocalValues& du, const ParticleSet<Dim, Space>& particles) {
  if (!particles.has(kCornersField))
    return;
  constexpr int kCorners = 1 << Dim;
  const auto corners = particles.values(kCornersField);
  const auto at = kinematics == Kinematics::totalLagrangian
                      ? particles.values(kReferenceCornersField)
                      : corners;
  auto rowPtr = map.rowPtr;
  auto node = map.node;
  Kokkos::parallel_for(
      "impm::moveCorners", RangePolicy<Space>(0, map.numParticles()), KOKKOS_LAMBDA(const int p) {
        double step[kCorners][Dim] = {};
        for (int c = 0; c < kCorners; ++c) {
          double g[Dim];
          for (int d = 0; d < Dim; ++d)
            g[d] = clipToGrid(grid, d, grid.gridCoord(d, at(p, c * Dim + d)));
          for (std::size_t k = rowPtr(p); k < rowPtr(p + 1); ++k) {
            int idx[Dim];
            grid.nodeIndex(node(k), idx);
            double n = 1.0;
            for (int d = 0; d < Dim; ++d)
              n *= tent(g[d] - idx[d]);
            for (int a = 0; a < Dim; ++a)
              step[c][a] += n * du(entryDofs(k) + a, 0);
          }
        }
        for (int c = 0; c < kCorners; ++c)
          for (int a = 0; a < Dim; ++a)
            corners(p, c * Dim + a) += step[c][a];
      });
}

#define IMPM_INSTANTIATE(D)                                                                     \
  template void moveCorners<D, DefaultExecSpace>(Kinematics, const GridGeometry<D>&,            \
                                                 const ParticleGridMap<D>&, const EntryDofs<>&, \
                                                 const LocalValues&, const ParticleSet<D>&);
IMPM_INSTANTIATE(1)
IMPM_INSTANTIATE(2)
IMPM_INSTANTIATE(3)
#undef IMPM_INSTANTIATE

}  // namespace impm
