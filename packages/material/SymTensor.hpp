#pragma once
// Symmetric 3 x 3 tensors as the finite-strain laws use them (strains, Kirchhoff stresses,
// the plastic metric), on a scalar type T: double, or Fad for exact derivatives.
// Six components in the order of the symmetric3x3 fields (xx, yy, zz, xy, yz, xz).  A 2-D
// law is the 3-D law at F_zz = 1: its tensors have yz = xz = 0, which the isotropic
// functions (material/LogStrain) recognise and treat on the in-plane block.
//
// The deformation gradient of a Dim-D law is a Dim x Dim array; embed<Dim> gives the 3 x 3
// F with F_zz = 1 (2-D), and the kinematics below act on that.

#include <type_traits>

#include "core/ForwardAD.hpp"

namespace impm {

template <class T>
struct Sym {
  T xx, yy, zz, xy, yz, xz;
};

// Component (i, j) of a.
template <class T>
KOKKOS_INLINE_FUNCTION const T& entry(const Sym<T>& a, int i, int j) {
  if (i == j)
    return i == 0 ? a.xx : (i == 1 ? a.yy : a.zz);
  const int k = i + j;  // 1: xy, 3: yz, 2: xz
  return k == 1 ? a.xy : (k == 3 ? a.yz : a.xz);
}

// The symmetric tensor of a full one (its upper triangle).
template <class T>
KOKKOS_INLINE_FUNCTION Sym<T> symmetricOf(const T m[3][3]) {
  return {m[0][0], m[1][1], m[2][2], m[0][1], m[1][2], m[0][2]};
}

template <class T>
KOKKOS_INLINE_FUNCTION T trace(const Sym<T>& a) {
  return a.xx + a.yy + a.zz;
}

// a : a
template <class T>
KOKKOS_INLINE_FUNCTION T squaredNorm(const Sym<T>& a) {
  return a.xx * a.xx + a.yy * a.yy + a.zz * a.zz + 2.0 * (a.xy * a.xy + a.yz * a.yz + a.xz * a.xz);
}

// a : b
template <class T>
KOKKOS_INLINE_FUNCTION T contraction(const Sym<T>& a, const Sym<T>& b) {
  return a.xx * b.xx + a.yy * b.yy + a.zz * b.zz + 2.0 * (a.xy * b.xy + a.yz * b.yz + a.xz * b.xz);
}

// a + s I
template <class T, class S>
KOKKOS_INLINE_FUNCTION Sym<T> plusIdentity(const Sym<T>& a, const S& s) {
  return {a.xx + s, a.yy + s, a.zz + s, a.xy, a.yz, a.xz};
}

template <class T, class S>
KOKKOS_INLINE_FUNCTION Sym<T> scaled(const Sym<T>& a, const S& s) {
  return {a.xx * s, a.yy * s, a.zz * s, a.xy * s, a.yz * s, a.xz * s};
}

template <class T>
KOKKOS_INLINE_FUNCTION Sym<T> difference(const Sym<T>& a, const Sym<T>& b) {
  return {a.xx - b.xx, a.yy - b.yy, a.zz - b.zz, a.xy - b.xy, a.yz - b.yz, a.xz - b.xz};
}

// The deviatoric part a - tr(a)/3 I.
template <class T>
KOKKOS_INLINE_FUNCTION Sym<T> deviator(const Sym<T>& a) {
  return plusIdentity(a, -trace(a) / 3.0);
}

template <class T>
KOKKOS_INLINE_FUNCTION Sym<T> identityOf() {
  return {T(1.0), T(1.0), T(1.0), T(0.0), T(0.0), T(0.0)};
}

// The 3 x 3 deformation gradient of a Dim x Dim one: F_zz = 1 in 2-D (plane strain).
template <int Dim, class T>
KOKKOS_INLINE_FUNCTION void embed(const T F[Dim][Dim], T F3[3][3]) {
  static_assert(Dim == 2 || Dim == 3, "embed: the finite-strain laws are 2-D and 3-D");
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b)
      F3[a][b] = (a < Dim && b < Dim) ? F[a][b] : T(a == b ? 1.0 : 0.0);
}

// The scalar type of a product of S and T, one of them double (not decltype(S() * T()):
// with expression templates, such as Sacado's, that is an expression, not a number).
template <class S, class T>
using ProductType = std::conditional_t<std::is_same_v<S, double>, T, S>;

// F A F^T for a 3 x 3 F.
template <class T, class S>
KOKKOS_INLINE_FUNCTION Sym<ProductType<S, T>> congruence(const S F[3][3], const Sym<T>& a) {
  using R = ProductType<S, T>;
  R FA[3][3];  // F A
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      FA[i][j] = F[i][0] * entry(a, 0, j) + F[i][1] * entry(a, 1, j) + F[i][2] * entry(a, 2, j);
  const auto row = [&](int i, int j) -> R {  // R, not an expression of the lambda's temporaries
    return FA[i][0] * F[j][0] + FA[i][1] * F[j][1] + FA[i][2] * F[j][2];
  };
  return {row(0, 0), row(1, 1), row(2, 2), row(0, 1), row(1, 2), row(0, 2)};
}

// F^-1 of a 3 x 3 F, given its determinant (the adjugate, cyclic indices).
template <class T>
KOKKOS_INLINE_FUNCTION void inverseOf(const T F[3][3], const T& J, T Finv[3][3]) {
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      const int j1 = (j + 1) % 3, j2 = (j + 2) % 3, i1 = (i + 1) % 3, i2 = (i + 2) % 3;
      Finv[i][j] = (F[j1][i1] * F[j2][i2] - F[j1][i2] * F[j2][i1]) / J;
    }
}

template <class T>
KOKKOS_INLINE_FUNCTION T determinantOf(const T F[3][3]) {
  return F[0][0] * (F[1][1] * F[2][2] - F[1][2] * F[2][1]) -
         F[0][1] * (F[1][0] * F[2][2] - F[1][2] * F[2][0]) +
         F[0][2] * (F[1][0] * F[2][1] - F[1][1] * F[2][0]);
}

// The Dim x Dim block of the first Piola stress P = tau F^-T of a Kirchhoff stress.
template <int Dim, class T, class S>
KOKKOS_INLINE_FUNCTION void piolaOfKirchhoff(const Sym<T>& tau, const S Finv[3][3], T P[Dim][Dim]) {
  for (int a = 0; a < Dim; ++a)
    for (int b = 0; b < Dim; ++b)
      P[a][b] = entry(tau, a, 0) * Finv[b][0] + entry(tau, a, 1) * Finv[b][1] +
                entry(tau, a, 2) * Finv[b][2];
}

}  // namespace impm
