#include "material/ElasticLaws1D.hpp"

#include <sstream>

#include "core/Errors.hpp"
#include "material/MaterialPropertyFill.hpp"

namespace impm {

namespace {

const char* describe(const std::string& parameter) {
  return parameter == "E" ? "Modulus E(x) > 0, x the particle's reference position"
                          : "Cubic coefficient C(x) of sigma = E eps + C eps^3";
}

}  // namespace

template <class Law>
Teuchos::ParameterList ElasticLaw1D<Law>::validParameters() {
  Teuchos::ParameterList valid;
  for (const auto& p : Law::parameters())
    declareFormula(valid, p, "1.0", {"x"}, describe(p),
                   p == "E" ? Bounds::positive() : Bounds::any(), true);
  return valid;
}

template <class Law>
ElasticLaw1D<Law>::ElasticLaw1D(const std::string& name, const Teuchos::ParameterList& params)
    : Material<1>(name, params.get<double>("Density")) {
  for (const auto& p : Law::parameters())
    parameters_.emplace_back(formulaText(params, p), std::vector<std::string>{"x"});
}

template <class Law>
void ElasticLaw1D<Law>::initialize(Particles& particles, int index) const {
  const auto names = Law::parameters();
  for (std::size_t k = 0; k < names.size(); ++k)
    fillPropertyFromFormula(particles, index, static_cast<int>(k), parameters_[k],
                            "Materials/" + name() + "/" + names[k],
                            names[k] == "E" ? Bounds::positive() : Bounds::any());
}

template <class Law>
void ElasticLaw1D<Law>::firstPiola(const Particles& particles, const Tensors& F, int index,
                                   Tensors& P, Tangents& A) const {
  auto material = particles.material;
  auto props = particles.props;
  const int n = static_cast<int>(particles.size());
  int firstBad = n;
  Kokkos::parallel_reduce(
      "impm::ElasticLaw1D", RangePolicy<DefaultExecSpace>(0, n),
      KOKKOS_LAMBDA(const int p, int& bad) {
        if (material(p) != index)
          return;
        double k[kMaxMaterialProps];
        for (int j = 0; j < kMaxMaterialProps; ++j)
          k[j] = props(p, j);
        const LawValue v = Law::evaluate(F(p, 0, 0), k);
        P(p, 0, 0) = v.P;
        A(p, 0, 0, 0, 0) = v.A;
        if (!v.admissible && p < bad)
          bad = p;
      },
      Kokkos::Min<int>(firstBad));
  if (firstBad < n) {
    auto Fh = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), F);
    auto id = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), particles.id);
    std::ostringstream msg;
    msg << "material '" << name() << "' (" << Law::model()
        << ") is not defined at F = " << Fh(firstBad, 0, 0) << " (particle " << id(firstBad) << ")";
    throw NumericalError(msg.str());
  }
}

template <class Law>
void ElasticLaw1D<Law>::energyDensity(const Particles& particles, const Tensors& F, int index,
                                      Particles::Scalars& W) const {
  auto material = particles.material;
  auto props = particles.props;
  Kokkos::parallel_for(
      "impm::ElasticLaw1D::energy", RangePolicy<DefaultExecSpace>(0, particles.size()),
      KOKKOS_LAMBDA(const int p) {
        if (material(p) != index)
          return;
        double k[kMaxMaterialProps];
        for (int j = 0; j < kMaxMaterialProps; ++j)
          k[j] = props(p, j);
        W(p) = Law::evaluate(F(p, 0, 0), k).W;
      });
}

template <class Law>
double ElasticLaw1D<Law>::maxModulus(const Particles& particles, int index) const {
  return maxProperty(particles, index, 0);  // E, the small-strain modulus of every law here
}

template class ElasticLaw1D<LinearLaw>;
template class ElasticLaw1D<LinearFiniteLaw>;
template class ElasticLaw1D<CubicLaw>;
template class ElasticLaw1D<NeoHookeanLaw1D>;

}  // namespace impm
