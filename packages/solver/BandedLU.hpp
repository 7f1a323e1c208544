#pragma once
// The exact LU of a banded matrix, by LAPACK (dgbtrf/dgbtrs through Teuchos::LAPACK; BLAS's
// banded triangular solves when no rows were exchanged) on each rank's diagonal block.  On several
// ranks the couplings between the blocks are restored exactly by a RankCoupling
// (solver/RankCoupling.hpp), so the operator is A^-1 on any number of ranks; or, asked to, left
// out: block Jacobi.  The matrix of a column a few cells wide is banded (its rows couple nodes a
// few cells apart), so the band holds all of its fill-in.
//
// This is what Ifpack2's block relaxation with a "Banded" container computes; that one
// copies the rows out through a row view per row (Kokkos reference counts and strided
// views), which took four fifths of its set-up, five times LAPACK's factorisation
// (doc/performance.md).  Here the band is filled from the local CRS arrays in one pass.
//
// The Stratimikos preconditioner type "Banded LU" (createLinearSolveStrategy registers it);
// its one parameter, "Across Ranks", is "exact" (the default) or "block Jacobi".

#include <Thyra_PreconditionerFactoryBase.hpp>
#include <Tpetra_Operator.hpp>
#include <memory>

#include "core/TpetraTypes.hpp"
#include "solver/RankCoupling.hpp"

namespace impm {

class BandedLU : public Tpetra::Operator<double, LO, GO, Node> {
 public:
  // Factorises the rows of A on this rank, restricted to its own columns, and with
  // `acrossRanks` the coupling of the ranks' blocks.  Collective.  Throws NumericalError on
  // every rank when a block is singular (naming the first zero pivot's unknown).
  explicit BandedLU(const CrsMatrix& A, bool acrossRanks = true);

  Teuchos::RCP<const Map> getDomainMap() const override { return domain_; }
  Teuchos::RCP<const Map> getRangeMap() const override { return range_; }
  // Y = alpha A^-1 X + beta Y (A_block^-1 without the coupling).  Collective.
  void apply(const MultiVector& X, MultiVector& Y, Teuchos::ETransp mode = Teuchos::NO_TRANS,
             double alpha = 1.0, double beta = 0.0) const override;

  int lowerBandwidth() const { return kl_; }
  int upperBandwidth() const { return ku_; }
  // Whether partial pivoting exchanged rows of this rank's block (then dgbtrs solves).
  bool interchangedRows() const { return interchanged_; }
  // The unknowns coupling the ranks' blocks (0 on one rank, or without the coupling).
  int interfaceSize() const { return coupling_ ? coupling_->interfaceSize() : 0; }

 private:
  // B = A^-1 B (A_block^-1 B without the coupling).
  void solveInPlace(MultiVector& B) const;
  // The nrhs columns of length n_ at B = A_block^-1 B.
  void solveBlock(double* B, int nrhs) const;

  Teuchos::RCP<const Map> domain_, range_;
  int n_ = 0, kl_ = 0, ku_ = 0;
  std::vector<double> band_;  // LAPACK's band storage, 2 kl + ku + 1 rows per column
  std::vector<int> pivots_;
  bool interchanged_ = false;  // whether the factorisation exchanged any rows
  std::unique_ptr<RankCoupling> coupling_;
};

class BandedLUFactory : public Thyra::PreconditionerFactoryBase<double> {
 public:
  bool isCompatible(const Thyra::LinearOpSourceBase<double>& fwdOpSrc) const override;
  Teuchos::RCP<Thyra::PreconditionerBase<double>> createPrec() const override;
  void initializePrec(const Teuchos::RCP<const Thyra::LinearOpSourceBase<double>>& fwdOpSrc,
                      Thyra::PreconditionerBase<double>* prec,
                      Thyra::ESupportSolveUse supportSolveUse) const override;
  void uninitializePrec(Thyra::PreconditionerBase<double>* prec,
                        Teuchos::RCP<const Thyra::LinearOpSourceBase<double>>* fwdOpSrc,
                        Thyra::ESupportSolveUse* supportSolveUse) const override;
  void setParameterList(const Teuchos::RCP<Teuchos::ParameterList>& list) override;
  Teuchos::RCP<Teuchos::ParameterList> getNonconstParameterList() override { return list_; }
  Teuchos::RCP<Teuchos::ParameterList> unsetParameterList() override;
  Teuchos::RCP<const Teuchos::ParameterList> getValidParameters() const override;

 private:
  Teuchos::RCP<Teuchos::ParameterList> list_;
};

}  // namespace impm
