#pragma once
// The exact inverse of a distributed matrix from exact solves with its ranks' diagonal
// blocks.  Write A = D + E, D the ranks' diagonal blocks (block Jacobi), E the entries that
// couple a rank's rows to other ranks' unknowns.  E touches few columns, the unknowns near
// the ranks' boundaries (the interface, m of them): E = U V^T, where V^T picks the interface
// columns and U holds their entries in other ranks' rows.  The Sherman-Morrison-Woodbury
// identity gives
//
//   A^-1 = D^-1 - S (I + V^T S)^-1 V^T D^-1,   S = D^-1 U,
//
// so after y = D^-1 b, x = y - S h with (I + V^T S) h = V^T y.  S (the "spikes" of the
// SPIKE algorithm for banded matrices) is one local solve per interface column a rank's rows
// couple to, at set-up; the m x m matrix I + V^T S is summed onto every rank and factorised
// there (LAPACK's dgetrf).  An application costs one sum of m values per vector across the
// ranks.  I + V^T S is singular only when A is (det A = det D det(I + V^T S)).

#include <functional>
#include <vector>

#include "core/TpetraTypes.hpp"

namespace impm {

class RankCoupling {
 public:
  // Solves D_rank X = B in place for nrhs columns of this rank's length (column-major).
  using LocalSolve = std::function<void(double* B, int nrhs)>;

  // rowOfColumn[c]: the local row of A's local column c, negative for another rank's unknown.
  // Collective.  Throws NumericalError when I + V^T S is singular.
  RankCoupling(const CrsMatrix& A, const std::vector<LO>& rowOfColumn, const LocalSolve& solve);

  // Y holds D^-1 B on entry and A^-1 B on return.  Collective.
  void correct(MultiVector& Y) const;

  // m, the unknowns that rows of other ranks couple to (0 when the blocks do not couple).
  int interfaceSize() const { return m_; }

 private:
  Teuchos::RCP<const Comm> comm_;
  int n_ = 0, m_ = 0;
  std::vector<int> spikeColumn_;  // each spike's interface column
  std::vector<double> spikes_;    // S on this rank's rows, n x spikes, column-major
  std::vector<std::pair<LO, int>> interfaceRows_;  // (local row, interface column) of own rows
  std::vector<double> capacitance_;                // the LU of I + V^T S, m x m
  std::vector<int> pivots_;
};

}  // namespace impm
