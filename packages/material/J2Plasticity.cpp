#include "material/J2Plasticity.hpp"

#include "core/Parameters.hpp"

namespace impm {

namespace {

// The state of particle p: C_p^-1 (components xx, yy, zz, xy, yz, xz) and alpha.
struct J2State {
  Material<2>::Table metric, alpha;

  KOKKOS_INLINE_FUNCTION PlaneSym<double> metricAt(int p) const {
    return {metric(p, 0), metric(p, 1), metric(p, 3), metric(p, 2)};
  }
  KOKKOS_INLINE_FUNCTION void store(int p, const PlaneSym<double>& m, double a) const {
    metric(p, 0) = m.xx, metric(p, 1) = m.yy, metric(p, 2) = m.zz, metric(p, 3) = m.xy;
    metric(p, 4) = metric(p, 5) = 0.0;
    alpha(p, 0) = a;
  }
};

J2State committed(const Material<2>::Evaluation& at) {
  return {at.variables.at(0), at.variables.at(1)};
}

// The committed elastic strain (1/2) ln(F C_p^-1 F^T) at particle p.
KOKKOS_INLINE_FUNCTION PlaneSym<double> elasticStrain(const Material<2>::Tensors& F,
                                                      const J2State& state, int p) {
  double f[2][2];
  load(F, p, f);
  return scaled(isotropicFunction<Logarithm>(congruence(f, state.metricAt(p))), 0.5);
}

}  // namespace

Teuchos::ParameterList J2PlaneStrain::validParameters() {
  Teuchos::ParameterList valid;
  declareElasticConstants(valid);
  declareDouble(valid, "Yield Stress", 1.0, "j2: initial yield stress sigma_y > 0 (von Mises)",
                Bounds::positive(), true);
  declareDouble(valid, "Hardening Modulus", 0.0,
                "j2: linear isotropic hardening modulus H >= 0 (0: perfect plasticity)",
                Bounds::nonNegative());
  return valid;
}

J2PlaneStrain::J2PlaneStrain(const std::string& name, const Teuchos::ParameterList& params)
    : Material<2>(name, params.get<double>("Density")) {
  const Lame lame = lameOf(params);
  parameters_ = {lame.mu, lame.lambda, params.get<double>("Yield Stress"),
                 params.get<double>("Hardening Modulus")};
}

std::vector<Material<2>::Variable> J2PlaneStrain::variables() const {
  FieldSpec metric;
  metric.name = "plastic_metric";
  metric.shape = FieldShape::symmetric3x3;
  metric.doc = "j2: inverse plastic right Cauchy-Green tensor C_p^-1 = F_p^-1 F_p^-T";
  metric.twoLevels = true;
  FieldSpec alpha;
  alpha.name = "equivalent_plastic_strain";
  alpha.doc = "accumulated equivalent plastic strain alpha";
  alpha.columns = defaultColumns<2>(alpha.name, alpha.shape);
  alpha.twoLevels = true;
  return {{metric, {1.0, 1.0, 1.0, 0.0, 0.0, 0.0}}, {alpha, {0.0}}};
}

void J2PlaneStrain::firstPiola(const Evaluation& at, Tensors& P, Tangents& A) const {
  const auto members = at.members;
  const auto F = at.F;
  const J2State n = committed(at), trial{at.trial.at(0), at.trial.at(1)};
  const J2Parameters k = parameters_;
  const int count = static_cast<int>(members.extent(0));
  int firstBad = count;
  Kokkos::parallel_reduce(
      "impm::J2PlaneStrain", RangePolicy<ExecutionSpace>(0, count),
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
        const auto r = j2Return(Fd, n.metricAt(p), n.alpha(p, 0), k);
        inverseOf(Fd, Fd[0][0] * Fd[1][1] - Fd[0][1] * Fd[1][0], Finv);
        piolaOfKirchhoff(r.tau, Finv, Pd);
        double Pv[2][2], Av[2][2][2][2];
        unpackPiola(Pd, Pv, Av);
        store(P, A, p, Pv, Av);
        const PlaneSym<double> metric{r.plasticMetric.xx.v, r.plasticMetric.yy.v,
                                      r.plasticMetric.xy.v, r.plasticMetric.zz.v};
        trial.store(p, metric, r.alpha.v);
      },
      Kokkos::Min<int>(firstBad));
  throwIfInverted(*this, model(), at, firstBad);
}

void J2PlaneStrain::energyDensity(const Evaluation& at, Scalars& W) const {
  const auto members = at.members;
  const auto F = at.F;
  const J2State n = committed(at);
  const J2Parameters k = parameters_;
  Kokkos::parallel_for(
      "impm::J2PlaneStrain::energy", RangePolicy<ExecutionSpace>(0, members.extent(0)),
      KOKKOS_LAMBDA(const int i) {
        const int p = members(i);
        const double a = n.alpha(p, 0);
        W(p) = henckyEnergy(elasticStrain(F, n, p), k.mu, k.lambda) + 0.5 * k.hardening * a * a;
      });
}

void J2PlaneStrain::dissipationDensity(const Evaluation& at, Scalars& D) const {
  const auto members = at.members;
  const J2State n = committed(at);
  const double yield = parameters_.yield;
  Kokkos::parallel_for(
      "impm::J2PlaneStrain::dissipation", RangePolicy<ExecutionSpace>(0, members.extent(0)),
      KOKKOS_LAMBDA(const int i) {
        const int p = members(i);
        D(p) = yield * n.alpha(p, 0);
      });
}

void J2PlaneStrain::outOfPlaneStress(const Evaluation& at, Scalars& stressZZ) const {
  const auto members = at.members;
  const auto F = at.F;
  const J2State n = committed(at);
  const J2Parameters k = parameters_;
  Kokkos::parallel_for(
      "impm::J2PlaneStrain::stressZZ", RangePolicy<ExecutionSpace>(0, members.extent(0)),
      KOKKOS_LAMBDA(const int i) {
        const int p = members(i);
        const double tauZZ = henckyStress(elasticStrain(F, n, p), k.mu, k.lambda).zz;
        stressZZ(p) = tauZZ / determinant<2>(F, p);
      });
}

}  // namespace impm
