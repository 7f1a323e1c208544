#include "assembly/ParticleUpdate.hpp"

namespace impm {

template <int Dim, class Space>
void displaceParticles(const ParticleGridMap<Dim, Space>& map, const EntryDofs<Space>& entryDofs,
                       const LocalValues& du, const ParticleSet<Dim, Space>& particles) {
  auto rowPtr = map.rowPtr;
  auto phi = map.phi;
  auto u = particles.u;
  auto x = particles.x;
  Kokkos::parallel_for(
      "impm::displaceParticles", RangePolicy<Space>(0, map.numParticles()),
      KOKKOS_LAMBDA(const int p) {
        for (int a = 0; a < Dim; ++a) {
          double dup = 0;
          for (std::size_t k = rowPtr(p); k < rowPtr(p + 1); ++k)
            dup += phi(k) * du(entryDofs(k) + a, 0);
          u(p, a) += dup;
          x(p, a) += dup;  // total Lagrangian: x = X + u, the map stays at X
        }
      });
}

template <int Dim, class Space>
void commitDeformation(Kinematics kinematics, const typename ParticleSet<Dim, Space>::Tensors& F,
                       const typename ParticleSet<Dim, Space>::Tensors& P,
                       const ParticleSet<Dim, Space>& particles) {
  auto Fp = particles.F;
  auto stress = particles.stress;
  auto volume = particles.volume;
  auto volume0 = particles.volume0;
  auto domain = particles.domain;
  auto domain0 = particles.domain0;
  const bool moves = kinematics == Kinematics::updatedLagrangian;
  Kokkos::parallel_for(
      "impm::commitDeformation", RangePolicy<Space>(0, particles.size()),
      KOKKOS_LAMBDA(const int p) {
        for (int a = 0; a < Dim; ++a)
          for (int b = 0; b < Dim; ++b)
            Fp(p, a, b) = F(p, a, b);
        const double J = determinant<Dim>(F, p);
        for (int a = 0; a < Dim; ++a)
          for (int b = 0; b < Dim; ++b) {
            double s = 0;
            for (int c = 0; c < Dim; ++c)
              s += P(p, a, c) * F(p, b, c);
            stress(p, a, b) = s / J;
          }
        // Where the particles move, the domain follows F and the volume J (total
        // Lagrangian: the map stays on domain0, and followDeformation draws the domain for
        // output).
        if (moves) {
          deformedDomain<Dim>(F, domain0, domain, p);
          volume(p) = J * volume0(p);
        }
      });
}

template <int Dim, class Space>
void followDeformation(const ParticleSet<Dim, Space>& particles) {
  auto F = particles.F;
  auto domain = particles.domain;
  auto domain0 = particles.domain0;
  Kokkos::parallel_for(
      "impm::followDeformation", RangePolicy<Space>(0, particles.size()),
      KOKKOS_LAMBDA(const int p) { deformedDomain<Dim>(F, domain0, domain, p); });
}

#define IMPM_INSTANTIATE(D)                                                                        \
  template void displaceParticles<D, DefaultExecSpace>(                                            \
      const ParticleGridMap<D>&, const EntryDofs<>&, const LocalValues&, const ParticleSet<D>&);   \
  template void commitDeformation<D, DefaultExecSpace>(Kinematics, const ParticleSet<D>::Tensors&, \
                                                       const ParticleSet<D>::Tensors&,             \
                                                       const ParticleSet<D>&);                     \
  template void followDeformation<D, DefaultExecSpace>(const ParticleSet<D>&);
IMPM_INSTANTIATE(1)
IMPM_INSTANTIATE(2)
IMPM_INSTANTIATE(3)
#undef IMPM_INSTANTIATE

}  // namespace impm
