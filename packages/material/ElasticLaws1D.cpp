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

Bounds boundsOf(const std::string& parameter) {
  return parameter == "E" ? Bounds::positive() : Bounds::any();
}

}  // namespace

template <class Law>
Teuchos::ParameterList ElasticLaw1D<Law>::validParameters() {
  Teuchos::ParameterList valid;
  for (const auto& p : Law::parameters())
    declareFormula(valid, p, "1.0", {"x"}, describe(p), boundsOf(p), true);
  return valid;
}

template <class Law>
ElasticLaw1D<Law>::ElasticLaw1D(const std::string& name, const Teuchos::ParameterList& params)
    : Material<1>(name, params.get<double>("Density")) {
  for (const auto& p : Law::parameters())
    parameters_.emplace_back(formulaText(params, p), std::vector<std::string>{"x"});
}

template <class Law>
std::vector<Material<1>::Variable> ElasticLaw1D<Law>::variables() const {
  std::vector<Variable> out;
  for (const auto& p : Law::parameters()) {
    FieldSpec spec;
    spec.name = p, spec.doc = describe(p), spec.checkpoint = false;  // recomputed from X_p
    out.push_back({spec, {}});
  }
  return out;
}

template <class Law>
void ElasticLaw1D<Law>::initialize(const Evaluation& at) const {
  const auto names = Law::parameters();
  for (std::size_t k = 0; k < names.size(); ++k)
    fillPropertyFromFormula<1>(at, at.variables[k], parameters_[k],
                               "Materials/" + name() + "/" + names[k], boundsOf(names[k]));
}

template <class Law>
void ElasticLaw1D<Law>::firstPiola(const Evaluation& at, Tensors& P, Tangents& A) const {
  const auto members = at.members;
  const auto F = at.F;
  const ParameterTables<1> parameters(at.variables);
  const int n = static_cast<int>(members.extent(0));
  int firstBad = n;
  Kokkos::parallel_reduce(
      "impm::ElasticLaw1D", RangePolicy<ExecutionSpace>(0, n),
      KOKKOS_LAMBDA(const int i, int& bad) {
        const int p = members(i);
        double k[kMaxLawParameters];
        parameters.at(p, k);
        const LawValue v = Law::evaluate(F(p, 0, 0), k);
        P(p, 0, 0) = v.P;
        A(p, 0, 0, 0, 0) = v.A;
        if (!v.admissible && i < bad)
          bad = i;
      },
      Kokkos::Min<int>(firstBad));
  if (firstBad < n) {
    auto Fh = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), F);
    auto id = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), at.particles.id);
    auto m = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), members);
    std::ostringstream msg;
    msg << "material '" << name() << "' (" << Law::model()
        << ") is not defined at F = " << Fh(m(firstBad), 0, 0) << " (particle " << id(m(firstBad))
        << ")";
    throw NumericalError(msg.str());
  }
}

template <class Law>
void ElasticLaw1D<Law>::energyDensity(const Evaluation& at, Scalars& W) const {
  const auto F = at.F;
  const ParameterTables<1> parameters(at.variables);
  setForMembers<ExecutionSpace>(
      "impm::ElasticLaw1D::energy", at.members, W, KOKKOS_LAMBDA(const int p) {
        double k[kMaxLawParameters];
        parameters.at(p, k);
        return Law::evaluate(F(p, 0, 0), k).W;
      });
}

template <class Law>
double ElasticLaw1D<Law>::maxModulus(const Evaluation& at) const {
  return maxProperty<1>(at, at.variables[0]);  // E, the small-strain modulus of every law here
}

template class ElasticLaw1D<LinearLaw>;
template class ElasticLaw1D<LinearFiniteLaw>;
template class ElasticLaw1D<CubicLaw>;
template class ElasticLaw1D<NeoHookeanLaw1D>;
template class ElasticLaw1D<HenckyLaw1D>;

}  // namespace impm
