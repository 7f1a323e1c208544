#pragma once
// Hencky's hyperelastic law in plane strain (AMPLE's elastic law): with the logarithmic
// strain eps = ln V = (1/2) ln b, b = F F^T (F_zz = 1, so eps_zz = 0),
//   tau = lambda tr(eps) I + 2 mu eps  (Kirchhoff),  sigma = tau / J,  P = tau F^-T,
//   W = lambda/2 tr(eps)^2 + mu eps : eps.
// The tangent dP/dF is written out (henckyTangent), the derivative of the logarithm included
// (material/LogStrain); the unit tests check it against the dual-number derivative of this
// evaluation, to round-off, and against central differences.  (The plastic laws, whose
// return map has no such closed form, keep the dual numbers.)

#include "material/LogStrain.hpp"
#include "material/PlaneStrainLaws.hpp"

namespace impm {

// A = dP/dF of Hencky's law, for P = tau F^-T with tau = lambda tr(eps) I + 2 mu eps,
// eps = (1/2) ln b, b = F F^T: along dF = e_c (x) e_d,
//   db = dF F^T + F dF^T,  d eps = (1/2) d ln b[db]  (LogarithmDerivative),
//   dP = d tau F^-T - tau F^-T dF^T F^-T,  whose second term is P_ad F^-1_bc.
KOKKOS_INLINE_FUNCTION void henckyTangent(const double F[2][2], const double Finv[2][2],
                                          const PlaneSym<double>& b, const double P[2][2], Lame k,
                                          double A[2][2][2][2]) {
  const LogarithmDerivative dlog(b);
  for (int c = 0; c < 2; ++c)
    for (int d = 0; d < 2; ++d) {
      // (dF F^T)_ij = delta_ic F_jd, plus its transpose.
      const PlaneSym<double> db{2.0 * (c == 0) * F[0][d], 2.0 * (c == 1) * F[1][d],
                                (c == 0) * F[1][d] + (c == 1) * F[0][d], 0.0};
      const auto dtau = henckyStress(scaled(dlog.along(db), 0.5), k.mu, k.lambda);
      const double t[2][2] = {{dtau.xx, dtau.xy}, {dtau.xy, dtau.yy}};
      for (int a = 0; a < 2; ++a)
        for (int e = 0; e < 2; ++e)
          A[a][e][c][d] = t[a][0] * Finv[e][0] + t[a][1] * Finv[e][1] - P[a][d] * Finv[e][c];
    }
}

struct HenckyLaw {
  static const char* model() { return "hencky"; }
  static constexpr bool linear = false;
  KOKKOS_INLINE_FUNCTION static PlaneStrainValue evaluate(const double F[2][2], Lame k) {
    PlaneStrainValue v{};
    const double J = determinant<2>(F);
    if (!(J > 0.0))
      return v;
    double Finv[2][2];
    inverseOf(F, J, Finv);
    const PlaneSym<double> identity{1.0, 1.0, 0.0, 1.0};
    const auto b = congruence(F, identity);
    const auto eps = scaled(isotropicFunction<Logarithm>(b), 0.5);
    const auto tau = henckyStress(eps, k.mu, k.lambda);
    piolaOfKirchhoff(tau, Finv, v.P);
    henckyTangent(F, Finv, b, v.P, k, v.A);
    v.W = henckyEnergy(eps, k.mu, k.lambda);
    v.stressZZ = tau.zz / J;
    v.admissible = true;
    return v;
  }
};

}  // namespace impm
