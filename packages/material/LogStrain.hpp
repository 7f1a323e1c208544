#pragma once
// The kinematics of the finite-strain laws (doc/theory.md, "Hencky elasticity and the
// exponential map"): the logarithm and the exponential of a symmetric 3 x 3 tensor, with
// derivatives, the Hencky stress of a logarithmic strain, and the trial and plastic states
// of the exponential map.  Written on a scalar type T, double or Fad<N>, so that one code
// gives the stress and its exact derivative.
//
// ln and exp are isotropic tensor functions: f(B) = sum_i f(lambda_i) n_i (x) n_i.  Their
// derivative along dB is the Daleckii-Krein formula: in the eigenbasis of B,
//   (d f(B)[dB])_ij = f[lambda_i, lambda_j] (Q^T dB Q)_ij,
// with the divided difference f[a, b] = (f(a) - f(b)) / (a - b), and f'(a) at a = b.  Written
// as f[m + r, m - r] with m the mean and r the half-difference, it is even in r, and near
// coincident eigenvalues (r -> 0, where the eigenvectors are undefined) it is evaluated by its
// Taylor series f'(m) + f'''(m) r^2 / 6: f(B) and its derivative are smooth and exact there,
// the reference state (three equal eigenvalues) included.
//
// A plane tensor (yz = xz = 0, derivatives included: every tensor of a 2-D law) takes the
// closed form of its in-plane block, f(B) = g0 I + g1 (B - m I) with g0 = (f(m + r) + f(m -
// r)) / 2 and g1 = f[m + r, m - r], and f(B_zz); any other the eigenvectors of B by Jacobi
// rotations (material/SymmetricEigen).

#include <type_traits>

#include "material/SymTensor.hpp"
#include "material/SymmetricEigen.hpp"

