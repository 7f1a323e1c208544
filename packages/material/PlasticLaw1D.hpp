#pragma once
// j2-1d: the primer's bar law sigma = xi(eps, history) with a return map, in uniaxial stress
// and small strain (eps = F - 1, P = sigma, as for the 1-D elastic laws):
//   eps = eps_e + eps_p,  P = E (eps - eps_p),  f = |P| - (sigma_y + H alpha) <= 0,
//   trial P_tr = E (eps - eps_p,n);  f_tr > 0:  d = f_tr / (E + H),
//   P = P_tr - E d sign(P_tr),  eps_p = eps_p,n + d sign(P_tr),  alpha = alpha_n + d,
//   A = dP/dF = E H / (E + H) (plastic), E (elastic)  -- the exact, consistent tangent.
// The parameters E(x), sigma_y(x) > 0, H(x) >= 0 are formulas of the reference position; the
// state is the plastic strain eps_p and the equivalent plastic strain alpha.  Energy
// W = E (eps - eps_p)^2 / 2 + H alpha^2 / 2 (stored), dissipation D = sigma_y alpha.
// The 2-D law of the same name (j2) is its finite-strain counterpart; for strains of the
// order of sigma_y / E the two agree to O(eps^2).

#include <Teuchos_ParameterList.hpp>

#include <string>
#include <vector>

#include "core/Formula.hpp"
#include "material/Material.hpp"

namespace impm {

struct PlasticValue1D {
  double P, A, plasticStrain, alpha;
};

KOKKOS_INLINE_FUNCTION PlasticValue1D j2Return1D(double F, double E, double yield, double H,
                                                 double plasticStrainN, double alphaN) {
  const double trial = E * (F - 1.0 - plasticStrainN);
  const double f = Kokkos::Experimental::fabs(trial) - (yield + H * alphaN);
  if (!(f > 0.0))
    return {trial, E, plasticStrainN, alphaN};
  const double d = f / (E + H), sign = trial > 0.0 ? 1.0 : -1.0;
  return {trial - E * d * sign, E * H / (E + H), plasticStrainN + d * sign, alphaN + d};
}

class J2Law1D : public Material<1> {
 public:
  static const char* model() { return "j2-1d"; }
  static Teuchos::ParameterList validParameters();

  J2Law1D(const std::string& name, const Teuchos::ParameterList& params);
  std::vector<Variable> variables() const override;
  void initialize(const Evaluation& at) const override;
  void firstPiola(const Evaluation& at, Tensors& P, Tangents& A) const override;
  void energyDensity(const Evaluation& at, Scalars& W) const override;
  void dissipationDensity(const Evaluation& at, Scalars& D) const override;
  bool dissipates() const override { return true; }
  double maxModulus(const Evaluation& at) const override;

 private:
  std::vector<Formula> parameters_;  // E, sigma_y, H
};

}  // namespace impm
