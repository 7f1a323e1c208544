#pragma once
// Newton's method through NOX (NOX::Thyra::Group over MpmModelEvaluator) with a Stratimikos
// linear solver.  Settings come from the deck's Solver sublist; every Newton iteration's
// residual norm and linear iteration count is recorded (and printed when asked).

#include <Teuchos_ParameterList.hpp>
#include <Thyra_LinearOpWithSolveFactoryBase.hpp>

#include <iosfwd>
#include <string>
#include <vector>

#include "solver/LinearSolver.hpp"
#include "solver/PreconditionerReuse.hpp"
#include "solver/ResidualModel.hpp"

namespace impm {

struct NewtonReport {
  bool converged = false;
  std::vector<double> residualNorms;  // ||R|| before the first and after every iteration
  std::vector<int> linearIterations;  // per Newton iteration
  std::string failure;                // why it stopped, when not converged
  // The first linear solve that stopped short of its tolerance (empty: none did): named in
  // `failure` when the step fails, since an inexact direction is then its likely cause.
  std::string unconvergedSolve;

  int iterations() const { return static_cast<int>(linearIterations.size()); }
  int totalLinearIterations() const;
};

class NewtonSolver {
 public:
  // Valid parameters of the deck's Solver sublist.
  static Teuchos::ParameterList validParameters();

  // `params`: a validated Solver sublist.  Builds (and checks) the linear solver, the deck's
  // list over the default for `kind` in `dim` dimensions.
  NewtonSolver(const Teuchos::ParameterList& params, const Teuchos::RCP<const Comm>& comm,
               OperatorKind kind = OperatorKind::small, int dim = 1);

  // Solves R(x) = 0 from the guess in x; x holds the last iterate on return.  Collective.
  // The preconditioner of the last solve may serve this one (solver/PreconditionerReuse).
  NewtonReport solve(const Teuchos::RCP<ResidualModel>& model, Vector& x) const;

  // The next solve builds its preconditioner from scratch (at checkpoints: the preconditioner
  // is a cache, and a restarted run starts with an empty one).
  void forgetPreconditioner() const {
    if (!reuse_.is_null())
      reuse_->forget();
  }
  // Frees the kept preconditioner unless it was built for the unknowns `next` (the next
  // system's, before its graph and matrix are built: the peak memory of a step).  Collective.
  void releasePreconditionerUnlessFor(const Map& next) const {
    if (!reuse_.is_null())
      reuse_->releaseUnlessFor(next, prec_.get());
  }
  // Frees the kept preconditioner: the next solve builds its own (the unknowns are the same,
  // but some are now fixed: solver/SystemLayout.hpp).
  void releasePreconditioner() const {
    if (!reuse_.is_null())
      reuse_->release(prec_.get());
  }
  // Whether the kept preconditioner also serves once nodes retire (solver/SystemLayout.hpp):
  // a multigrid hierarchy kept while Preconditioner Reuse is on.
  bool preconditionerServesRetiredNodes() const { return !reuse_.is_null() && reuse_->isMueLu(); }
  // Preconditioners built and reused so far (zeros without a preconditioner).
  ReuseCounts preconditionerCounts() const {
    return reuse_.is_null() ? ReuseCounts{} : reuse_->counts();
  }

  // The Stratimikos strategy, for the other linear solves of a step (mass projections).
  const Teuchos::RCP<Thyra::LinearOpWithSolveFactoryBase<double>>& linearSolveStrategy() const {
    return lows_;
  }

  // The linear solver the Newton iterations use, in a few words (describeLinearSolver).
  const std::string& linearSolverName() const { return linearSolverName_; }

  // Where per-iteration lines go (rank 0 only); null: nowhere.
  void setLog(std::ostream* log, const std::string& indent) {
    log_ = log;
    indent_ = indent;
  }

 private:
  Teuchos::RCP<const Comm> comm_;
  Teuchos::RCP<Thyra::LinearOpWithSolveFactoryBase<double>> lows_;
  // The Newton solves' preconditioner, kept from one solve to the next (null: no reuse).
  Teuchos::RCP<ReusingPreconditionerFactory> reuse_;
  Teuchos::RCP<Thyra::PreconditionerBase<double>> prec_;
  Teuchos::ParameterList noxParams_;
  double relativeTolerance_, absoluteTolerance_, updateTolerance_, linearTolerance_,
      roundOffFactor_;
  bool adaptiveLinearTolerance_;
  bool rigidBodyModes_;  // hand MueLu the model's near-null space (else MueLu's own)
  int maxIterations_;
  std::ostream* log_ = nullptr;
  std::string indent_;
  std::string linearSolverName_;
};

}  // namespace impm
