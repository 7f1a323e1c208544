#include "material/ElasticLaws.hpp"

#include "material/HenckyLaw.hpp"

#include <sstream>

#include "core/Errors.hpp"
#include "core/Parameters.hpp"

namespace impm {

template <int Dim>
void throwIfInverted(const Material<Dim>& material, const char* model,
                     const typename Material<Dim>::Evaluation& at, int firstBad) {
  if (firstBad >= static_cast<int>(at.members.extent(0)))
    return;
  auto Fh = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), at.F);
  auto id = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), at.particles.id);
  auto m = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), at.members);
  std::ostringstream msg;
  msg << "material '" << material.name() << "' (" << model
      << ") is not defined at J = det F = " << determinant<Dim>(Fh, m(firstBad)) << " (particle "
      << id(m(firstBad)) << "): the particle is inverted";
  throw NumericalError(msg.str());
}

void declareElasticConstants(Teuchos::ParameterList& valid) {
  declareDouble(valid, "E", 1.0, "Young's modulus", Bounds::positive(), true);
  declareDouble(valid, "nu", 0.0, "Poisson's ratio, -1 < nu < 0.5", Bounds{-1.0, 0.5, true, true},
                true);
}

Lame lameOf(const Teuchos::ParameterList& params) {
  const double E = params.get<double>("E"), nu = params.get<double>("nu");
  return {E / (2.0 * (1.0 + nu)), E * nu / ((1.0 + nu) * (1.0 - 2.0 * nu))};
}

template <int Dim, class Law>
Teuchos::ParameterList ElasticLaw<Dim, Law>::validParameters() {
  Teuchos::ParameterList valid;
  declareElasticConstants(valid);
  return valid;
}

template <int Dim, class Law>
ElasticLaw<Dim, Law>::ElasticLaw(const std::string& name, const Teuchos::ParameterList& params)
    : Material<Dim>(name, params.get<double>("Density")), lame_(lameOf(params)) {}

template <int Dim, class Law>
void ElasticLaw<Dim, Law>::firstPiola(const Evaluation& at, Tensors& P, Tangents& A) const {
  const auto members = at.members;
  const auto F = at.F;
  const Lame lame = lame_;
  const int n = static_cast<int>(members.extent(0));
  int firstBad = n;
  Kokkos::parallel_reduce(
      "impm::ElasticLaw", RangePolicy<ExecutionSpace>(0, n),
      KOKKOS_LAMBDA(const int i, int& bad) {
        const int p = members(i);
        double f[Dim][Dim];
        load<Dim>(F, p, f);
        const ElasticValue<Dim> v = Law::template evaluate<Dim>(f, lame);
        if (!v.admissible && i < bad)
          bad = i;
        store<Dim>(P, A, p, v.P, v.A);
      },
      Kokkos::Min<int>(firstBad));
  throwIfInverted<Dim>(*this, Law::model(), at, firstBad);
}

template <int Dim, class Law>
void ElasticLaw<Dim, Law>::energyDensity(const Evaluation& at, Scalars& W) const {
  setFromValue("impm::ElasticLaw::energy", at, &ElasticValue<Dim>::W, W);
}

template <int Dim, class Law>
void ElasticLaw<Dim, Law>::outOfPlaneStress(const Evaluation& at, Scalars& stressZZ) const {
  if constexpr (Dim == 2)  // plane strain; a 3-D stress has its own zz component
    setFromValue("impm::ElasticLaw::stressZZ", at, &ElasticValue<Dim>::stressZZ, stressZZ);
}

template <int Dim, class Law>
void ElasticLaw<Dim, Law>::setFromValue(const char* label, const Evaluation& at,
                                        double ElasticValue<Dim>::*field, Scalars& out) const {
  const auto F = at.F;
  const Lame lame = lame_;
  setForMembers<ExecutionSpace>(
      label, at.members, out, KOKKOS_LAMBDA(const int p) {
        double f[Dim][Dim];
        load<Dim>(F, p, f);
        return Law::template evaluate<Dim>(f, lame).*field;
      });
}

template void throwIfInverted<2>(const Material<2>&, const char*, const Material<2>::Evaluation&,
                                 int);
template void throwIfInverted<3>(const Material<3>&, const char*, const Material<3>::Evaluation&,
                                 int);
template class ElasticLaw<2, LinearElasticLaw>;
template class ElasticLaw<2, NeoHookeanLaw>;
template class ElasticLaw<2, HenckyLaw>;
template class ElasticLaw<3, LinearElasticLaw>;
template class ElasticLaw<3, NeoHookeanLaw>;
template class ElasticLaw<3, HenckyLaw>;

}  // namespace impm
