#pragma once
// The kinematics of the finite-strain laws in plane strain (doc/theory.md, "Hencky
// elasticity and the exponential map"): symmetric 3 x 3 tensors with no out-of-plane shear,
// the logarithm and the exponential of such a tensor, the Hencky stress of a logarithmic
// strain, and the first Piola stress of a Kirchhoff stress.  Written on a scalar type T,
// double or Dual<4>, so that one code gives the stress and its exact derivative.
//
// ln and exp are isotropic tensor functions: f(B) = sum_i f(lambda_i) n_i (x) n_i.  On the
// in-plane block, with m the mean and r the half-difference of the two eigenvalues,
//   f(B) = g0 I + g1 (B - m I),  g0 = (f(m + r) + f(m - r)) / 2,  g1 = (f(m + r) - f(m - r)) / (2
//   r),
// and g0, g1 are even in r: near coincident eigenvalues (r -> 0, where eigenvectors are
// undefined and their derivatives blow up) they are evaluated by their Taylor series in r^2,
// so f(B) and its derivative are smooth and exact there, the reference state included.

#include "core/Dual.hpp"

namespace impm {

// The finite-strain laws' derivatives by dual numbers (the plastic laws' return map; the
// unit tests' reference for Hencky's written-out tangent).
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

// A symmetric 3 x 3 tensor of plane strain: xz = yz = 0.
template <class T>
struct PlaneSym {
  T xx, yy, xy, zz;
};

template <class T>
KOKKOS_INLINE_FUNCTION T trace(const PlaneSym<T>& a) {
  return a.xx + a.yy + a.zz;
}

// a : a
template <class T>
KOKKOS_INLINE_FUNCTION T squaredNorm(const PlaneSym<T>& a) {
  return a.xx * a.xx + a.yy * a.yy + a.zz * a.zz + 2.0 * a.xy * a.xy;
}

// a + s I
template <class T, class S>
KOKKOS_INLINE_FUNCTION PlaneSym<T> plusIdentity(const PlaneSym<T>& a, const S& s) {
  return {a.xx + s, a.yy + s, a.xy, a.zz + s};
}

template <class T, class S>
KOKKOS_INLINE_FUNCTION PlaneSym<T> scaled(const PlaneSym<T>& a, const S& s) {
  return {a.xx * s, a.yy * s, a.xy * s, a.zz * s};
}

// The deviatoric part a - tr(a)/3 I.
template <class T>
KOKKOS_INLINE_FUNCTION PlaneSym<T> deviator(const PlaneSym<T>& a) {
  return plusIdentity(a, -trace(a) / 3.0);
}

// ln x, with the difference ln(lo + 2r) - ln(lo) computed without cancellation.
struct Logarithm {
  template <class T>
  KOKKOS_INLINE_FUNCTION static T f(const T& x) {
    return logOf(x);
  }
  template <class T>
  KOKKOS_INLINE_FUNCTION static T difference(const T& lo, const T& twoR) {
    return log1pOf(twoR / lo);
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

// f(B) for the isotropic function Fn (Logarithm: B symmetric positive definite).
template <class Fn, class T>
KOKKOS_INLINE_FUNCTION PlaneSym<T> isotropicFunction(const PlaneSym<T>& B) {
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
    const T lo = valueOf(m) > 0.0 ? (B.xx * B.yy - B.xy * B.xy) / (m + r) : m - r;
    const T diff = Fn::difference(lo, 2.0 * r);
    g0 = Fn::f(lo) + 0.5 * diff;
    g1 = diff / (2.0 * r);
  }
  return {g0 + g1 * h, g0 - g1 * h, g1 * B.xy, Fn::f(B.zz)};
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

// The derivative of ln B (B symmetric positive definite) along any dB.  On the in-plane
// block ln B = g0 I + g1 (B - m I) with g0 = (1/2) ln det and g1 = phi(s/m^2)/m, functions
// of the mean m and of s = r^2 (doc/theory.md); so
//   d ln B = dg0 I + dg1 (B - m I) + g1 (dB - dm I),
//   dg0 = (m dm - ds/2)/det,  dg1 = -dm/det + phi'(s/m^2) ds/m^3,
// smooth where the eigenvalues coincide (no division by r).  The zz entry: dB_zz / B_zz.
// What depends on B alone is computed once, for the four directions of a tangent.
class LogarithmDerivative {
 public:
  KOKKOS_INLINE_FUNCTION explicit LogarithmDerivative(const PlaneSym<double>& B)
      : B_(B), m_(0.5 * (B.xx + B.yy)), h_(0.5 * (B.xx - B.yy)) {
    const double s = h_ * h_ + B.xy * B.xy;
    double phi, dphi;
    atanhRatio(s / (m_ * m_), phi, dphi);
    g1_ = phi / m_, c_ = dphi / (m_ * m_ * m_);
    inverseDet_ = 1.0 / (B.xx * B.yy - B.xy * B.xy);
  }
  KOKKOS_INLINE_FUNCTION PlaneSym<double> along(const PlaneSym<double>& dB) const {
    const double dm = 0.5 * (dB.xx + dB.yy), dh = 0.5 * (dB.xx - dB.yy);
    const double ds = 2.0 * (h_ * dh + B_.xy * dB.xy);
    const double dg0 = (m_ * dm - 0.5 * ds) * inverseDet_, dg1 = c_ * ds - dm * inverseDet_;
    return {dg0 + dg1 * h_ + g1_ * dh, dg0 - dg1 * h_ - g1_ * dh, dg1 * B_.xy + g1_ * dB.xy,
            dB.zz / B_.zz};
  }

 private:
  PlaneSym<double> B_;
  double m_, h_, g1_ = 0, c_ = 0, inverseDet_ = 0;
};

// Hencky's law: tau = lambda tr(eps) I + 2 mu eps (isotropic, linear in the log strain).
template <class T>
KOKKOS_INLINE_FUNCTION PlaneSym<T> henckyStress(const PlaneSym<T>& eps, double mu, double lambda) {
  return plusIdentity(scaled(eps, 2.0 * mu), lambda * trace(eps));
}

// Hencky's stored energy: lambda/2 tr(eps)^2 + mu eps : eps.
template <class T>
KOKKOS_INLINE_FUNCTION T henckyEnergy(const PlaneSym<T>& eps, double mu, double lambda) {
  const T tr = trace(eps);
  return 0.5 * lambda * tr * tr + mu * squaredNorm(eps);
}

// F A F^T for the in-plane block of F (F_zz = 1).
template <class T, class S>
KOKKOS_INLINE_FUNCTION auto congruence(const S F[2][2], const PlaneSym<T>& a)
    -> PlaneSym<decltype(S() * T())> {
  using R = decltype(S() * T());
  const R t00 = F[0][0] * a.xx + F[0][1] * a.xy, t01 = F[0][0] * a.xy + F[0][1] * a.yy;
  const R t10 = F[1][0] * a.xx + F[1][1] * a.xy, t11 = F[1][0] * a.xy + F[1][1] * a.yy;
  return {t00 * F[0][0] + t01 * F[0][1], t10 * F[1][0] + t11 * F[1][1],
          t00 * F[1][0] + t01 * F[1][1], R(a.zz)};
}

// F^-1 of the in-plane block, given its determinant.
template <class T>
KOKKOS_INLINE_FUNCTION void inverseOf(const T F[2][2], const T& J, T Finv[2][2]) {
  Finv[0][0] = F[1][1] / J, Finv[0][1] = -F[0][1] / J;
  Finv[1][0] = -F[1][0] / J, Finv[1][1] = F[0][0] / J;
}

// The trial elastic strain of a step from the plastic state C_p^-1: (1/2) ln(F C_p^-1 F^T).
template <class T>
KOKKOS_INLINE_FUNCTION PlaneSym<T> trialElasticStrain(const T F[2][2],
                                                      const PlaneSym<double>& CpInv) {
  return scaled(isotropicFunction<Logarithm>(congruence(F, CpInv)), 0.5);
}

// The plastic state after the return: C_p^-1 = F^-1 exp(2 eps_e) F^-T.
template <class T>
KOKKOS_INLINE_FUNCTION PlaneSym<T> plasticMetricOf(const T F[2][2], const PlaneSym<T>& epsE) {
  const T J = F[0][0] * F[1][1] - F[0][1] * F[1][0];
  T Finv[2][2];
  inverseOf(F, J, Finv);
  return congruence(Finv, isotropicFunction<Exponential>(scaled(epsE, 2.0)));
}

// The in-plane first Piola stress P = tau F^-T of a Kirchhoff stress.
template <class T, class S>
KOKKOS_INLINE_FUNCTION void piolaOfKirchhoff(const PlaneSym<T>& tau, const S Finv[2][2],
                                             T P[2][2]) {
  const T t[2][2] = {{tau.xx, tau.xy}, {tau.xy, tau.yy}};
  for (int a = 0; a < 2; ++a)
    for (int b = 0; b < 2; ++b)
      P[a][b] = t[a][0] * Finv[b][0] + t[a][1] * Finv[b][1];
}

}  // namespace impm
