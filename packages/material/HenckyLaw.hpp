#pragma once
// Hencky's hyperelastic law (AMPLE's elastic law), 2-D (plane strain, F_zz = 1, so
// eps_zz = 0) and 3-D: with the logarithmic strain eps = ln V = (1/2) ln b, b = F F^T,
//   tau = lambda tr(eps) I + 2 mu eps  (Kirchhoff),  sigma = tau / J,  P = tau F^-T,
//   W = lambda/2 tr(eps)^2 + mu eps : eps.
// The tangent dP/dF is written out (henckyTangent), the derivative of the logarithm included
// (material/LogStrain); the unit tests check it against the dual-number derivative of this
// evaluation, to round-off, and against central differences.  (The plastic laws, whose
// return map has no such closed form, keep the dual numbers.)

#include "material/ElasticLaws.hpp"
#include "material/LogStrain.hpp"

namespace impm {

// A = dP/dF of Hencky's law, for P = tau F^-T with tau = lambda tr(eps) I + 2 mu eps,
// eps = (1/2) ln b, b = F F^T: along dF = e_c (x) e_d (c, d < Dim),
//   db = dF F^T + F dF^T,  d eps = (1/2) d ln b[db]  (LogarithmDerivative),
//   dP = d tau F^-T - tau F^-T dF^T F^-T,  whose second term is P_ad F^-1_bc.
template <int Dim>
KOKKOS_INLINE_FUNCTION void henckyTangent(const double F[3][3], const double Finv[3][3],
                                          const Sym<double>& b, const double P[Dim][Dim], Lame k,
                                          double A[Dim][Dim][Dim][Dim]) {
  const LogarithmDerivative<Dim> dlog(b);
  for (int c = 0; c < Dim; ++c)
    for (int d = 0; d < Dim; ++d) {
      // (dF F^T)_ij = delta_ic F_jd, plus its transpose.
      double db[3][3];
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
          db[i][j] = (i == c) * F[j][d] + (j == c) * F[i][d];
      const auto dtau = henckyStress(scaled(dlog.along(symmetricOf(db)), 0.5), k.mu, k.lambda);
      double dP[Dim][Dim];
      piolaOfKirchhoff<Dim>(dtau, Finv, dP);
      for (int a = 0; a < Dim; ++a)
        for (int e = 0; e < Dim; ++e)
          A[a][e][c][d] = dP[a][e] - P[a][d] * Finv[e][c];
    }
}

struct HenckyLaw {
  static const char* model() { return "hencky"; }
  static constexpr bool linear = false;
  static constexpr int maxDimension = 3;
  template <int Dim>
  KOKKOS_INLINE_FUNCTION static ElasticValue<Dim> evaluate(const double F[Dim][Dim], Lame k) {
    ElasticValue<Dim> v{};
    double F3[3][3], Finv[3][3];
    embed<Dim>(F, F3);
    const double J = determinantOf(F3);
    if (!(J > 0.0))
      return v;
    inverseOf(F3, J, Finv);
    const auto b = congruence(F3, identityOf<double>());
    const auto eps = scaled(isotropicFunction<Logarithm>(b), 0.5);
    const auto tau = henckyStress(eps, k.mu, k.lambda);
    piolaOfKirchhoff<Dim>(tau, Finv, v.P);
    henckyTangent<Dim>(F3, Finv, b, v.P, k, v.A);
    v.W = henckyEnergy(eps, k.mu, k.lambda);
    v.stressZZ = tau.zz / J;
    v.admissible = true;
    return v;
  }
};

}  // namespace impm
