#pragma once
// 2-D elastic laws in plane strain (F_zz = 1), as device functors of the 2 x 2 in-plane
// deformation gradient; PlaneStrainLaw<Law> runs them through the Material interface.
// With mu = E / (2 (1 + nu)), lambda = E nu / ((1 + nu)(1 - 2 nu)):
//
//   linear-elastic  P = lambda tr(eps) I + 2 mu eps,  eps = sym(F) - I
//                   (small-strain Hooke's law read as a first Piola stress: linear in F, so
//                   a total-Lagrangian step is one linear solve; not objective under large
//                   rotations, which is what "linear" costs)
//   neo-hookean     P = mu (F - F^-T) + lambda ln J F^-T,  J = det F
//                   (sigma = (mu / J)(b - I) + (lambda / J) ln J I; needs J > 0)
//
// Tangents A_abcd = dP_ab / dF_cd in closed form; with d(F^-1)_ba / dF_cd = -F^-1_bc F^-1_da,
//   neo-hookean  A = mu d_ac d_bd + (mu - lambda ln J) F^-1_bc F^-1_da + lambda F^-T_ab F^-T_cd.
// The out-of-plane Cauchy stress, zero strain along z: sigma_zz = lambda tr(eps) (linear),
// lambda ln J / J (neo-hookean).

#include <Teuchos_ParameterList.hpp>

#include <string>

#include "core/Tensor.hpp"
#include "material/Material.hpp"

namespace impm {

struct Lame {
  double mu, lambda;
};

struct PlaneStrainValue {
  double P[2][2];
  double A[2][2][2][2];
  double W;         // energy per unit reference volume
  double stressZZ;  // out-of-plane Cauchy stress
  bool admissible;  // false where the law is not defined (J <= 0 for neo-Hookean)
};

KOKKOS_INLINE_FUNCTION double delta(int a, int b) {
  return a == b ? 1.0 : 0.0;
}

struct LinearElasticLaw {
  static const char* model() { return "linear-elastic"; }
  static constexpr bool linear = true;
  KOKKOS_INLINE_FUNCTION static PlaneStrainValue evaluate(const double F[2][2], Lame k) {
    PlaneStrainValue v{};
    double eps[2][2];
    for (int a = 0; a < 2; ++a)
      for (int b = 0; b < 2; ++b)
        eps[a][b] = 0.5 * (F[a][b] + F[b][a]) - delta(a, b);
    const double tr = eps[0][0] + eps[1][1];
    v.W = 0.5 * k.lambda * tr * tr;
    for (int a = 0; a < 2; ++a)
      for (int b = 0; b < 2; ++b) {
        v.P[a][b] = k.lambda * tr * delta(a, b) + 2.0 * k.mu * eps[a][b];
        v.W += k.mu * eps[a][b] * eps[a][b];
        for (int c = 0; c < 2; ++c)
          for (int d = 0; d < 2; ++d)
            v.A[a][b][c][d] = k.lambda * delta(a, b) * delta(c, d) +
                              k.mu * (delta(a, c) * delta(b, d) + delta(a, d) * delta(b, c));
      }
    v.stressZZ = k.lambda * tr;
    v.admissible = true;
    return v;
  }
};

struct NeoHookeanLaw {
  static const char* model() { return "neo-hookean"; }
  static constexpr bool linear = false;
  KOKKOS_INLINE_FUNCTION static PlaneStrainValue evaluate(const double F[2][2], Lame k) {
    PlaneStrainValue v{};
    const double J = determinant<2>(F);
    if (!(J > 0.0))
      return v;
    double Finv[2][2];
    inverse<2>(F, J, Finv);
    const double lnJ = Kokkos::Experimental::log(J);
    double trC = 0.0;
    for (int a = 0; a < 2; ++a)
      for (int b = 0; b < 2; ++b) {
        trC += F[a][b] * F[a][b];
        v.P[a][b] = k.mu * (F[a][b] - Finv[b][a]) + k.lambda * lnJ * Finv[b][a];
        for (int c = 0; c < 2; ++c)
          for (int d = 0; d < 2; ++d)
            v.A[a][b][c][d] = k.mu * delta(a, c) * delta(b, d) +
                              (k.mu - k.lambda * lnJ) * Finv[b][c] * Finv[d][a] +
                              k.lambda * Finv[b][a] * Finv[d][c];
      }
    v.W = 0.5 * k.mu * (trC - 2.0 - 2.0 * lnJ) + 0.5 * k.lambda * lnJ * lnJ;
    v.stressZZ = k.lambda * lnJ / J;
    v.admissible = true;
    return v;
  }
};

// Row p of a view of 2 x 2 tensors.
KOKKOS_INLINE_FUNCTION void load(const Material<2>::Tensors& F, int p, double f[2][2]) {
  for (int a = 0; a < 2; ++a)
    for (int b = 0; b < 2; ++b)
      f[a][b] = F(p, a, b);
}

// P(p) and A(p) from a law's values.
KOKKOS_INLINE_FUNCTION void store(const Material<2>::Tensors& P, const Material<2>::Tangents& A,
                                  int p, const double Pv[2][2], const double Av[2][2][2][2]) {
  for (int a = 0; a < 2; ++a)
    for (int b = 0; b < 2; ++b) {
      P(p, a, b) = Pv[a][b];
      for (int c = 0; c < 2; ++c)
        for (int d = 0; d < 2; ++d)
          A(p, a, b, c, d) = Av[a][b][c][d];
    }
}

// Throws NumericalError naming the material and the particle when firstBad is a member index
// (the first particle where the law is undefined: J <= 0); returns when it is past the end.
void throwIfInverted(const Material<2>& material, const char* model,
                     const Material<2>::Evaluation& at, int firstBad);

// E and nu (required) of the plane-strain laws, and their Lame constants.
void declareElasticConstants(Teuchos::ParameterList& valid);
Lame lameOf(const Teuchos::ParameterList& params);

template <class Law>
class PlaneStrainLaw : public Material<2> {
 public:
  static const char* model() { return Law::model(); }
  static Teuchos::ParameterList validParameters();

  PlaneStrainLaw(const std::string& name, const Teuchos::ParameterList& params);
  void firstPiola(const Evaluation& at, Tensors& P, Tangents& A) const override;
  void energyDensity(const Evaluation& at, Scalars& W) const override;
  void outOfPlaneStress(const Evaluation& at, Scalars& stressZZ) const override;
  double maxModulus(const Evaluation& /*at*/) const override {
    return lame_.lambda + 2.0 * lame_.mu;  // P-wave modulus: c = sqrt((lambda + 2 mu) / rho)
  }
  double youngModulus(const Evaluation& /*at*/) const override {
    return youngFromLame(lame_.lambda, lame_.mu);
  }
  bool isLinear() const override { return Law::linear; }
  bool hasSymmetricTangent() const override { return true; }  // hyperelastic

 private:
  // out(p) = the given field of the law's value at F_p, for the material's particles.
  void setFromValue(const char* label, const Evaluation& at, double PlaneStrainValue::*field,
                    Scalars& out) const;

  Lame lame_;
};

}  // namespace impm
