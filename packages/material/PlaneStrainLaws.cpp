#include "material/PlaneStrainLaws.hpp"

#include <sstream>

#include "core/Errors.hpp"
#include "core/Parameters.hpp"

namespace impm {

namespace {

KOKKOS_INLINE_FUNCTION void load(const Material<2>::Tensors& F, int p, double f[2][2]) {
  for (int a = 0; a < 2; ++a)
    for (int b = 0; b < 2; ++b)
      f[a][b] = F(p, a, b);
}

}  // namespace

template <class Law>
Teuchos::ParameterList PlaneStrainLaw<Law>::validParameters() {
  Teuchos::ParameterList valid;
  declareDouble(valid, "E", 1.0, "Young's modulus (plane strain)", Bounds::positive(), true);
  declareDouble(valid, "nu", 0.0, "Poisson's ratio, -1 < nu < 0.5", Bounds{-1.0, 0.5, true, true},
                true);
  return valid;
}

template <class Law>
PlaneStrainLaw<Law>::PlaneStrainLaw(const std::string& name, const Teuchos::ParameterList& params)
    : Material<2>(name, params.get<double>("Density")) {
  const double E = params.get<double>("E"), nu = params.get<double>("nu");
  lame_.mu = E / (2.0 * (1.0 + nu));
  lame_.lambda = E * nu / ((1.0 + nu) * (1.0 - 2.0 * nu));
}

template <class Law>
void PlaneStrainLaw<Law>::firstPiola(const Particles& particles, const Tensors& F, int index,
                                     Tensors& P, Tangents& A) const {
  auto material = particles.material;
  const Lame lame = lame_;
  const int n = static_cast<int>(particles.size());
  int firstBad = n;
  Kokkos::parallel_reduce(
      "impm::PlaneStrainLaw", RangePolicy<DefaultExecSpace>(0, n),
      KOKKOS_LAMBDA(const int p, int& bad) {
        if (material(p) != index)
          return;
        double f[2][2];
        load(F, p, f);
        const PlaneStrainValue v = Law::evaluate(f, lame);
        if (!v.admissible && p < bad)
          bad = p;
        for (int a = 0; a < 2; ++a)
          for (int b = 0; b < 2; ++b) {
            P(p, a, b) = v.P[a][b];
            for (int c = 0; c < 2; ++c)
              for (int d = 0; d < 2; ++d)
                A(p, a, b, c, d) = v.A[a][b][c][d];
          }
      },
      Kokkos::Min<int>(firstBad));
  if (firstBad < n) {
    auto Fh = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), F);
    auto id = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), particles.id);
    const double J =
        Fh(firstBad, 0, 0) * Fh(firstBad, 1, 1) - Fh(firstBad, 0, 1) * Fh(firstBad, 1, 0);
    std::ostringstream msg;
    msg << "material '" << name() << "' (" << Law::model()
        << ") is not defined at J = det F = " << J << " (particle " << id(firstBad)
        << "): the particle is inverted";
    throw NumericalError(msg.str());
  }
}

template <class Law>
void PlaneStrainLaw<Law>::energyDensity(const Particles& particles, const Tensors& F, int index,
                                        Particles::Scalars& W) const {
  auto material = particles.material;
  const Lame lame = lame_;
  Kokkos::parallel_for(
      "impm::PlaneStrainLaw::energy", RangePolicy<DefaultExecSpace>(0, particles.size()),
      KOKKOS_LAMBDA(const int p) {
        if (material(p) != index)
          return;
        double f[2][2];
        load(F, p, f);
        W(p) = Law::evaluate(f, lame).W;
      });
}

template <class Law>
void PlaneStrainLaw<Law>::outOfPlaneStress(const Particles& particles, const Tensors& F, int index,
                                           Particles::Scalars& stressZZ) const {
  auto material = particles.material;
  const Lame lame = lame_;
  Kokkos::parallel_for(
      "impm::PlaneStrainLaw::stressZZ", RangePolicy<DefaultExecSpace>(0, particles.size()),
      KOKKOS_LAMBDA(const int p) {
        if (material(p) != index)
          return;
        double f[2][2];
        load(F, p, f);
        stressZZ(p) = Law::evaluate(f, lame).stressZZ;
      });
}

template class PlaneStrainLaw<LinearElasticLaw>;
template class PlaneStrainLaw<NeoHookeanLaw>;

}  // namespace impm