namespace impm {

// ln x, with the difference ln(lo + 2r) - ln(lo) computed without cancellation.
struct Logarithm {
  template <class T>
  KOKKOS_INLINE_FUNCTION static T f(const T& x) {
    return logOf(x);
  }
  template <class T>
  KOKKOS_INLINE_FUNCTION static T difference(const T& lo, const T& twoR) {
    return log1pOf(T(twoR / lo));
  }
  // f', f'', f''' at m
  template <class T>
  KOKKOS_INLINE_FUNCTION static void derivatives(const T& m, T& d1, T& d2, T& d3) {
    d1 = 1.0 / m, d2 = -d1 * d1, d3 = -2.0 * d2 * d1;
  }
  KOKKOS_INLINE_FUNCTION static bool nearlyEqual(double m, double r) { return r < 1e-5 * m; }
};

// exp x, with exp(lo + 2r) - exp(lo) = exp(lo) expm1(2r).
struct Exponential {
  template <class T>
  KOKKOS_INLINE_FUNCTION static T f(const T& x) {
    return expOf(x);
  }
  template <class T>
  KOKKOS_INLINE_FUNCTION static T difference(const T& lo, const T& twoR) {
    return expOf(lo) * expm1Of(twoR);
  }
  template <class T>
  KOKKOS_INLINE_FUNCTION static void derivatives(const T& m, T& d1, T& d2, T& d3) {
    d1 = d2 = d3 = expOf(m);
  }
  KOKKOS_INLINE_FUNCTION static bool nearlyEqual(double /*m*/, double r) { return r < 1e-5; }
};

// The divided difference f[a, b] of Fn (above), by value.
template <class Fn>
KOKKOS_INLINE_FUNCTION double dividedDifference(double a, double b) {
  const double m = 0.5 * (a + b), r = 0.5 * Kokkos::Experimental::fabs(a - b);
  if (Fn::nearlyEqual(m, r)) {
    double d1, d2, d3;
    Fn::derivatives(m, d1, d2, d3);
    return d1 + d3 * r * r / 6.0;
  }
  const double lo = a < b ? a : b;
  return Fn::difference(lo, 2.0 * r) / (2.0 * r);
}

// True when a has no out-of-plane shear, in value and in every derivative.
template <class T>
KOKKOS_INLINE_FUNCTION bool isPlane(const Sym<T>& a) {
  if (valueOf(a.yz) != 0.0 || valueOf(a.xz) != 0.0)
    return false;
  for (int k = 0; k < Directions<T>::value; ++k)
    if (derivativeOf(a.yz, k) != 0.0 || derivativeOf(a.xz, k) != 0.0)
      return false;
  return true;
}

// f(B) of a plane B: the in-plane block's closed form, and f(B_zz).
template <class Fn, class T>
KOKKOS_INLINE_FUNCTION Sym<T> planeFunction(const Sym<T>& B) {
  const T m = 0.5 * (B.xx + B.yy), h = 0.5 * (B.xx - B.yy);
  const T s = h * h + B.xy * B.xy;  // r^2
  T g0, g1;
  if (Fn::nearlyEqual(valueOf(m), Kokkos::Experimental::sqrt(valueOf(s)))) {
    T d1, d2, d3;
    Fn::derivatives(m, d1, d2, d3);
    g0 = Fn::f(m) + 0.5 * d2 * s;
    g1 = d1 + d3 * s / 6.0;
  } else {
    const T r = sqrtOf(s);
    // The smaller eigenvalue; from the determinant when m > 0, where m - r would cancel.
    const T lo = valueOf(m) > 0.0 ? T((B.xx * B.yy - B.xy * B.xy) / (m + r)) : T(m - r);
    const T diff = Fn::difference(lo, T(2.0 * r));
    g0 = Fn::f(lo) + 0.5 * diff;
    g1 = diff / (2.0 * r);
  }
  return {g0 + g1 * h, g0 - g1 * h, Fn::f(B.zz), g1 * B.xy, T(0.0), T(0.0)};
}

// The derivative of f(B) along any dB, for a B fixed once: Daleckii-Krein (above).
template <class Fn>
class IsotropicDerivative {
 public:
  KOKKOS_INLINE_FUNCTION explicit IsotropicDerivative(const Sym<double>& B) {
    symmetricEigen(B, lambda_, Q_);
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        G_[i][j] = dividedDifference<Fn>(lambda_[i], lambda_[j]);
  }
  // f(B) = Q diag(f(lambda)) Q^T.
  KOKKOS_INLINE_FUNCTION Sym<double> value() const {
    double f[3], m[3][3];
    for (int k = 0; k < 3; ++k)
      f[k] = Fn::f(lambda_[k]);
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        m[i][j] =
            Q_[i][0] * f[0] * Q_[j][0] + Q_[i][1] * f[1] * Q_[j][1] + Q_[i][2] * f[2] * Q_[j][2];
    return symmetricOf(m);
  }
  // Q (G o (Q^T dB Q)) Q^T.
  KOKKOS_INLINE_FUNCTION Sym<double> along(const Sym<double>& dB) const {
    double D[3][3], E[3][3];
    for (int a = 0; a < 3; ++a)  // E = dB Q
      for (int k = 0; k < 3; ++k)
        E[a][k] =
            entry(dB, a, 0) * Q_[0][k] + entry(dB, a, 1) * Q_[1][k] + entry(dB, a, 2) * Q_[2][k];
    for (int i = 0; i < 3; ++i)  // D = G o (Q^T E)
      for (int k = 0; k < 3; ++k)
        D[i][k] = G_[i][k] * (Q_[0][i] * E[0][k] + Q_[1][i] * E[1][k] + Q_[2][i] * E[2][k]);
    for (int a = 0; a < 3; ++a)  // E = Q D
      for (int k = 0; k < 3; ++k)
        E[a][k] = Q_[a][0] * D[0][k] + Q_[a][1] * D[1][k] + Q_[a][2] * D[2][k];
    double m[3][3];
    for (int a = 0; a < 3; ++a)  // E Q^T
      for (int b = 0; b < 3; ++b)
        m[a][b] = E[a][0] * Q_[b][0] + E[a][1] * Q_[b][1] + E[a][2] * Q_[b][2];
    return symmetricOf(m);
  }

