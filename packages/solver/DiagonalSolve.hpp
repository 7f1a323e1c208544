#pragma once
// The linear solve of an explicit step with the lumped mass, without a Krylov method.  The
// Jacobian's nodal block is then the diagonal D = c0 M (with the constraint scale on
// Dirichlet rows), and the few extra unknowns e of Robin ends couple to it through a column
// B and a row C each:
//   [D B] [dn]   [rn]
//   [C E] [de] = [re].
// Eliminating dn = D^-1 (rn - B de) leaves the small dense system
//   (E - C D^-1 B) de = re - C D^-1 rn,
// solved on every rank alike; then dn follows by division.  B and C are the columns and
// rows of the extras, taken from the matrix by products with unit vectors.

#include <vector>

#include "core/TpetraTypes.hpp"

namespace impm {

// Solves J x = b for a J whose block on the unknowns where `nodal` is 1 is diagonal;
// `extras` are the global indices of the other unknowns that take part (rows where `nodal`
// is 0 and that are not extras, the padding unknown of an empty rank, get x = 0).
// Collective.  Throws NumericalError when a nodal diagonal entry or the reduced system is
// singular.
void solveDiagonalWithExtras(const CrsMatrix& J, const Vector& nodal, const std::vector<GO>& extras,
                             const Vector& b, Vector& x);

}  // namespace impm
