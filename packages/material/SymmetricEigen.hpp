#pragma once
// Eigenvalues and eigenvectors of a symmetric 3 x 3 tensor by cyclic Jacobi rotations:
// unconditionally convergent (quadratically, a handful of sweeps), accurate to round-off in
// every eigenvalue relative to the tensor's norm, and exact for a diagonal tensor (no
// rotation at all), which the reference state and repeated eigenvalues need.  A device
// function; no LAPACK.

#include <Kokkos_Core.hpp>

#include "material/SymTensor.hpp"

namespace impm {

// a = Q diag(lambda) Q^T, the columns of Q orthonormal eigenvectors.
KOKKOS_INLINE_FUNCTION void symmetricEigen(const Sym<double>& a, double lambda[3], double Q[3][3]) {
  double A[3][3];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      A[i][j] = entry(a, i, j);
      Q[i][j] = i == j ? 1.0 : 0.0;
    }
  const double norm = squaredNorm(a);
  for (int sweep = 0; sweep < 32; ++sweep) {
    const double off = A[0][1] * A[0][1] + A[0][2] * A[0][2] + A[1][2] * A[1][2];
    if (!(off > 1e-36 * norm))  // the off-diagonal below round-off of the diagonal
      break;
    for (int p = 0; p < 2; ++p)
      for (int q = p + 1; q < 3; ++q) {
        if (A[p][q] == 0.0)
          continue;
        // The rotation in the (p, q) plane that zeroes A[p][q]: t = tan of its angle, the
        // smaller root of t^2 + 2 theta t - 1 = 0.
        const double theta = (A[q][q] - A[p][p]) / (2.0 * A[p][q]);
        const double t =
            (theta >= 0.0 ? 1.0 : -1.0) /
            (Kokkos::Experimental::fabs(theta) + Kokkos::Experimental::sqrt(theta * theta + 1.0));
        const double c = 1.0 / Kokkos::Experimental::sqrt(t * t + 1.0), s = t * c;
        for (int k = 0; k < 3; ++k) {  // A <- A J
          const double akp = A[k][p], akq = A[k][q];
          A[k][p] = c * akp - s * akq, A[k][q] = s * akp + c * akq;
        }
        for (int k = 0; k < 3; ++k) {  // A <- J^T A
          const double apk = A[p][k], aqk = A[q][k];
          A[p][k] = c * apk - s * aqk, A[q][k] = s * apk + c * aqk;
        }
        for (int k = 0; k < 3; ++k) {  // Q <- Q J
          const double qkp = Q[k][p], qkq = Q[k][q];
          Q[k][p] = c * qkp - s * qkq, Q[k][q] = s * qkp + c * qkq;
        }
      }
  }
  for (int k = 0; k < 3; ++k)
    lambda[k] = A[k][k];
}

}  // namespace impm
