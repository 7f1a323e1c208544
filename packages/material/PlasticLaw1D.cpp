#include "material/PlasticLaw1D.hpp"

#include "core/Parameters.hpp"
#include "material/MaterialPropertyFill.hpp"

namespace impm {

namespace {

// The deck's parameter, the field that holds its values, its bounds and its doc.
struct LawParameter {
  const char* parameter;
  const char* field;
  const char* defaultValue;
  Bounds bounds;
  const char* doc;
};

const LawParameter kParameters[] = {
    {"E", "E", "1.0", Bounds::positive(), "j2-1d: modulus E(x) > 0"},
    {"Yield Stress", "yield_stress", "1.0", Bounds::positive(),
     "j2-1d: yield stress sigma_y(x) > 0 in tension and compression"},
    {"Hardening Modulus", "hardening_modulus", "0", Bounds::nonNegative(),
     "j2-1d: linear isotropic hardening modulus H(x) >= 0 (0: perfect plasticity)"}};
constexpr int kParameterCount = 3;

// Variables in declaration order: the parameters, then eps_p and alpha.
constexpr int kPlasticStrain = kParameterCount, kAlpha = kParameterCount + 1;

}  // namespace

Teuchos::ParameterList J2Law1D::validParameters() {
  Teuchos::ParameterList valid;
  for (const auto& p : kParameters)
    declareFormula(valid, p.parameter, p.defaultValue, {"x"}, p.doc, p.bounds,
                   std::string(p.parameter) != "Hardening Modulus");
  return valid;
}

J2Law1D::J2Law1D(const std::string& name, const Teuchos::ParameterList& params)
    : Material<1>(name, params.get<double>("Density")) {
  for (const auto& p : kParameters)
    parameters_.emplace_back(formulaText(params, p.parameter), std::vector<std::string>{"x"});
}

std::vector<Material<1>::Variable> J2Law1D::variables() const {
  std::vector<Variable> out;
  for (const auto& p : kParameters) {
    FieldSpec spec;
    spec.name = p.field, spec.doc = p.doc, spec.checkpoint = false;  // recomputed from X_p
    out.push_back({spec, {}});
  }
  for (const char* name : {"plastic_strain", "equivalent_plastic_strain"}) {
    FieldSpec spec;
    spec.name = name;
    spec.doc = std::string(name) == "plastic_strain"
                   ? "j2-1d: plastic strain eps_p"
                   : "accumulated equivalent plastic strain alpha";
    spec.columns = defaultColumns<1>(name, spec.shape);
    spec.twoLevels = true;
    out.push_back({spec, {0.0}});
  }
  return out;
}

void J2Law1D::initialize(const Evaluation& at) const {
  for (int k = 0; k < kParameterCount; ++k)
    fillPropertyFromFormula<1>(at, at.variables[k], parameters_[k],
                               "Materials/" + name() + "/" + kParameters[k].parameter,
                               kParameters[k].bounds);
}

void J2Law1D::firstPiola(const Evaluation& at, Tensors& P, Tangents& A) const {
  const auto members = at.members;
  const auto F = at.F;
  const ParameterTables<1> k(at.variables, kParameterCount);
  const Table epsP = at.variables.at(kPlasticStrain), alpha = at.variables.at(kAlpha);
  const Table epsPTrial = at.trial.at(0), alphaTrial = at.trial.at(1);
  Kokkos::parallel_for(
      "impm::J2Law1D", RangePolicy<ExecutionSpace>(0, members.extent(0)),
      KOKKOS_LAMBDA(const int i) {
        const int p = members(i);
        double c[kMaxLawParameters];
        k.at(p, c);
        const auto v = j2Return1D(F(p, 0, 0), c[0], c[1], c[2], epsP(p, 0), alpha(p, 0));
        P(p, 0, 0) = v.P;
        A(p, 0, 0, 0, 0) = v.A;
        epsPTrial(p, 0) = v.plasticStrain;
        alphaTrial(p, 0) = v.alpha;
      });
}

void J2Law1D::energyDensity(const Evaluation& at, Scalars& W) const {
  const auto F = at.F;
  const ParameterTables<1> k(at.variables, kParameterCount);
  const Table epsP = at.variables.at(kPlasticStrain), alpha = at.variables.at(kAlpha);
  setForMembers<ExecutionSpace>(
      "impm::J2Law1D::energy", at.members, W, KOKKOS_LAMBDA(const int p) {
        double c[kMaxLawParameters];
        k.at(p, c);
        const double e = F(p, 0, 0) - 1.0 - epsP(p, 0), a = alpha(p, 0);
        return 0.5 * c[0] * e * e + 0.5 * c[2] * a * a;
      });
}

void J2Law1D::dissipationDensity(const Evaluation& at, Scalars& D) const {
  const Table yield = at.variables.at(1), alpha = at.variables.at(kAlpha);
  setForMembers<ExecutionSpace>(
      "impm::J2Law1D::dissipation", at.members, D,
      KOKKOS_LAMBDA(const int p) { return yield(p, 0) * alpha(p, 0); });
}

double J2Law1D::maxModulus(const Evaluation& at) const {
  return maxProperty<1>(at, at.variables[0]);
}

}  // namespace impm
