#include "assembly/ParticleUpdate.hpp"

namespace impm {

template <int Dim>
void updateParticles(Kinematics kinematics, const ParticleGridMap<Dim>& map,
                     const Kokkos::View<LO*>& entryDofs, const LocalValues& du,
                     const typename ParticleSet<Dim>::Tensors& F,
                     const typename ParticleSet<Dim>::Tensors& P, ParticleSet<Dim>& particles) {
  auto rowPtr = map.rowPtr;
  auto phi = map.phi;
  auto u = particles.u;
  auto x = particles.x;
  auto Fp = particles.F;
  auto stress = particles.stress;
  auto volume = particles.volume;
  auto volume0 = particles.volume0;
  auto domain = particles.domain;
  auto domain0 = particles.domain0;
  const bool moves = kinematics == Kinematics::updatedLagrangian;
  Kokkos::parallel_for(
      "impm::updateParticles", RangePolicy<DefaultExecSpace>(0, map.numParticles()),
      KOKKOS_LAMBDA(const int p) {
        for (int a = 0; a < Dim; ++a) {
          double dup = 0;
          for (std::size_t k = rowPtr(p); k < rowPtr(p + 1); ++k)
            dup += phi(k) * du(entryDofs(k) + a, 0);
          u(p, a) += dup;
          x(p, a) += dup;  // total Lagrangian: x = X + u, the map stays at X
        }
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
        if (!moves)
          return;
        volume(p) = J * volume0(p);
        for (int a = 0; a < Dim; ++a)
          for (int k = 0; k < Dim; ++k) {
            double s = 0;
            for (int c = 0; c < Dim; ++c)
              s += F(p, a, c) * domain0(p, c, k);
            domain(p, a, k) = s;
          }
      });
}

template void updateParticles<1>(Kinematics, const ParticleGridMap<1>&, const Kokkos::View<LO*>&,
                                 const LocalValues&, const ParticleSet<1>::Tensors&,
                                 const ParticleSet<1>::Tensors&, ParticleSet<1>&);
template void updateParticles<2>(Kinematics, const ParticleGridMap<2>&, const Kokkos::View<LO*>&,
                                 const LocalValues&, const ParticleSet<2>::Tensors&,
                                 const ParticleSet<2>::Tensors&, ParticleSet<2>&);

}  // namespace impm
