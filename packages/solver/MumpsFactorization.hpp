#pragma once
// A sparse direct factorisation of a distributed Tpetra matrix by MUMPS (Amestoy, Duff,
// L'Excellent & Koster, SIAM J. Matrix Anal. Appl. 23, 2001; Debian's libmumps), the
// multifrontal LU (or LDL^T) with a fill-reducing ordering.
//
// MUMPS runs on rank 0 alone: the ranks' rows are gathered there (centralised assembled
// input, ICNTL(18) = 0), and so are the right-hand sides; the solution is scattered back.  Its
// distributed factorisation was tried and not kept: it picks the processes of its parallel
// fronts at run time by their load and sums the children's contributions in the order their
// messages arrive, so on a loaded machine the last bits of the solution changed from run to
// run (the colliding disks' history, 1 run in 3 on 2 ranks), and a restart was no longer bit
// for bit the uninterrupted run.  One process is deterministic; on the 2-core reference machine
// it also costs little (doc/performance.md).  MUMPS numbers the unknowns 1..n; the matrix's
// rows are renumbered rank by rank in their local order, so any row map serves.
//
// The ordering and the symbolic analysis are kept while the matrix's pattern stays the same
// (the Newton iterations of one load step); only the numerical factorisation is then redone.

#include <memory>
#include <string>
#include <vector>

#include "core/TpetraTypes.hpp"

namespace impm {

struct MumpsOptions {
  // LDL^T of the lower triangle (MUMPS's SYM = 2) instead of LU: half the work and memory,
  // for symmetric matrices only.
  bool symmetric = false;
  // The fill-reducing ordering (ICNTL(7)): "automatic" (MUMPS chooses), "amd", "amf", "qamd",
  // "pord", "scotch" or "metis".
  std::string ordering = "automatic";
  // Extra working space over MUMPS's estimate, percent (ICNTL(14)); doubled and the
  // factorisation retried (twice at most) when MUMPS runs out of it.
  int workspaceIncrease = 30;
};

class MumpsFactorization {
 public:
  // Collective over `comm`.
  MumpsFactorization(const Teuchos::RCP<const Comm>& comm, const MumpsOptions& options);
  ~MumpsFactorization();
  MumpsFactorization(const MumpsFactorization&) = delete;
  MumpsFactorization& operator=(const MumpsFactorization&) = delete;

  // Factorises A, square with its domain and range maps equal to its row map.  Collective.
  // Throws NumericalError on every rank when A is numerically singular (a zero pivot) or
  // MUMPS fails otherwise (its INFOG(1) and INFOG(2) in the message).
  void factor(const CrsMatrix& A);
  // X = A^-1 B, for the A of the last factor().  Collective.
  void solve(const MultiVector& B, MultiVector& X) const;

  // Symbolic analyses and numerical factorisations so far.
  int analyses() const { return analyses_; }
  int factorizations() const { return factorizations_; }

 private:
  struct Instance;  // MUMPS's own structure
  // Runs MUMPS's phase `job`; throws NumericalError naming `what` when it fails.
  void run(int job, const std::string& what) const;
  // The 1-based MUMPS indices of A's entries on this rank (the lower triangle when symmetric).
  void entries(const CrsMatrix& A, std::vector<int>& rows, std::vector<int>& columns,
               std::vector<double>& values) const;
  // Analyses (when the pattern changed) and factorises the gathered entries (rank 0).
  void factorOnRoot(std::vector<int>& rows, std::vector<int>& columns);

  Teuchos::RCP<const Comm> comm_;
  MumpsOptions options_;
  std::unique_ptr<Instance> mumps_;
  std::vector<int> rows_, columns_;  // the analysed pattern (rank 0)
  std::vector<double> values_;       // the factorised values (rank 0; MUMPS reads them in place)
  Teuchos::RCP<const Map> rowMap_, contiguous_, root_;
  Teuchos::RCP<const Import> gather_;  // contiguous rows -> all rows on rank 0
  int analyses_ = 0, factorizations_ = 0;
};

}  // namespace impm
