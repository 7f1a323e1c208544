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

#include <Teuchos_SerialDenseMatrix.hpp>

#include "core/TpetraTypes.hpp"

namespace impm {

// Solves J x = b for a J whose block on the unknowns where `nodal` is 1 is diagonal;
// `extras` are the global indices of the other unknowns that take part (rows where `nodal`
// is 0 and that are not extras, the padding unknown of an empty rank, get x = 0).  The
// elimination is done once, at construction; solve() is then one division per unknown and a
// few operations per entry of B and C, as many times as the matrix serves (an explicit run's
// fixed grid: every step).
class DiagonalElimination {
 public:
  // Collective.  Throws NumericalError when a nodal diagonal entry or the reduced system is
  // singular.
  DiagonalElimination(const CrsMatrix& J, const Vector& nodal, const std::vector<GO>& extras);
  // Collective.
  void solve(const Vector& b, Vector& x) const;

 private:
  // The nonzero entries of a vector on this rank: local rows (ascending) and values.
  struct Sparse {
    std::vector<LO> rows;
    std::vector<double> values;
  };
  // Those of scale .* v.
  static Sparse nonzeros(const Vector& v, const Vector& scale);
  // The sum over this rank's rows of a_i b_i.
  static double dot(const Sparse& a, const Sparse& b);

  Teuchos::RCP<const Map> map_;
  std::vector<GO> extras_;
  std::vector<LO> extraRows_;                   // local rows of the extras (-1: not owned here)
  Vector dinv_;                                 // D^-1 on the nodal rows, 0 elsewhere
  std::vector<Sparse> column_, rowScaled_;      // B_k (nodal part), D^-1 C_k^T
  std::vector<LO> touched_;                     // the rows of every B_k, each once
  Teuchos::SerialDenseMatrix<int, double> lu_;  // E - C D^-1 B, factored
  std::vector<int> pivots_;
};

}  // namespace impm
