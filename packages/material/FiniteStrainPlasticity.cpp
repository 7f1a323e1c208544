#include "material/FiniteStrainPlasticity.hpp"

#include "core/Parameters.hpp"
#include "material/DruckerPragerLaw.hpp"
#include "material/J2Law.hpp"

namespace impm {

namespace {

// The state tables: C_p^-1 (components xx, yy, zz, xy, yz, xz), alpha, dissipation.
struct StateTables {
  Material<2>::Table metric, alpha, dissipation;

  KOKKOS_INLINE_FUNCTION PlasticState at(int p) const {
    return {
        {metric(p, 0), metric(p, 1), metric(p, 3), metric(p, 2)}, alpha(p, 0), dissipation(p, 0)};
  }
  template <class T>
  KOKKOS_INLINE_FUNCTION void store(int p, const PlaneSym<T>& m, const T& a, const T& d) const {
    metric(p, 0) = valueOf(m.xx), metric(p, 1) = valueOf(m.yy), metric(p, 2) = valueOf(m.zz);
    metric(p, 3) = valueOf(m.xy), metric(p, 4) = metric(p, 5) = 0.0;
    alpha(p, 0) = valueOf(a), dissipation(p, 0) = valueOf(d);
  }
};

StateTables committed(const Material<2>::Evaluation& at) {
  return {at.variables.at(0), at.variables.at(1), at.variables.at(2)};
}

// The committed elastic strain (1/2) ln(F C_p^-1 F^T) at particle p.
KOKKOS_INLINE_FUNCTION PlaneSym<double> elasticStrain(const Material<2>::Tensors& F,
                                                      const StateTables& state, int p) {
  double f[2][2];
  load(F, p, f);
  return trialElasticStrain(f, state.at(p).metric);
}

FieldSpec stateField(const std::string& name, const std::string& doc, FieldShape shape,
                     bool written) {
  FieldSpec spec;
  spec.name = name, spec.doc = doc, spec.shape = shape, spec.twoLevels = true;
  if (written)
    spec.columns = defaultColumns<2>(name, shape);
  return spec;
}

}  // namespace

template <class Law>
Teuchos::ParameterList FiniteStrainPlasticity<Law>::validParameters() {
  Teuchos::ParameterList valid;
  declareElasticConstants(valid);
  Law::declare(valid);
  return valid;
}

template <class Law>
FiniteStrainPlasticity<Law>::FiniteStrainPlasticity(const std::string& name,
                                                    const Teuchos::ParameterList& params)
    : Material<2>(name, params.get<double>("Density")),
      parameters_(Law::read(params, lameOf(params), "Materials/" + name + "/")) {}

template <class Law>
std::vector<Material<2>::Variable> FiniteStrainPlasticity<Law>::variables() const {
  return {{stateField("plastic_metric", "inverse plastic right Cauchy-Green tensor C_p^-1",
                      FieldShape::symmetric3x3, false),
           {1.0, 1.0, 1.0, 0.0, 0.0, 0.0}},
          {stateField("equivalent_plastic_strain", "accumulated equivalent plastic strain alpha",
                      FieldShape::scalar, true),
           {0.0}},
          {stateField("plastic_dissipation", "energy dissipated per unit reference volume",
                      FieldShape::scalar, true),
           {0.0}}};
}

template <class Law>
void FiniteStrainPlasticity<Law>::firstPiola(const Evaluation& at, Tensors& P, Tangents& A) const {
  const auto members = at.members;
  const auto F = at.F;
  const StateTables n = committed(at), trial{at.trial.at(0), at.trial.at(1), at.trial.at(2)};
  const Parameters k = parameters_;
  const int count = static_cast<int>(members.extent(0));
  int firstBad = count;
  Kokkos::parallel_reduce(
      "impm::FiniteStrainPlasticity", RangePolicy<ExecutionSpace>(0, count),
      KOKKOS_LAMBDA(const int i, int& bad) {
        const int p = members(i);
        double f[2][2];
        load(F, p, f);
        if (!(determinant<2>(f) > 0.0)) {
          bad = i < bad ? i : bad;
          return;
        }
        Dual4 Fd[2][2], Pd[2][2], Finv[2][2];
        seedDeformation(f, Fd);
        const auto r = Law::returnMap(Fd, n.at(p), k);
        inverseOf(Fd, Fd[0][0] * Fd[1][1] - Fd[0][1] * Fd[1][0], Finv);
        piolaOfKirchhoff(r.tau, Finv, Pd);
        double Pv[2][2], Av[2][2][2][2];
        unpackPiola(Pd, Pv, Av);
        store(P, A, p, Pv, Av);
        trial.store(
            p,
            plasticMetricOf(f, PlaneSym<double>{r.elasticStrain.xx.v, r.elasticStrain.yy.v,
                                                r.elasticStrain.xy.v, r.elasticStrain.zz.v}),
            r.alpha.v, r.dissipation.v);
      },
      Kokkos::Min<int>(firstBad));
  throwIfInverted(*this, model(), at, firstBad);
}

template <class Law>
void FiniteStrainPlasticity<Law>::energyDensity(const Evaluation& at, Scalars& W) const {
  const auto F = at.F;
  const StateTables n = committed(at);
  const Parameters k = parameters_;
  setForMembers<ExecutionSpace>(
      "impm::FiniteStrainPlasticity::energy", at.members, W, KOKKOS_LAMBDA(const int p) {
        return henckyEnergy(elasticStrain(F, n, p), k.mu, k.lambda) +
               Law::hardeningEnergy(n.alpha(p, 0), k);
      });
}

template <class Law>
void FiniteStrainPlasticity<Law>::dissipationDensity(const Evaluation& at, Scalars& D) const {
  const StateTables n = committed(at);
  setForMembers<ExecutionSpace>(
      "impm::FiniteStrainPlasticity::dissipation", at.members, D,
      KOKKOS_LAMBDA(const int p) { return n.dissipation(p, 0); });
}

template <class Law>
void FiniteStrainPlasticity<Law>::outOfPlaneStress(const Evaluation& at, Scalars& stressZZ) const {
  const auto F = at.F;
  const StateTables n = committed(at);
  const Parameters k = parameters_;
  setForMembers<ExecutionSpace>(
      "impm::FiniteStrainPlasticity::stressZZ", at.members, stressZZ, KOKKOS_LAMBDA(const int p) {
        const double tauZZ = henckyStress(elasticStrain(F, n, p), k.mu, k.lambda).zz;
        return tauZZ / determinant<2>(F, p);
      });
}

template class FiniteStrainPlasticity<J2Law>;
template class FiniteStrainPlasticity<DruckerPragerLaw>;

}  // namespace impm