 private:
  double lambda_[3], Q_[3][3], G_[3][3];
};

// f(B) for the isotropic function Fn (Logarithm: B symmetric positive definite).
template <class Fn, class T>
KOKKOS_INLINE_FUNCTION Sym<T> isotropicFunction(const Sym<T>& B) {
  if (isPlane(B))
    return planeFunction<Fn>(B);
  const Sym<double> Bv{valueOf(B.xx), valueOf(B.yy), valueOf(B.zz),
                       valueOf(B.xy), valueOf(B.yz), valueOf(B.xz)};
  const IsotropicDerivative<Fn> derivative(Bv);
  const Sym<double> v = derivative.value();
  Sym<T> out{T(v.xx), T(v.yy), T(v.zz), T(v.xy), T(v.yz), T(v.xz)};
  for (int k = 0; k < Directions<T>::value; ++k) {
    const Sym<double> dB{derivativeOf(B.xx, k), derivativeOf(B.yy, k), derivativeOf(B.zz, k),
                         derivativeOf(B.xy, k), derivativeOf(B.yz, k), derivativeOf(B.xz, k)};
    const Sym<double> d = derivative.along(dB);
    setDerivative(out.xx, k, d.xx), setDerivative(out.yy, k, d.yy);
    setDerivative(out.zz, k, d.zz), setDerivative(out.xy, k, d.xy);
    setDerivative(out.yz, k, d.yz), setDerivative(out.xz, k, d.xz);
  }
  return out;
}

// phi(q) = atanh(x)/x and phi'(q), x = sqrt(q) in [0, 1): for ln, g1 = phi(r^2/m^2)/m.  By
// their series sum q^k/(2k + 1) below q = 0.01 (ten terms: truncation below 1e-20), where
// the closed form of phi' would cancel.
KOKKOS_INLINE_FUNCTION void atanhRatio(double q, double& phi, double& dphi) {
  if (q < 0.01) {
    phi = dphi = 0.0;
    for (int k = 9; k >= 0; --k) {  // Horner
      phi = phi * q + 1.0 / (2 * k + 1);
      dphi = dphi * q + (k + 1.0) / (2 * k + 3);
    }
    return;
  }
  const double x = Kokkos::Experimental::sqrt(q), t = Kokkos::Experimental::atanh(x);
  phi = t / x;
  dphi = (x / (1.0 - q) - t) / (2.0 * q * x);
}

// The derivative of ln B along plane directions dB of a plane B (2-D laws), in closed form:
// on the in-plane block ln B = g0 I + g1 (B - m I) with g0 = (1/2) ln det and g1 =
// phi(s/m^2)/m, functions of the mean m and of s = r^2 (doc/theory.md); so
//   d ln B = dg0 I + dg1 (B - m I) + g1 (dB - dm I),
//   dg0 = (m dm - ds/2)/det,  dg1 = -dm/det + phi'(s/m^2) ds/m^3,
// smooth where the eigenvalues coincide (no division by r); and dB_zz / B_zz.  What depends
// on B alone is computed once, for the directions of a tangent.
class PlaneLogarithmDerivative {
 public:
  KOKKOS_INLINE_FUNCTION explicit PlaneLogarithmDerivative(const Sym<double>& B)
      : B_(B), m_(0.5 * (B.xx + B.yy)), h_(0.5 * (B.xx - B.yy)) {
    const double s = h_ * h_ + B.xy * B.xy;
    double phi, dphi;
    atanhRatio(s / (m_ * m_), phi, dphi);
    g1_ = phi / m_, c_ = dphi / (m_ * m_ * m_);
    inverseDet_ = 1.0 / (B.xx * B.yy - B.xy * B.xy);
  }
  KOKKOS_INLINE_FUNCTION Sym<double> along(const Sym<double>& dB) const {
    const double dm = 0.5 * (dB.xx + dB.yy), dh = 0.5 * (dB.xx - dB.yy);
    const double ds = 2.0 * (h_ * dh + B_.xy * dB.xy);
    const double dg0 = (m_ * dm - 0.5 * ds) * inverseDet_, dg1 = c_ * ds - dm * inverseDet_;
    return {dg0 + dg1 * h_ + g1_ * dh,
            dg0 - dg1 * h_ - g1_ * dh,
            dB.zz / B_.zz,
            dg1 * B_.xy + g1_ * dB.xy,
            0.0,
            0.0};
  }

 private:
  Sym<double> B_;
  double m_, h_, g1_ = 0, c_ = 0, inverseDet_ = 0;
};

// The derivative of ln B (B symmetric positive definite) of a Dim-D law, constructed from B,
// along(dB) for any direction of that dimension.
template <int Dim>
using LogarithmDerivative =
    std::conditional_t<Dim == 2, PlaneLogarithmDerivative, IsotropicDerivative<Logarithm>>;

// Hencky's law: tau = lambda tr(eps) I + 2 mu eps (isotropic, linear in the log strain).
template <class T>
KOKKOS_INLINE_FUNCTION Sym<T> henckyStress(const Sym<T>& eps, double mu, double lambda) {
  return plusIdentity(scaled(eps, 2.0 * mu), lambda * trace(eps));
}

// Hencky's stored energy: lambda/2 tr(eps)^2 + mu eps : eps.
template <class T>
KOKKOS_INLINE_FUNCTION T henckyEnergy(const Sym<T>& eps, double mu, double lambda) {
  const T tr = trace(eps);
  return 0.5 * lambda * tr * tr + mu * squaredNorm(eps);
}

// The trial elastic strain of a step from the plastic state C_p^-1: (1/2) ln(F C_p^-1 F^T).
template <class T>
KOKKOS_INLINE_FUNCTION Sym<T> trialElasticStrain(const T F[3][3], const Sym<double>& CpInv) {
  return scaled(isotropicFunction<Logarithm>(congruence(F, CpInv)), 0.5);
}

// The plastic state after the return: C_p^-1 = F^-1 exp(2 eps_e) F^-T.
template <class T>
KOKKOS_INLINE_FUNCTION Sym<T> plasticMetricOf(const T F[3][3], const Sym<T>& epsE) {
  T Finv[3][3];
  inverseOf(F, determinantOf(F), Finv);
  return congruence(Finv, isotropicFunction<Exponential>(scaled(epsE, 2.0)));
}

}  // namespace impm
