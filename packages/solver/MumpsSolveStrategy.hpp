#pragma once
// The Stratimikos linear solver type "MUMPS": a sparse direct solve of the grid system
// (solver/MumpsFactorization.hpp), on any number of ranks.  createLinearSolveStrategy
// registers it; a deck names it with
//
//   <Parameter name="Linear Solver Type" type="string" value="MUMPS"/>
//
// and sets its options in "Linear Solver Types"/"MUMPS" ("Symmetric", "Ordering",
// "Workspace Increase").  It takes no preconditioner.  Each linear operator it is given is
// factorised once; an operator initialised again (the next Newton iteration's Jacobian)
// keeps its MUMPS instance and, while the pattern is the same, the symbolic analysis.

#include <Thyra_LinearOpWithSolveFactoryBase.hpp>

#include "solver/MumpsFactorization.hpp"

namespace impm {

class MumpsSolveStrategy : public Thyra::LinearOpWithSolveFactoryBase<double> {
 public:
  bool isCompatible(const Thyra::LinearOpSourceBase<double>& fwdOpSrc) const override;
  Teuchos::RCP<Thyra::LinearOpWithSolveBase<double>> createOp() const override;
  void initializeOp(const Teuchos::RCP<const Thyra::LinearOpSourceBase<double>>& fwdOpSrc,
                    Thyra::LinearOpWithSolveBase<double>* op,
                    Thyra::ESupportSolveUse supportSolveUse) const override;
  // A preconditioner given with the operator is not used: the solve is exact.
  bool supportsPreconditionerInputType(Thyra::EPreconditionerInputType) const override {
    return false;
  }
  void initializePreconditionedOp(
      const Teuchos::RCP<const Thyra::LinearOpSourceBase<double>>& fwdOpSrc,
      const Teuchos::RCP<const Thyra::PreconditionerBase<double>>& prec,
      Thyra::LinearOpWithSolveBase<double>* op,
      Thyra::ESupportSolveUse supportSolveUse) const override;
  void initializeApproxPreconditionedOp(
      const Teuchos::RCP<const Thyra::LinearOpSourceBase<double>>& fwdOpSrc,
      const Teuchos::RCP<const Thyra::LinearOpSourceBase<double>>& approxFwdOpSrc,
      Thyra::LinearOpWithSolveBase<double>* op,
      Thyra::ESupportSolveUse supportSolveUse) const override;
  void uninitializeOp(Thyra::LinearOpWithSolveBase<double>* op,
                      Teuchos::RCP<const Thyra::LinearOpSourceBase<double>>* fwdOpSrc,
                      Teuchos::RCP<const Thyra::PreconditionerBase<double>>* prec,
                      Teuchos::RCP<const Thyra::LinearOpSourceBase<double>>* approxFwdOpSrc,
                      Thyra::ESupportSolveUse* supportSolveUse) const override;

  void setParameterList(const Teuchos::RCP<Teuchos::ParameterList>& list) override;
  Teuchos::RCP<Teuchos::ParameterList> getNonconstParameterList() override { return list_; }
  Teuchos::RCP<Teuchos::ParameterList> unsetParameterList() override;
  Teuchos::RCP<const Teuchos::ParameterList> getParameterList() const override { return list_; }
  Teuchos::RCP<const Teuchos::ParameterList> getValidParameters() const override;

 private:
  Teuchos::RCP<Teuchos::ParameterList> list_;
  MumpsOptions options_;
};

}  // namespace impm
