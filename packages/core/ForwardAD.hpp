#pragma once
// Forward-mode automatic differentiation for the constitutive laws, by Trilinos' Sacado: a
// value and its derivatives along N directions (Fad<N>, a static Fad with expression
// templates), carried through arithmetic and the elementary functions by the chain rule.  A
// law written once on a scalar type T (double or Fad<N>) returns its stress and the exact
// derivative of the algorithm that computed it: for a return map, that derivative is the
// algorithmic (consistent) tangent Newton needs for its quadratic rate (doc/theory.md,
// "Consistent tangents").  Branches (elastic or plastic, cone or apex) are taken on the
// value; the derivative is that of the branch taken, which is what the consistent tangent is.
//
// What the laws call on T is here, for double and for Fad<N> alike: valueOf, the elementary
// functions sqrtOf ... expm1Of (Sacado has no log1p and no expm1: their chain rule is written
// out), and, for rules that set a result's derivatives themselves (the Daleckii-Krein
// formula of material/LogStrain), Directions<T>, derivativeOf and setDerivative.  Results of
// arithmetic on Fad are expressions that refer to their operands: a law stores them in a T
// (never in `auto`), as the scalar types of material/SymTensor do.

#include <Kokkos_Core.hpp>
#include <Sacado.hpp>

namespace impm {

template <int N>
using Fad = Sacado::Fad::SFad<double, N>;

// The independent variable number k (0 <= k < N) at `value`.
template <int N>
KOKKOS_INLINE_FUNCTION Fad<N> variable(double value, int k) {
  return Fad<N>(N, k, value);
}

// The value of a double or of a Fad (for branches and output).
KOKKOS_INLINE_FUNCTION double valueOf(double x) {
  return x;
}
template <int N>
KOKKOS_INLINE_FUNCTION double valueOf(const Fad<N>& x) {
  return x.val();
}

// The number of derivative directions of a scalar type (0 for double), and access to them.
template <class T>
struct Directions {
  static constexpr int value = 0;
};
template <int N>
struct Directions<Fad<N>> {
  static constexpr int value = N;
};
KOKKOS_INLINE_FUNCTION double derivativeOf(double /*x*/, int /*k*/) {
  return 0.0;
}
template <int N>
KOKKOS_INLINE_FUNCTION double derivativeOf(const Fad<N>& x, int k) {
  return x.fastAccessDx(k);
}
KOKKOS_INLINE_FUNCTION void setDerivative(double& /*x*/, int /*k*/, double /*value*/) {}
template <int N>
KOKKOS_INLINE_FUNCTION void setDerivative(Fad<N>& x, int k, double value) {
  x.fastAccessDx(k) = value;
}

// The elementary functions, for doubles and Fads alike (laws are written once, on T).
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
KOKKOS_INLINE_FUNCTION Fad<N> sqrtOf(const Fad<N>& x) {
  return sqrt(x);
}
template <int N>
KOKKOS_INLINE_FUNCTION Fad<N> logOf(const Fad<N>& x) {
  return log(x);
}
template <int N>
KOKKOS_INLINE_FUNCTION Fad<N> expOf(const Fad<N>& x) {
  return exp(x);
}
// f(x) with f(x.val()) = fv and f'(x.val()) = dfdx.
template <int N>
KOKKOS_INLINE_FUNCTION Fad<N> chain(const Fad<N>& x, double fv, double dfdx) {
  Fad<N> r(N, fv);
  for (int k = 0; k < N; ++k)
    r.fastAccessDx(k) = dfdx * x.fastAccessDx(k);
  return r;
}
template <int N>
KOKKOS_INLINE_FUNCTION Fad<N> log1pOf(const Fad<N>& x) {
  return chain(x, Kokkos::Experimental::log1p(x.val()), 1.0 / (1.0 + x.val()));
}
template <int N>
KOKKOS_INLINE_FUNCTION Fad<N> expm1Of(const Fad<N>& x) {
  return chain(x, Kokkos::Experimental::expm1(x.val()), Kokkos::Experimental::exp(x.val()));
}

}  // namespace impm
