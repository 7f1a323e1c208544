#pragma once
// Hencky's hyperelastic law in plane strain (AMPLE's elastic law): with the logarithmic
// strain eps = ln V = (1/2) ln b, b = F F^T (F_zz = 1, so eps_zz = 0),
//   tau = lambda tr(eps) I + 2 mu eps  (Kirchhoff),  sigma = tau / J,  P = tau F^-T,
//   W = lambda/2 tr(eps)^2 + mu eps : eps.
// The tangent dP/dF is the exact derivative of this evaluation (dual numbers), so it is
// consistent by construction and checked against central differences in the unit tests.

#include "core/Dual.hpp"
#include "material/LogStrain.hpp"
#include "material/PlaneStrainLaws.hpp"

namespace impm {

using Dual4 = Dual<4>;  // derivatives along the four in-plane components of F, (a, b) -> 2a + b

// F as dual numbers: each component its own direction.
KOKKOS_INLINE_FUNCTION void seedDeformation(const double F[2][2], Dual4 Fd[2][2]) {
  for (int a = 0; a < 2; ++a)
    for (int b = 0; b < 2; ++b)
      Fd[a][b] = Dual4::variable(F[a][b], 2 * a + b);
}

// P and A = dP/dF from a dual first Piola stress.
KOKKOS_INLINE_FUNCTION void unpackPiola(const Dual4 P[2][2], double Pv[2][2],
                                        double A[2][2][2][2]) {
  for (int a = 0; a < 2; ++a)
    for (int b = 0; b < 2; ++b) {
      Pv[a][b] = P[a][b].v;
      for (int c = 0; c < 2; ++c)
        for (int d = 0; d < 2; ++d)
          A[a][b][c][d] = P[a][b].d[2 * c + d];
    }
}

struct HenckyLaw {
  static const char* model() { return "hencky"; }
  static constexpr bool linear = false;
  KOKKOS_INLINE_FUNCTION static PlaneStrainValue evaluate(const double F[2][2], Lame k) {
    PlaneStrainValue v{};
    const double Jv = determinant<2>(F);
    if (!(Jv > 0.0))
      return v;
    Dual4 Fd[2][2], Finv[2][2], P[2][2];
    seedDeformation(F, Fd);
    const Dual4 J = Fd[0][0] * Fd[1][1] - Fd[0][1] * Fd[1][0];
    inverseOf(Fd, J, Finv);
    const PlaneSym<double> identity{1.0, 1.0, 0.0, 1.0};
    const auto eps = scaled(isotropicFunction<Logarithm>(congruence(Fd, identity)), 0.5);
    const auto tau = henckyStress(eps, k.mu, k.lambda);
    piolaOfKirchhoff(tau, Finv, P);
    unpackPiola(P, v.P, v.A);
    v.W = henckyEnergy(eps, k.mu, k.lambda).v;
    v.stressZZ = tau.zz.v / Jv;
    v.admissible = true;
    return v;
  }
};

}  // namespace impm
