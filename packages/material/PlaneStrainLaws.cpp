#include "material/PlaneStrainLaws.hpp"

#include "material/HenckyLaw.hpp"

#include <sstream>

#include "core/Errors.hpp"
#include "core/Parameters.hpp"

namespace impm {

void throwIfInverted(const Material<2>& material, const char* model,
                     const Material<2>::Evaluation& at, int firstBad) {
  if (firstBad >= static_cast<int>(at.members.extent(0)))
    return;
  auto Fh = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), at.F);
  auto id = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), at.particles.id);
  auto m = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), at.members);
  std::ostringstream msg;
  msg << "material '" << material.name() << "' (" << model
      << ") is not defined at J = det F = " << determinant<2>(Fh, m(firstBad)) << " (particle "
      << id(m(firstBad)) << "): the particle is inverted";
  throw NumericalError(msg.str());
}

void declareElasticConstants(Teuchos::ParameterList& valid) {
  declareDouble(valid, "E", 1.0, "Young's modulus (plane strain)", Bounds::positive(), true);
  declareDouble(valid, "nu", 0.0, "Poisson's ratio, -1 < nu < 0.5", Bounds{-1.0, 0.5, true, true},
                true);
}

Lame lameOf(const Teuchos::ParameterList& params) {
  const double E = params.get<double>("E"), nu = params.get<double>("nu");
  return {E / (2.0 * (1.0 + nu)), E * nu / ((1.0 + nu) * (1.0 - 2.0 * nu))};
}

template <class Law>
Teuchos::ParameterList PlaneStrainLaw<Law>::validParameters() {
  Teuchos::ParameterList valid;
  declareElasticConstants(valid);
  return valid;
}

template <class Law>
PlaneStrainLaw<Law>::PlaneStrainLaw(const std::string& name, const Teuchos::ParameterList& params)
    : Material<2>(name, params.get<double>("Density")), lame_(lameOf(params)) {}

template <class Law>
void PlaneStrainLaw<Law>::firstPiola(const Evaluation& at, Tensors& P, Tangents& A) const {
  const auto members = at.members;
  const auto F = at.F;
  const Lame lame = lame_;
  const int n = static_cast<int>(members.extent(0));
  int firstBad = n;
  Kokkos::parallel_reduce(
      "impm::PlaneStrainLaw", RangePolicy<ExecutionSpace>(0, n),
      KOKKOS_LAMBDA(const int i, int& bad) {
        const int p = members(i);
        double f[2][2];
        load(F, p, f);
        const PlaneStrainValue v = Law::evaluate(f, lame);
        if (!v.admissible && i < bad)
          bad = i;
        store(P, A, p, v.P, v.A);
      },
      Kokkos::Min<int>(firstBad));
  throwIfInverted(*this, Law::model(), at, firstBad);
}

template <class Law>
void PlaneStrainLaw<Law>::energyDensity(const Evaluation& at, Scalars& W) const {
  setFromValue("impm::PlaneStrainLaw::energy", at, &PlaneStrainValue::W, W);
}

template <class Law>
void PlaneStrainLaw<Law>::outOfPlaneStress(const Evaluation& at, Scalars& stressZZ) const {
  setFromValue("impm::PlaneStrainLaw::stressZZ", at, &PlaneStrainValue::stressZZ, stressZZ);
}

template <class Law>
void PlaneStrainLaw<Law>::setFromValue(const char* label, const Evaluation& at,
                                       double PlaneStrainValue::*field, Scalars& out) const {
  const auto F = at.F;
  const Lame lame = lame_;
  setForMembers<ExecutionSpace>(
      label, at.members, out, KOKKOS_LAMBDA(const int p) {
        double f[2][2];
        load(F, p, f);
        return Law::evaluate(f, lame).*field;
      });
}

template class PlaneStrainLaw<LinearElasticLaw>;
template class PlaneStrainLaw<NeoHookeanLaw>;
template class PlaneStrainLaw<HenckyLaw>;

}  // namespace impm
