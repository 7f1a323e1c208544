#pragma once
// Finite-strain von Mises (J2) plasticity in plane strain, on Hencky elasticity (Simo 1992;
// Eterovic & Bathe 1990; the formulation of AMPLE): F = F_e F_p, b_e = F_e F_e^T,
// tau = D : eps_e with eps_e = (1/2) ln b_e, yield f = q(tau) - (sigma_y + H alpha) <= 0
// with q = sqrt(3/2 s : s), s = dev tau, linear isotropic hardening (H = 0: perfect
// plasticity), associated flow integrated by the exponential map.  For isotropic elasticity
// the exponential map is a radial return on the logarithmic strain (doc/theory.md):
//   eps_tr = (1/2) ln(F C_p^-1 F^T),  tau_tr = D : eps_tr,
//   f_tr > 0:  d_alpha = f_tr / (3 mu + H),  s = (1 - 3 mu d_alpha / q_tr) s_tr,
//              eps_e = eps_tr - (3/2) d_alpha s_tr / q_tr,
//   C_p^-1 (n+1) = F^-1 exp(2 eps_e) F^-T.
// The state is C_p^-1 (symmetric 3 x 3: plane strain has an out-of-plane part) and the
// equivalent plastic strain alpha.  C_p^-1 rather than b_e: b_e at the start of the step
// would need F_n, C_p^-1 gives the trial b_e from the evaluation's F alone, under total and
// updated Lagrangian kinematics and after a restart alike (doc/design.md).  The tangent is
// the exact derivative of the return (dual numbers): the algorithmic tangent.
//
// Energy: W = lambda/2 tr(eps_e)^2 + mu eps_e : eps_e + H alpha^2 / 2 (stored), dissipation
// D = sigma_y alpha; the continuous balance tau : d = dW/dt + dD/dt holds exactly.

#include <Teuchos_ParameterList.hpp>

#include <string>

#include "material/HenckyLaw.hpp"

namespace impm {

struct J2Parameters {
  double mu, lambda, yield, hardening;
};

template <class T>
struct J2Update {
  PlaneSym<T> tau;            // Kirchhoff stress
  PlaneSym<T> elasticStrain;  // eps_e = (1/2) ln b_e
  PlaneSym<T> plasticMetric;  // C_p^-1 at the end of the step
  T alpha;                    // equivalent plastic strain
  bool plastic;
};

// The return map at F (in-plane block, J > 0) from the state (C_p^-1, alpha) at the start of
// the step.  With T = Dual4 every result carries its derivative with respect to F.
template <class T>
KOKKOS_INLINE_FUNCTION J2Update<T> j2Return(const T F[2][2], const PlaneSym<double>& CpInv,
                                            double alphaN, const J2Parameters& k) {
  J2Update<T> r;
  const auto epsTrial = scaled(isotropicFunction<Logarithm>(congruence(F, CpInv)), 0.5);
  const auto tauTrial = henckyStress(epsTrial, k.mu, k.lambda);
  const auto s = deviator(tauTrial);
  // The trial equivalent stress by value first: at s = 0 its derivative does not exist, and
  // elastic steps do not need it.
  const double qValue = Kokkos::Experimental::sqrt(1.5 * valueOf(squaredNorm(s)));
  const double f = qValue - (k.yield + k.hardening * alphaN);
  r.plastic = f > 0.0;
  if (!r.plastic) {
    r.tau = tauTrial, r.elasticStrain = epsTrial, r.alpha = T(alphaN);
  } else {
    const T q = sqrtOf(1.5 * squaredNorm(s));
    const T dAlpha = (q - (k.yield + k.hardening * alphaN)) / (3.0 * k.mu + k.hardening);
    const T p = trace(tauTrial) / 3.0;
    r.tau = plusIdentity(scaled(s, 1.0 - 3.0 * k.mu * dAlpha / q), p);
    const T flow = 1.5 * dAlpha / q;
    r.elasticStrain = {epsTrial.xx - flow * s.xx, epsTrial.yy - flow * s.yy,
                       epsTrial.xy - flow * s.xy, epsTrial.zz - flow * s.zz};
    r.alpha = alphaN + dAlpha;
  }
  const T J = F[0][0] * F[1][1] - F[0][1] * F[1][0];
  T Finv[2][2];
  inverseOf(F, J, Finv);
  r.plasticMetric = congruence(Finv, isotropicFunction<Exponential>(scaled(r.elasticStrain, 2.0)));
  return r;
}

// The Material: parameters E, nu, Yield Stress, Hardening Modulus; variables plastic_metric
// (C_p^-1, checkpointed, not written) and equivalent_plastic_strain (written).
class J2PlaneStrain : public Material<2> {
 public:
  static const char* model() { return "j2"; }
  static Teuchos::ParameterList validParameters();

  J2PlaneStrain(const std::string& name, const Teuchos::ParameterList& params);
  std::vector<Variable> variables() const override;
  void firstPiola(const Evaluation& at, Tensors& P, Tangents& A) const override;
  void energyDensity(const Evaluation& at, Scalars& W) const override;
  void dissipationDensity(const Evaluation& at, Scalars& D) const override;
  void outOfPlaneStress(const Evaluation& at, Scalars& stressZZ) const override;
  double maxModulus(const Evaluation& /*at*/) const override {
    return parameters_.lambda + 2.0 * parameters_.mu;
  }

 private:
  J2Parameters parameters_;
};

}  // namespace impm
