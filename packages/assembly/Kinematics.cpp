#include "assembly/Kinematics.hpp"

namespace impm {

template <int Dim>
void trialDeformationGradient(Kinematics kinematics, const ParticleGridMap<Dim>& map,
                              const Kokkos::View<LO*>& entryDofs, const LocalValues& du,
                              const typename ParticleSet<Dim>::Tensors& Fn,
                              typename ParticleSet<Dim>::Tensors& F) {
  auto rowPtr = map.rowPtr;
  auto grad = map.grad;
  const bool total = kinematics == Kinematics::totalLagrangian;
  Kokkos::parallel_for(
      "impm::trialF", RangePolicy<DefaultExecSpace>(0, map.numParticles()),
      KOKKOS_LAMBDA(const int p) {
        double H[Dim][Dim] = {};  // grad du
        for (std::size_t k = rowPtr(p); k < rowPtr(p + 1); ++k)
          for (int a = 0; a < Dim; ++a)
            for (int b = 0; b < Dim; ++b)
              H[a][b] += du(entryDofs(k) + a, 0) * grad(k, b);
        for (int a = 0; a < Dim; ++a)
          for (int b = 0; b < Dim; ++b) {
            double value = Fn(p, a, b);
            if (total) {
              value += H[a][b];
            } else {
              for (int c = 0; c < Dim; ++c)
                value += H[a][c] * Fn(p, c, b);
            }
            F(p, a, b) = value;
          }
      });
}

template <int Dim>
void stressRelativeToStepStart(Kinematics kinematics, const typename ParticleSet<Dim>::Tensors& Fn,
                               const typename ParticleSet<Dim>::Tensors& P, const Tangents<Dim>& A,
                               typename ParticleSet<Dim>::Tensors& Pn, Tangents<Dim>& An) {
  if (kinematics == Kinematics::totalLagrangian) {
    Kokkos::deep_copy(Pn, P);
    Kokkos::deep_copy(An, A);
    return;
  }
  Kokkos::parallel_for(
      "impm::pushForwardToStepStart", RangePolicy<DefaultExecSpace>(0, Fn.extent(0)),
      KOKKOS_LAMBDA(const int p) {
        const double J = determinant<Dim>(Fn, p);
        for (int a = 0; a < Dim; ++a)
          for (int B = 0; B < Dim; ++B) {
            double s = 0;
            for (int E = 0; E < Dim; ++E)
              s += P(p, a, E) * Fn(p, B, E);
            Pn(p, a, B) = s / J;
          }
        for (int a = 0; a < Dim; ++a)
          for (int B = 0; B < Dim; ++B)
            for (int c = 0; c < Dim; ++c)
              for (int D = 0; D < Dim; ++D) {
                double s = 0;
                for (int E = 0; E < Dim; ++E)
                  for (int G = 0; G < Dim; ++G)
                    s += A(p, a, E, c, G) * Fn(p, B, E) * Fn(p, D, G);
                An(p, a, B, c, D) = s / J;
              }
      });
}

template void trialDeformationGradient<1>(Kinematics, const ParticleGridMap<1>&,
                                          const Kokkos::View<LO*>&, const LocalValues&,
                                          const ParticleSet<1>::Tensors&, ParticleSet<1>::Tensors&);
template void trialDeformationGradient<2>(Kinematics, const ParticleGridMap<2>&,
                                          const Kokkos::View<LO*>&, const LocalValues&,
                                          const ParticleSet<2>::Tensors&, ParticleSet<2>::Tensors&);
template void stressRelativeToStepStart<1>(Kinematics, const ParticleSet<1>::Tensors&,
                                           const ParticleSet<1>::Tensors&, const Tangents<1>&,
                                           ParticleSet<1>::Tensors&, Tangents<1>&);
template void stressRelativeToStepStart<2>(Kinematics, const ParticleSet<2>::Tensors&,
                                           const ParticleSet<2>::Tensors&, const Tangents<2>&,
                                           ParticleSet<2>::Tensors&, Tangents<2>&);

}  // namespace impm
