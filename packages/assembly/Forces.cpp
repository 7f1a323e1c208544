#include "assembly/Forces.hpp"

namespace impm {

template <int Dim>
void addInternalForce(const ParticleGridMap<Dim>& map, const Kokkos::View<LO*>& entryDofs,
                      const ParticleSet<Dim>& particles,
                      const typename ParticleSet<Dim>::Tensors& Pn, const LocalValuesMutable& f) {
  auto rowPtr = map.rowPtr;
  auto grad = map.grad;
  auto section = particles.section;
  auto volume = particles.volume;
  Kokkos::parallel_for(
      "impm::internalForce", RangePolicy<DefaultExecSpace>(0, map.numParticles()),
      KOKKOS_LAMBDA(const int p) {
        const double w = section(p) * volume(p);
        for (std::size_t k = rowPtr(p); k < rowPtr(p + 1); ++k)
          for (int a = 0; a < Dim; ++a) {
            double s = 0;
            for (int b = 0; b < Dim; ++b)
              s += Pn(p, a, b) * grad(k, b);
            Kokkos::atomic_add(&f(entryDofs(k) + a, 0), w * s);
          }
      });
}

template <int Dim>
void addExternalForce(const ParticleGridMap<Dim>& map, const Kokkos::View<LO*>& entryDofs,
                      const typename ParticleSet<Dim>::Vectors& force, double scale,
                      const LocalValuesMutable& f) {
  auto rowPtr = map.rowPtr;
  auto phi = map.phi;
  Kokkos::parallel_for(
      "impm::externalForce", RangePolicy<DefaultExecSpace>(0, map.numParticles()),
      KOKKOS_LAMBDA(const int p) {
        for (std::size_t k = rowPtr(p); k < rowPtr(p + 1); ++k)
          for (int a = 0; a < Dim; ++a)
            Kokkos::atomic_add(&f(entryDofs(k) + a, 0), -scale * phi(k) * force(p, a));
      });
}

template <int Dim>
void addTangent(const ParticleGridMap<Dim>& map, const Kokkos::View<LO*>& entryRows,
                const Kokkos::View<LO**>& entryCols, const ParticleSet<Dim>& particles,
                const Tangents<Dim>& An, const LocalMatrix& K) {
  auto rowPtr = map.rowPtr;
  auto grad = map.grad;
  auto section = particles.section;
  auto volume = particles.volume;
  Kokkos::parallel_for(
      "impm::tangent", RangePolicy<DefaultExecSpace>(0, map.numParticles()),
      KOKKOS_LAMBDA(const int p) {
        const double w = section(p) * volume(p);
        for (std::size_t ki = rowPtr(p); ki < rowPtr(p + 1); ++ki)
          for (int a = 0; a < Dim; ++a) {
            const LO row = entryRows(ki) + a;
            for (std::size_t kj = rowPtr(p); kj < rowPtr(p + 1); ++kj) {
              LO cols[Dim];
              double vals[Dim];
              for (int c = 0; c < Dim; ++c) {
                double s = 0;
                for (int b = 0; b < Dim; ++b)
                  for (int d = 0; d < Dim; ++d)
                    s += grad(ki, b) * An(p, a, b, c, d) * grad(kj, d);
                cols[c] = entryCols(kj, c);
                vals[c] = w * s;
              }
              K.sumIntoValues(row, cols, Dim, vals, false, true);
            }
          }
      });
}

template void addInternalForce<1>(const ParticleGridMap<1>&, const Kokkos::View<LO*>&,
                                  const ParticleSet<1>&, const ParticleSet<1>::Tensors&,
                                  const LocalValuesMutable&);
template void addInternalForce<2>(const ParticleGridMap<2>&, const Kokkos::View<LO*>&,
                                  const ParticleSet<2>&, const ParticleSet<2>::Tensors&,
                                  const LocalValuesMutable&);
template void addExternalForce<1>(const ParticleGridMap<1>&, const Kokkos::View<LO*>&,
                                  const ParticleSet<1>::Vectors&, double,
                                  const LocalValuesMutable&);
template void addExternalForce<2>(const ParticleGridMap<2>&, const Kokkos::View<LO*>&,
                                  const ParticleSet<2>::Vectors&, double,
                                  const LocalValuesMutable&);
template void addTangent<1>(const ParticleGridMap<1>&, const Kokkos::View<LO*>&,
                            const Kokkos::View<LO**>&, const ParticleSet<1>&, const Tangents<1>&,
                            const LocalMatrix&);
template void addTangent<2>(const ParticleGridMap<2>&, const Kokkos::View<LO*>&,
                            const Kokkos::View<LO**>&, const ParticleSet<2>&, const Tangents<2>&,
                            const LocalMatrix&);

}  // namespace impm
