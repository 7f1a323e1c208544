#pragma once
// The elastic laws of 2-D (plane strain, F_zz = 1) and 3-D, as device functors of the Dim x Dim
// deformation gradient; ElasticLaw<Dim, Law> runs them through the Material interface.  The
// formulas below hold in any dimension; in 2-D they are the 3-D law at F_zz = 1 (the
// out-of-plane terms are constants), so a slab one cell thick with rollers on its z faces is
// the plane-strain body.  With mu = E / (2 (1 + nu)), lambda = E nu / ((1 + nu)(1 - 2 nu)):
//
//   linear-elastic  P = lambda tr(eps) I + 2 mu eps,  eps = sym(F) - I
//                   (small-strain Hooke's law read as a first Piola stress: linear in F, so
//                   a total-Lagrangian step is one linear solve; not objective under large
//                   rotations, which is what "linear" costs)
//   neo-hookean     P = mu (F - F^-T) + lambda ln J F^-T,  J = det F
//                   (sigma = (mu / J)(b - I) + (lambda / J) ln J I; needs J > 0;
//                   W = mu/2 (tr C - 3 - 2 ln J) + lambda/2 ln^2 J, tr C over the 3-D F)
//
// Tangents A_abcd = dP_ab / dF_cd in closed form; with d(F^-1)_ba / dF_cd = -F^-1_bc F^-1_da,
//   neo-hookean  A = mu d_ac d_bd + (mu - lambda ln J) F^-1_bc F^-1_da + lambda F^-T_ab F^-T_cd.
// The out-of-plane Cauchy stress of plane strain is P_zz / J, as the 3-D law's at F_zz = 1:
// lambda tr(eps) / J (linear), lambda ln J / J (neo-hookean).

#include <Teuchos_ParameterList.hpp>

#include <string>

#include "core/Tensor.hpp"
#include "material/Material.hpp"

