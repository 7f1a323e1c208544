#include "assembly/Kinematics.hpp"

namespace impm {

template <int Dim, class Space>
void trialDeformationGradient(Kinematics kinematics, const ParticleGridMap<Dim, Space>& map,
                              const EntryDofs<Space>& entryDofs, const LocalValues& du,
                              const typename ParticleSet<Dim, Space>::Tensors& Fn,
                              const typename ParticleSet<Dim, Space>::Tensors& F,
                              const typename ParticleSet<Dim, Space>::Tensors& g) {
  auto rowPtr = map.rowPtr;
  auto grad = map.grad;
  const bool total = kinematics == Kinematics::totalLagrangian;
  const bool relative = g.extent(0) > 0;
  Kokkos::parallel_for(
      "impm::trialF", RangePolicy<Space>(0, map.numParticles()), KOKKOS_LAMBDA(const int p) {
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
            if (relative)
              g(p, a, b) = total ? value : H[a][b] + (a == b ? 1.0 : 0.0);
          }
      });
}

template <int Dim, class Space>
void stressRelativeToStepStart(Kinematics kinematics,
                               const typename ParticleSet<Dim, Space>::Tensors& Fn,
                               const typename ParticleSet<Dim, Space>::Tensors& P,
                               const Tangents<Dim, Space>& A,
                               const typename ParticleSet<Dim, Space>::Tensors& Pn,
                               const Tangents<Dim, Space>& An) {
  if (kinematics == Kinematics::totalLagrangian) {
    if (Pn.data() != P.data())
      Kokkos::deep_copy(Pn, P);
    if (An.data() != A.data())
      Kokkos::deep_copy(An, A);
    return;
  }
  Kokkos::parallel_for(
      "impm::pushForwardToStepStart", RangePolicy<Space>(0, Fn.extent(0)),
      KOKKOS_LAMBDA(const int p) {
        const double J = determinant<Dim>(Fn, p);
        for (int a = 0; a < Dim; ++a)
          for (int B = 0; B < Dim; ++B) {
            double s = 0;
            for (int E = 0; E < Dim; ++E)
              s += P(p, a, E) * Fn(p, B, E);
            Pn(p, a, B) = s / J;
          }
        double Ap[Dim][Dim][Dim][Dim];  // read whole first: An may be A
        for (int a = 0; a < Dim; ++a)
          for (int E = 0; E < Dim; ++E)
            for (int c = 0; c < Dim; ++c)
              for (int G = 0; G < Dim; ++G)
                Ap[a][E][c][G] = A(p, a, E, c, G);
        for (int a = 0; a < Dim; ++a)
          for (int B = 0; B < Dim; ++B)
            for (int c = 0; c < Dim; ++c)
              for (int D = 0; D < Dim; ++D) {
                double s = 0;
                for (int E = 0; E < Dim; ++E)
                  for (int G = 0; G < Dim; ++G)
                    s += Ap[a][E][c][G] * Fn(p, B, E) * Fn(p, D, G);
                An(p, a, B, c, D) = s / J;
              }
      });
}

#define IMPM_INSTANTIATE(D)                                                          \
  template void trialDeformationGradient<D, DefaultExecSpace>(                       \
      Kinematics, const ParticleGridMap<D>&, const EntryDofs<>&, const LocalValues&, \
      const ParticleSet<D>::Tensors&, const ParticleSet<D>::Tensors&,                \
      const ParticleSet<D>::Tensors&);                                               \
  template void stressRelativeToStepStart<D, DefaultExecSpace>(                      \
      Kinematics, const ParticleSet<D>::Tensors&, const ParticleSet<D>::Tensors&,    \
      const Tangents<D>&, const ParticleSet<D>::Tensors&, const Tangents<D>&);
IMPM_INSTANTIATE(1)
IMPM_INSTANTIATE(2)
IMPM_INSTANTIATE(3)
#undef IMPM_INSTANTIATE

}  // namespace impm
