#include "assembly/Forces.hpp"

#include "assembly/RowAccumulator.hpp"

namespace impm {

template <int Dim, class Space>
void addInternalForce(const ParticleGridMap<Dim, Space>& map, const EntryDofs<Space>& entryDofs,
                      const ParticleSet<Dim, Space>& particles,
                      const typename ParticleSet<Dim, Space>::Tensors& Pn,
                      const LocalValuesMutable& f) {
  auto rowPtr = map.rowPtr;
  auto grad = map.grad;
  auto section = particles.section;
  auto volume = particles.volume;
  Kokkos::parallel_for(
      "impm::internalForce", RangePolicy<Space>(0, map.numParticles()), KOKKOS_LAMBDA(const int p) {
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

template <int Dim, class Space>
void addExternalForce(const ParticleGridMap<Dim, Space>& map, const EntryDofs<Space>& entryDofs,
                      const typename ParticleSet<Dim, Space>::Vectors& force, double scale,
                      const LocalValuesMutable& f) {
  auto rowPtr = map.rowPtr;
  auto phi = map.phi;
  Kokkos::parallel_for(
      "impm::externalForce", RangePolicy<Space>(0, map.numParticles()), KOKKOS_LAMBDA(const int p) {
        for (std::size_t k = rowPtr(p); k < rowPtr(p + 1); ++k)
          for (int a = 0; a < Dim; ++a)
            Kokkos::atomic_add(&f(entryDofs(k) + a, 0), -scale * phi(k) * force(p, a));
      });
}

template <int Dim, class Space>
void addTangent(const ParticleGridMap<Dim, Space>& map, const EntryDofs<Space>& entryDofs,
                const ParticleSet<Dim, Space>& particles, const Tangents<Dim, Space>& An,
                const LocalMatrix& K, const typename ParticleSet<Dim, Space>::Scalars& scale) {
  auto rowPtr = map.rowPtr;
  auto grad = map.grad;
  auto section = particles.section;
  auto volume = particles.volume;
  const bool scaled = scale.extent(0) > 0;
  Kokkos::parallel_for(
      "impm::tangent", RangePolicy<Space>(0, map.numParticles()), KOKKOS_LAMBDA(const int p) {
        const double w = section(p) * volume(p) * (scaled ? scale(p) : 1.0);
        for (std::size_t ki = rowPtr(p); ki < rowPtr(p + 1); ++ki) {
          // wGA_acd = w sum_b G_ipb A^n_abcd, once per node i instead of once per pair (i, j)
          double wGA[Dim][Dim][Dim];
          for (int a = 0; a < Dim; ++a)
            for (int c = 0; c < Dim; ++c)
              for (int d = 0; d < Dim; ++d) {
                double s = 0;
                for (int b = 0; b < Dim; ++b)
                  s += grad(ki, b) * An(p, a, b, c, d);
                wGA[a][c][d] = w * s;
              }
          NodeRowsAccumulator<LocalMatrix, Dim> rows(K, entryDofs(ki));
          for (std::size_t kj = rowPtr(p); kj < rowPtr(p + 1); ++kj)
            for (int c = 0; c < Dim; ++c) {
              double s[Dim] = {};
              for (int a = 0; a < Dim; ++a)
                for (int d = 0; d < Dim; ++d)
                  s[a] += wGA[a][c][d] * grad(kj, d);
              rows.add(entryDofs(kj) + c, s);
            }
        }
      });
}

template <int Dim, class Space>
void addStressRoundOffScale(const ParticleGridMap<Dim, Space>& map,
                            const EntryDofs<Space>& entryDofs,
                            const ParticleSet<Dim, Space>& particles,
                            const Tangents<Dim, Space>& An,
                            const typename ParticleSet<Dim, Space>::Tensors& g,
                            const LocalValuesMutable& s) {
  auto rowPtr = map.rowPtr;
  auto grad = map.grad;
  auto section = particles.section;
  auto volume = particles.volume;
  const bool identity = g.extent(0) == 0;
  Kokkos::parallel_for(
      "impm::stressRoundOff", RangePolicy<Space>(0, map.numParticles()),
      KOKKOS_LAMBDA(const int p) {
        double AG[Dim][Dim];  // sum_cD |An_aBcD| |g_cD|
        for (int a = 0; a < Dim; ++a)
          for (int B = 0; B < Dim; ++B) {
            double sum = 0.0;
            for (int c = 0; c < Dim; ++c)
              for (int D = 0; D < Dim; ++D) {
                const double gcD = identity ? (c == D ? 1.0 : 0.0) : g(p, c, D);
                sum +=
                    Kokkos::Experimental::fabs(An(p, a, B, c, D)) * Kokkos::Experimental::fabs(gcD);
              }
            AG[a][B] = sum;
          }
        const double w = section(p) * volume(p);
        for (std::size_t k = rowPtr(p); k < rowPtr(p + 1); ++k)
          for (int a = 0; a < Dim; ++a) {
            double sum = 0.0;
            for (int B = 0; B < Dim; ++B)
              sum += AG[a][B] * Kokkos::Experimental::fabs(grad(k, B));
            Kokkos::atomic_add(&s(entryDofs(k) + a, 0), w * sum);
          }
      });
}

#define IMPM_INSTANTIATE(D)                                                                     \
  template void addInternalForce<D, DefaultExecSpace>(                                          \
      const ParticleGridMap<D>&, const EntryDofs<>&, const ParticleSet<D>&,                     \
      const ParticleSet<D>::Tensors&, const LocalValuesMutable&);                               \
  template void addExternalForce<D, DefaultExecSpace>(                                          \
      const ParticleGridMap<D>&, const EntryDofs<>&, const ParticleSet<D>::Vectors&, double,    \
      const LocalValuesMutable&);                                                               \
  template void addTangent<D, DefaultExecSpace>(                                                \
      const ParticleGridMap<D>&, const EntryDofs<>&, const ParticleSet<D>&, const Tangents<D>&, \
      const LocalMatrix&, const ParticleSet<D>::Scalars&);                                      \
  template void addStressRoundOffScale<D, DefaultExecSpace>(                                    \
      const ParticleGridMap<D>&, const EntryDofs<>&, const ParticleSet<D>&, const Tangents<D>&, \
      const ParticleSet<D>::Tensors&, const LocalValuesMutable&);
IMPM_INSTANTIATE(1)
IMPM_INSTANTIATE(2)
IMPM_INSTANTIATE(3)
#undef IMPM_INSTANTIATE

}  // namespace impm
