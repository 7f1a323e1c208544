#pragma once
// drucker-prager: a pressure-dependent cone on Hencky elasticity and the exponential map (de
// Souza Neto, Peric & Owen 2008, section 8.3), perfectly plastic.  With p = tr(tau)/3 and
// sqrt(J2) = sqrt(s : s / 2), the yield function and the flow potential are
//   f = sqrt(J2) + eta p - xi c,   g = sqrt(J2) + etaBar p,
// fitted to Mohr-Coulomb's friction angle phi, dilation angle psi and cohesion c:
//   plane strain  eta = 3 tan(phi) / sqrt(9 + 12 tan^2 phi),  xi = 3 / sqrt(9 + 12 tan^2 phi)
//                 (the limit loads of plane-strain Mohr-Coulomb; the default),
//   outer cone    eta = 6 sin(phi) / (sqrt(3) (3 - sin phi)),  xi = 6 cos(phi) / (sqrt(3) (3 - sin
//   phi)), inner cone    the same with 3 + sin phi,
// and etaBar the same function of psi.  psi = phi is associated flow; psi < phi makes the
// tangent non-symmetric (the default GMRES handles it; CG would not).  The return on the
// logarithmic strain, with K the bulk and G the shear modulus:
//   cone   d_gamma = f_tr / (G + K eta etaBar),  s = (1 - G d_gamma / sqrt(J2_tr)) s_tr,
//          p = p_tr - K etaBar d_gamma,  valid while sqrt(J2_tr) >= G d_gamma;
//   apex   s = 0, p = xi c / eta (the cone's vertex).
// eps_e = s / (2G) + p / (3K) I; alpha accumulates sqrt(2/3 d:d) of the plastic strain
// increments d = eps_tr - eps_e, the dissipation tau : d.

#include <cmath>
#include <sstream>

#include "core/Errors.hpp"
#include "core/Parameters.hpp"
#include "material/FiniteStrainPlasticity.hpp"

namespace impm {

struct DruckerPragerLaw {
  struct Parameters {
    double mu, lambda, cohesion, eta, xi, etaBar;
  };

  static const char* model() { return "drucker-prager"; }
  static void declare(Teuchos::ParameterList& valid) {
    declareDouble(valid, "Cohesion", 0.0, "drucker-prager: cohesion c >= 0", Bounds::nonNegative(),
                  true);
    declareDouble(valid, "Friction Angle", 30.0,
                  "drucker-prager: friction angle phi in degrees, 0 <= phi < 90",
                  Bounds{0.0, 90.0, false, true}, true);
    declareDouble(valid, "Dilation Angle", 0.0,
                  "drucker-prager: dilation angle psi in degrees, 0 <= psi <= phi (psi = phi: "
                  "associated flow)",
                  Bounds{0.0, 90.0, false, true});
    declareChoice(valid, "Cone", "plane strain", {"plane strain", "outer", "inner"},
                  "drucker-prager: the fit to Mohr-Coulomb: plane strain (matches its "
                  "plane-strain limit loads), outer (compressive meridian) or inner (tensile)");
  }

  // (eta or etaBar, xi) of an angle in degrees for the cone fit.
  static std::pair<double, double> fit(double degrees, const std::string& cone) {
    const double a = degrees * M_PI / 180.0, t = std::tan(a), s = std::sin(a);
    if (cone == "plane strain") {
      const double d = std::sqrt(9.0 + 12.0 * t * t);
      return {3.0 * t / d, 3.0 / d};
    }
    const double d = std::sqrt(3.0) * (cone == "outer" ? 3.0 - s : 3.0 + s);
    return {6.0 * s / d, 6.0 * std::cos(a) / d};
  }

  static Parameters read(const Teuchos::ParameterList& params, Lame lame, const std::string& path) {
    const double phi = params.get<double>("Friction Angle"),
                 psi = params.get<double>("Dilation Angle"), c = params.get<double>("Cohesion");
    if (psi > phi) {
      std::ostringstream message;
      message << "the dilation angle " << psi << " exceeds the friction angle " << phi;
      throw InputError(path + "Dilation Angle", message.str());
    }
    if (phi == 0.0 && c == 0.0)
      throw InputError(path + "Cohesion", "with a zero friction angle the cohesion must be > 0");
    const auto& cone = params.get<std::string>("Cone");
    const auto [eta, xi] = fit(phi, cone);
    return {lame.mu, lame.lambda, c, eta, xi, fit(psi, cone).first};
  }

  template <class T>
  KOKKOS_INLINE_FUNCTION static PlasticUpdate<T> returnMap(const T F[3][3], const PlasticState& n,
                                                           const Parameters& k) {
    const Trial<T> t = trialOf(F, n, k.mu, k.lambda);
    const auto& s = t.s;
    const T p = trace(t.tau) / 3.0;
    const double rootJ2 = Kokkos::Experimental::sqrt(0.5 * valueOf(squaredNorm(s)));
    const double f = rootJ2 + k.eta * valueOf(p) - k.xi * k.cohesion;
    if (!(f > 0.0))
      return elasticUpdate(t, n);
    PlasticUpdate<T> r;
    const double G = k.mu, K = k.lambda + 2.0 * k.mu / 3.0;
    const double gammaValue = f / (G + K * k.eta * k.etaBar);
    if (rootJ2 - G * gammaValue >= 0.0) {  // the cone
      const T root = sqrtOf(T(0.5 * squaredNorm(s)));
      const T dGamma = (root + k.eta * p - k.xi * k.cohesion) / (G + K * k.eta * k.etaBar);
      r.tau = plusIdentity(scaled(s, 1.0 - G * dGamma / root), p - K * k.etaBar * dGamma);
    } else {  // the apex
      const T apex(k.xi * k.cohesion / k.eta);
      r.tau = {apex, apex, apex, T(0.0), T(0.0), T(0.0)};
    }
    const T pNew = trace(r.tau) / 3.0;
    r.elasticStrain = plusIdentity(scaled(deviator(r.tau), 0.5 / G), pNew / (3.0 * K));
    const auto plastic = difference(t.eps, r.elasticStrain);
    r.alpha = T(n.alpha + equivalentIncrement(plastic));
    r.dissipation = n.dissipation + contraction(r.tau, plastic);
    return r;
  }

  KOKKOS_INLINE_FUNCTION static double hardeningEnergy(double /*alpha*/, const Parameters&) {
    return 0.0;
  }
};

}  // namespace impm
