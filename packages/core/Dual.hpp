#pragma once
// Forward-mode dual numbers: a value and its derivatives along N directions, carried
// through arithmetic and the elementary functions by the chain rule.  A constitutive law
// written once on Dual<N> returns its stress and the exact derivative of the algorithm that
// computed it: for a return map, that derivative is the algorithmic (consistent) tangent
// Newton needs for its quadratic rate (doc/theory.md, "Consistent tangents").
//
// Branches (elastic or plastic, cone or apex) are taken on the value; the derivative is
// that of the branch taken, which is what the consistent tangent is.

#include <Kokkos_Core.hpp>

namespace impm {

template <int N>
struct Dual {
  double v = 0.0;
  double d[N] = {};

  KOKKOS_INLINE_FUNCTION Dual() = default;
  KOKKOS_INLINE_FUNCTION Dual(double value) : v(value) {}  // NOLINT: constants mix freely

  // The independent variable number k (0 <= k < N) at `value`.
  KOKKOS_INLINE_FUNCTION static Dual variable(double value, int k) {
    Dual x(value);
    x.d[k] = 1.0;
    return x;
  }
};

// The value of a double or of a dual (for branches and output).
KOKKOS_INLINE_FUNCTION double valueOf(double x) {
  return x;
}
template <int N>
KOKKOS_INLINE_FUNCTION double valueOf(const Dual<N>& x) {
  return x.v;
}

// The derivative directions of a scalar type (0 for double), and access to them: for rules
// that set a result's derivatives themselves (an isotropic tensor function's, by the
// Daleckii-Krein formula in material/LogStrain).
template <class T>
struct Directions {
  static constexpr int value = 0;
};
template <int N>
struct Directions<Dual<N>> {
  static constexpr int value = N;
};
KOKKOS_INLINE_FUNCTION double derivativeOf(double /*x*/, int /*k*/) {
  return 0.0;
}
template <int N>
KOKKOS_INLINE_FUNCTION double derivativeOf(const Dual<N>& x, int k) {
  return x.d[k];
}
KOKKOS_INLINE_FUNCTION void setDerivative(double& /*x*/, int /*k*/, double /*value*/) {}
template <int N>
KOKKOS_INLINE_FUNCTION void setDerivative(Dual<N>& x, int k, double value) {
  x.d[k] = value;
}

// f(x) with f(x.v) = fv and f'(x.v) = dfdx.
template <int N>
KOKKOS_INLINE_FUNCTION Dual<N> chain(const Dual<N>& x, double fv, double dfdx) {
  Dual<N> r(fv);
  for (int k = 0; k < N; ++k)
    r.d[k] = dfdx * x.d[k];
  return r;
}

template <int N>
KOKKOS_INLINE_FUNCTION Dual<N> operator-(const Dual<N>& a) {
  return chain(a, -a.v, -1.0);
}

template <int N>
KOKKOS_INLINE_FUNCTION Dual<N> operator+(const Dual<N>& a, const Dual<N>& b) {
  Dual<N> r(a.v + b.v);
  for (int k = 0; k < N; ++k)
    r.d[k] = a.d[k] + b.d[k];
  return r;
}

template <int N>
KOKKOS_INLINE_FUNCTION Dual<N> operator-(const Dual<N>& a, const Dual<N>& b) {
  Dual<N> r(a.v - b.v);
  for (int k = 0; k < N; ++k)
    r.d[k] = a.d[k] - b.d[k];
  return r;
}

template <int N>
KOKKOS_INLINE_FUNCTION Dual<N> operator*(const Dual<N>& a, const Dual<N>& b) {
  Dual<N> r(a.v * b.v);
  for (int k = 0; k < N; ++k)
    r.d[k] = a.d[k] * b.v + a.v * b.d[k];
  return r;
}

template <int N>
KOKKOS_INLINE_FUNCTION Dual<N> operator/(const Dual<N>& a, const Dual<N>& b) {
  const double q = a.v / b.v;
  Dual<N> r(q);
  for (int k = 0; k < N; ++k)
    r.d[k] = (a.d[k] - q * b.d[k]) / b.v;
  return r;
}

// Mixed with doubles (the overloads above do not deduce N from a double).
#define IMPM_DUAL_MIXED(op)                                                      \
  template <int N>                                                               \
  KOKKOS_INLINE_FUNCTION Dual<N> operator op(const Dual<N>& a, double b) {       \
    return a op Dual<N>(b);                                                      \
  }                                                                              \
  template <int N>                                                               \
  KOKKOS_INLINE_FUNCTION Dual<N> operator op(double a, const Dual<N>& b) {       \
    return Dual<N>(a) op b;                                                      \
  }                                                                              \
  template <int N>                                                               \
  KOKKOS_INLINE_FUNCTION Dual<N>& operator op##=(Dual<N>& a, const Dual<N>& b) { \
    return a = a op b;                                                           \
  }                                                                              \
  template <int N>                                                               \
  KOKKOS_INLINE_FUNCTION Dual<N>& operator op##=(Dual<N>& a, double b) {         \
    return a = a op Dual<N>(b);                                                  \
  }
IMPM_DUAL_MIXED(+)
IMPM_DUAL_MIXED(-)
IMPM_DUAL_MIXED(*)
IMPM_DUAL_MIXED(/)
#undef IMPM_DUAL_MIXED

// The elementary functions, for doubles and duals alike (laws are written once, on T).
KOKKOS_INLINE_FUNCTION double sqrtOf(double x) {
  return Kokkos::Experimental::sqrt(x);
}
KOKKOS_INLINE_FUNCTION double logOf(double x) {
  return Kokkos::Experimental::log(x);
}
KOKKOS_INLINE_FUNCTION double log1pOf(double x) {
  return Kokkos::Experimental::log1p(x);
}
KOKKOS_INLINE_FUNCTION double expOf(double x) {
  return Kokkos::Experimental::exp(x);
}
KOKKOS_INLINE_FUNCTION double expm1Of(double x) {
  return Kokkos::Experimental::expm1(x);
}

template <int N>
KOKKOS_INLINE_FUNCTION Dual<N> sqrtOf(const Dual<N>& x) {
  const double s = Kokkos::Experimental::sqrt(x.v);
  return chain(x, s, 0.5 / s);
}
template <int N>
KOKKOS_INLINE_FUNCTION Dual<N> logOf(const Dual<N>& x) {
  return chain(x, Kokkos::Experimental::log(x.v), 1.0 / x.v);
}
template <int N>
KOKKOS_INLINE_FUNCTION Dual<N> log1pOf(const Dual<N>& x) {
  return chain(x, Kokkos::Experimental::log1p(x.v), 1.0 / (1.0 + x.v));
}
template <int N>
KOKKOS_INLINE_FUNCTION Dual<N> expOf(const Dual<N>& x) {
  const double e = Kokkos::Experimental::exp(x.v);
  return chain(x, e, e);
}
template <int N>
KOKKOS_INLINE_FUNCTION Dual<N> expm1Of(const Dual<N>& x) {
  return chain(x, Kokkos::Experimental::expm1(x.v), Kokkos::Experimental::exp(x.v));
}

}  // namespace impm
