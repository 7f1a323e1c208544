#pragma once
// j2: von Mises plasticity with linear isotropic hardening on Hencky elasticity (Simo 1992;
// Eterovic & Bathe 1990; the law of AMPLE).  Yield f = q - (sigma_y + H alpha) <= 0,
// q = sqrt(3/2 s : s), s = dev tau; associated flow; for isotropic elasticity the
// exponential map is a radial return on the logarithmic strain:
//   f_tr > 0:  d_alpha = f_tr / (3 mu + H),  s = (1 - 3 mu d_alpha / q_tr) s_tr,
//              eps_e = eps_tr - (3/2) d_alpha s_tr / q_tr.
// Stored energy beyond Hencky's: H alpha^2 / 2; dissipation sigma_y alpha.

#include "core/Parameters.hpp"
#include "material/FiniteStrainPlasticity.hpp"

namespace impm {

struct J2Law {
  struct Parameters {
    double mu, lambda, yield, hardening;
  };

  static const char* model() { return "j2"; }
  static void declare(Teuchos::ParameterList& valid) {
    declareDouble(valid, "Yield Stress", 1.0, "j2: initial yield stress sigma_y > 0 (von Mises)",
                  Bounds::positive(), true);
    declareDouble(valid, "Hardening Modulus", 0.0,
                  "j2: linear isotropic hardening modulus H >= 0 (0: perfect plasticity)",
                  Bounds::nonNegative());
  }
  static Parameters read(const Teuchos::ParameterList& params, Lame lame,
                         const std::string& /*path*/) {
    return {lame.mu, lame.lambda, params.get<double>("Yield Stress"),
            params.get<double>("Hardening Modulus")};
  }

  template <class T>
  KOKKOS_INLINE_FUNCTION static PlasticUpdate<T> returnMap(const T F[3][3], const PlasticState& n,
                                                           const Parameters& k) {
    const Trial<T> t = trialOf(F, n, k.mu, k.lambda);
    const auto& s = t.s;
    // The trial equivalent stress by value first: at s = 0 its derivative does not exist,
    // and elastic steps do not need it.
    const double qValue = Kokkos::Experimental::sqrt(1.5 * valueOf(squaredNorm(s)));
    if (!(qValue - (k.yield + k.hardening * n.alpha) > 0.0))
      return elasticUpdate(t, n);
    PlasticUpdate<T> r;
    const T q = sqrtOf(T(1.5 * squaredNorm(s)));
    const T dAlpha = (q - (k.yield + k.hardening * n.alpha)) / (3.0 * k.mu + k.hardening);
    r.tau = plusIdentity(scaled(s, 1.0 - 3.0 * k.mu * dAlpha / q), trace(t.tau) / 3.0);
    r.elasticStrain = difference(t.eps, scaled(s, 1.5 * dAlpha / q));
    r.alpha = n.alpha + dAlpha;
    r.dissipation = k.yield * r.alpha;
    return r;
  }

  KOKKOS_INLINE_FUNCTION static double hardeningEnergy(double alpha, const Parameters& k) {
    return 0.5 * k.hardening * alpha * alpha;
  }
};

}  // namespace impm