namespace impm {

struct Lame {
  double mu, lambda;
};

template <int Dim>
struct ElasticValue {
  double P[Dim][Dim];
  double A[Dim][Dim][Dim][Dim];
  double W;         // energy per unit reference volume
  double stressZZ;  // out-of-plane Cauchy stress (plane strain)
  bool admissible;  // false where the law is not defined (J <= 0 for neo-Hookean)
};

KOKKOS_INLINE_FUNCTION double delta(int a, int b) {
  return a == b ? 1.0 : 0.0;
}

struct LinearElasticLaw {
  static const char* model() { return "linear-elastic"; }
  static constexpr bool linear = true;
  static constexpr int maxDimension = 3;
  template <int Dim>
  KOKKOS_INLINE_FUNCTION static ElasticValue<Dim> evaluate(const double F[Dim][Dim], Lame k) {
    ElasticValue<Dim> v{};
    double eps[Dim][Dim];
    double tr = 0.0;
    for (int a = 0; a < Dim; ++a) {
      for (int b = 0; b < Dim; ++b)
        eps[a][b] = 0.5 * (F[a][b] + F[b][a]) - delta(a, b);
      tr += eps[a][a];
    }
    v.W = 0.5 * k.lambda * tr * tr;
    for (int a = 0; a < Dim; ++a)
      for (int b = 0; b < Dim; ++b) {
        v.P[a][b] = k.lambda * tr * delta(a, b) + 2.0 * k.mu * eps[a][b];
        v.W += k.mu * eps[a][b] * eps[a][b];
        for (int c = 0; c < Dim; ++c)
          for (int d = 0; d < Dim; ++d)
            v.A[a][b][c][d] = k.lambda * delta(a, b) * delta(c, d) +
                              k.mu * (delta(a, c) * delta(b, d) + delta(a, d) * delta(b, c));
      }
    v.stressZZ = k.lambda * tr / determinant<Dim>(F);  // P_zz / J, as for every law
    v.admissible = true;
    return v;
  }
};

struct NeoHookeanLaw {
  static const char* model() { return "neo-hookean"; }
  static constexpr bool linear = false;
  static constexpr int maxDimension = 3;
  template <int Dim>
  KOKKOS_INLINE_FUNCTION static ElasticValue<Dim> evaluate(const double F[Dim][Dim], Lame k) {
    ElasticValue<Dim> v{};
    const double J = determinant<Dim>(F);
    if (!(J > 0.0))
      return v;
    double Finv[Dim][Dim];
    inverse<Dim>(F, J, Finv);
    const double lnJ = Kokkos::Experimental::log(J);
    double trC = 0.0;
    for (int a = 0; a < Dim; ++a)
      for (int b = 0; b < Dim; ++b) {
        trC += F[a][b] * F[a][b];
        v.P[a][b] = k.mu * (F[a][b] - Finv[b][a]) + k.lambda * lnJ * Finv[b][a];
        for (int c = 0; c < Dim; ++c)
          for (int d = 0; d < Dim; ++d)
            v.A[a][b][c][d] = k.mu * delta(a, c) * delta(b, d) +
                              (k.mu - k.lambda * lnJ) * Finv[b][c] * Finv[d][a] +
                              k.lambda * Finv[b][a] * Finv[d][c];
      }
    v.W = 0.5 * k.mu * (trC - Dim - 2.0 * lnJ) + 0.5 * k.lambda * lnJ * lnJ;
    v.stressZZ = k.lambda * lnJ / J;
    v.admissible = true;
    return v;
  }
};

// Row p of a view of Dim x Dim tensors.
template <int Dim>
KOKKOS_INLINE_FUNCTION void load(const typename Material<Dim>::Tensors& F, int p,
                                 double f[Dim][Dim]) {
  for (int a = 0; a < Dim; ++a)
    for (int b = 0; b < Dim; ++b)
      f[a][b] = F(p, a, b);
}

// P(p) and A(p) from a law's values.
template <int Dim>
KOKKOS_INLINE_FUNCTION void store(const typename Material<Dim>::Tensors& P,
                                  const typename Material<Dim>::Tangents& A, int p,
                                  const double Pv[Dim][Dim], const double Av[Dim][Dim][Dim][Dim]) {
  for (int a = 0; a < Dim; ++a)
    for (int b = 0; b < Dim; ++b) {
      P(p, a, b) = Pv[a][b];
      for (int c = 0; c < Dim; ++c)
        for (int d = 0; d < Dim; ++d)
          A(p, a, b, c, d) = Av[a][b][c][d];
    }
}

// Throws NumericalError naming the material and the particle when firstBad is a member index
// (the first particle where the law is undefined: J <= 0); returns when it is past the end.
template <int Dim>
void throwIfInverted(const Material<Dim>& material, const char* model,
                     const typename Material<Dim>::Evaluation& at, int firstBad);

// E and nu (required) of the plane-strain laws, and their Lame constants.
void declareElasticConstants(Teuchos::ParameterList& valid);
Lame lameOf(const Teuchos::ParameterList& params);

// An elastic law in Dim dimensions; Law::maxDimension says up to which it is written.
template <int Dim, class Law>
class ElasticLaw : public Material<Dim> {
  static_assert(Dim >= 2 && Dim <= Law::maxDimension, "ElasticLaw: not written for this dimension");

 public:
  using Base = Material<Dim>;
  using typename Base::Evaluation;
  using typename Base::Scalars;
  using typename Base::Tangents;
  using typename Base::Tensors;
  using ExecutionSpace = typename Base::ExecutionSpace;
  static constexpr int dimension = Dim;
  static const char* model() { return Law::model(); }
  static Teuchos::ParameterList validParameters();

  ElasticLaw(const std::string& name, const Teuchos::ParameterList& params);
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
  void setFromValue(const char* label, const Evaluation& at, double ElasticValue<Dim>::*field,
                    Scalars& out) const;

  Lame lame_;
};

}  // namespace impm
