#include "assembly/Mass.hpp"

#include "assembly/RowAccumulator.hpp"

namespace impm {

template <int Dim, class Space>
void particleToGrid(const ParticleGridMap<Dim, Space>& map, const EntryDofs<Space>& entryDofs,
                    const typename ParticleSet<Dim, Space>::Scalars& mass,
                    const typename ParticleSet<Dim, Space>::Vectors& q,
                    const LocalValuesMutable& f) {
  auto rowPtr = map.rowPtr;
  auto phi = map.phi;
  Kokkos::parallel_for(
      "impm::particleToGrid", RangePolicy<Space>(0, map.numParticles()),
      KOKKOS_LAMBDA(const int p) {
        for (std::size_t k = rowPtr(p); k < rowPtr(p + 1); ++k)
          for (int d = 0; d < Dim; ++d)
            Kokkos::atomic_add(&f(entryDofs(k) + d, 0), mass(p) * phi(k) * q(p, d));
      });
}

template <int Dim, class Space>
void addLumpedMass(const ParticleGridMap<Dim, Space>& map, const EntryDofs<Space>& entryDofs,
                   const typename ParticleSet<Dim, Space>::Scalars& mass,
                   const LocalValuesMutable& m) {
  auto rowPtr = map.rowPtr;
  auto phi = map.phi;
  Kokkos::parallel_for(
      "impm::lumpedMass", RangePolicy<Space>(0, map.numParticles()), KOKKOS_LAMBDA(const int p) {
        for (std::size_t k = rowPtr(p); k < rowPtr(p + 1); ++k)
          for (int d = 0; d < Dim; ++d)
            Kokkos::atomic_add(&m(entryDofs(k) + d, 0), mass(p) * phi(k));
      });
}

template <int Dim, class Space>
void addConsistentInertiaForce(const ParticleGridMap<Dim, Space>& map,
                               const EntryDofs<Space>& entryDofs,
                               const typename ParticleSet<Dim, Space>::Scalars& mass,
                               const LocalValues& a, const LocalValuesMutable& f) {
  auto rowPtr = map.rowPtr;
  auto phi = map.phi;
  Kokkos::parallel_for(
      "impm::inertiaForce", RangePolicy<Space>(0, map.numParticles()), KOKKOS_LAMBDA(const int p) {
        double ap[Dim] = {};  // the particle's acceleration sum_j phi_jp a_j
        for (std::size_t k = rowPtr(p); k < rowPtr(p + 1); ++k)
          for (int d = 0; d < Dim; ++d)
            ap[d] += phi(k) * a(entryDofs(k) + d, 0);
        for (std::size_t k = rowPtr(p); k < rowPtr(p + 1); ++k)
          for (int d = 0; d < Dim; ++d)
            Kokkos::atomic_add(&f(entryDofs(k) + d, 0), mass(p) * phi(k) * ap[d]);
      });
}

template <class Space>
void addDiagonal(double scale, const LocalValues& d, const LocalMatrix& K) {
  // Added once per row: one search of the row instead of one per particle and node.
  Kokkos::parallel_for(
      "impm::addDiagonal", RangePolicy<Space>(0, d.extent(0)), KOKKOS_LAMBDA(const LO row) {
        if (d(row, 0) != 0.0)
          RowAccumulator<LocalMatrix>(K, row).add(row, scale * d(row, 0));
      });
}

template <int Dim, class Space>
void addConsistentMassMatrix(double scale, const ParticleGridMap<Dim, Space>& map,
                             const EntryDofs<Space>& entryDofs,
                             const typename ParticleSet<Dim, Space>::Scalars& mass,
                             const LocalMatrix& K) {
  auto rowPtr = map.rowPtr;
  auto phi = map.phi;
  Kokkos::parallel_for(
      "impm::massMatrix", RangePolicy<Space>(0, map.numParticles()), KOKKOS_LAMBDA(const int p) {
        for (std::size_t ki = rowPtr(p); ki < rowPtr(p + 1); ++ki)
          for (int d = 0; d < Dim; ++d) {
            RowAccumulator<LocalMatrix> sum(K, entryDofs(ki) + d);
            for (std::size_t kj = rowPtr(p); kj < rowPtr(p + 1); ++kj)
              sum.add(entryDofs(kj) + d, scale * mass(p) * phi(ki) * phi(kj));
          }
      });
}

template <int Dim, class Space>
void gridToParticleVelocity(const ParticleGridMap<Dim, Space>& map,
                            const EntryDofs<Space>& entryDofs, const LocalValues& vOld,
                            const LocalValues& vNew, const LocalValues& aNew, double flip,
                            const ParticleSet<Dim, Space>& particles) {
  auto rowPtr = map.rowPtr;
  auto phi = map.phi;
  auto v = particles.v;
  auto a = particles.a;
  const bool pure = flip == 0.0;  // PIC: the old velocities are not read
  Kokkos::parallel_for(
      "impm::gridToParticleVelocity", RangePolicy<Space>(0, map.numParticles()),
      KOKKOS_LAMBDA(const int p) {
        for (int d = 0; d < Dim; ++d) {
          double change = 0, pic = 0, acc = 0;
          for (std::size_t k = rowPtr(p); k < rowPtr(p + 1); ++k) {
            const LO i = entryDofs(k) + d;
            if (!pure)
              change += phi(k) * (vNew(i, 0) - vOld(i, 0));
            pic += phi(k) * vNew(i, 0);
            acc += phi(k) * aNew(i, 0);
          }
          v(p, d) = pure ? pic : flip * (v(p, d) + change) + (1.0 - flip) * pic;
          a(p, d) = acc;
        }
      });
}

#define IMPM_INSTANTIATE(D)                                                                       \
  template void particleToGrid<D, DefaultExecSpace>(                                              \
      const ParticleGridMap<D>&, const EntryDofs<>&, const ParticleSet<D>::Scalars&,              \
      const ParticleSet<D>::Vectors&, const LocalValuesMutable&);                                 \
  template void addLumpedMass<D, DefaultExecSpace>(const ParticleGridMap<D>&, const EntryDofs<>&, \
                                                   const ParticleSet<D>::Scalars&,                \
                                                   const LocalValuesMutable&);                    \
  template void addConsistentInertiaForce<D, DefaultExecSpace>(                                   \
      const ParticleGridMap<D>&, const EntryDofs<>&, const ParticleSet<D>::Scalars&,              \
      const LocalValues&, const LocalValuesMutable&);                                             \
  template void addConsistentMassMatrix<D, DefaultExecSpace>(                                     \
      double, const ParticleGridMap<D>&, const EntryDofs<>&, const ParticleSet<D>::Scalars&,      \
      const LocalMatrix&);                                                                        \
  template void gridToParticleVelocity<D, DefaultExecSpace>(                                      \
      const ParticleGridMap<D>&, const EntryDofs<>&, const LocalValues&, const LocalValues&,      \
      const LocalValues&, double, const ParticleSet<D>&);
IMPM_INSTANTIATE(1)
IMPM_INSTANTIATE(2)
IMPM_INSTANTIATE(3)
#undef IMPM_INSTANTIATE
template void addDiagonal<DefaultExecSpace>(double, const LocalValues&, const LocalMatrix&);

}  // namespace impm
