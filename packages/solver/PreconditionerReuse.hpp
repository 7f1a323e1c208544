#pragma once
// A preconditioner kept across Newton iterations and across steps while it still pays.
//
// The Jacobian of one Newton iteration differs little from the last one's, and often from
// the last step's: rebuilding an incomplete factorisation or a multigrid hierarchy for
// every linear solve costs more than the few Krylov iterations it saves.  This factory wraps
// the deck's Stratimikos preconditioner factory and decides, each time NOX asks for a
// preconditioner, whether to build one:
//   - always when the unknowns changed (another row map: particles reached new nodes), or
//     when the last linear solve failed;
//   - when the last solve took more than `Rebuild Factor` times the iterations of the
//     first solve after the last build (at least `Minimum Iterations`), per decade of
//     residual reduction when the two solves had different tolerances (a Newton iteration
//     that needs less than Linear Tolerance stops early: solver/LinearTarget.hpp);
//   - at the start of a Newton solve (a new step), once a preconditioner carried into a
//     step went past that limit in its first solve (CarryState below);
//   - otherwise the preconditioner built from an earlier Jacobian stays: the Krylov solve
//     still solves the current Jacobian to its tolerance, so only the cost changes.  Rows
//     that hold their diagonal alone (nodes retired since the build) are then solved
//     exactly and the kept preconditioner serves the others (solver/DecoupledRows.hpp).
// With MueLu, a rebuild on unchanged unknowns keeps the aggregates and the tentative
// prolongator (MueLu's "reuse: type" tP) and recomputes the smoothed prolongator, the coarse
// operators and the smoothers; new unknowns
// start the hierarchy over, with the rigid-body modes of the new nodes as near-null space.
// A kept hierarchy works on the Jacobian it serves at its finest level (the fine residual
// and smoothers), the coarse levels staying those of its build (solver/FinestLevel.hpp).

#include <functional>

#include <Teuchos_ParameterList.hpp>
#include <Thyra_PreconditionerFactoryBase.hpp>

#include "core/TpetraTypes.hpp"
#include "solver/DecoupledRows.hpp"

namespace impm {

struct ReuseRules {
  double rebuildFactor = 2.0;
  int minimumIterations = 5;
};

// What the factory did, for the step's report.
struct ReuseCounts {
  int builds = 0;  // preconditioners computed (including refreshes on the same unknowns)
  int reuses = 0;  // requests served by the previous preconditioner
};

class ReusingPreconditionerFactory : public Thyra::PreconditionerFactoryBase<double> {
 public:
  // The near-null space of the operator being solved (MueLu), or null.
  using NullSpace = std::function<Teuchos::RCP<MultiVector>()>;

  // `inner`: the factory that builds the preconditioners; `muelu`: whether it is MueLu's
  // (which takes the near-null space).
  ReusingPreconditionerFactory(Teuchos::RCP<Thyra::PreconditionerFactoryBase<double>> inner,
                               bool muelu, const ReuseRules& rules);

  // The near-null space of the problem being solved (set by the Newton solver per solve).
  void setNullSpace(NullSpace nullSpace) { nullSpace_ = std::move(nullSpace); }
  // A new Newton solve (a step, or a step's retry) begins: its first request decides
  // whether the kept preconditioner is carried into it.
  void startSolve() { solveStarted_ = true; }
  // The outcome of the linear solve that used the current preconditioner, and the relative
  // residual tolerance it was asked for.
  void recordSolve(int iterations, bool converged, double tolerance);
  bool isMueLu() const { return muelu_; }
  ReuseCounts counts() const { return counts_; }
  // The next request builds a new preconditioner from scratch, as a fresh run would (a run
  // restarted from a checkpoint then follows the uninterrupted run's path bit for bit).
  void forget() {
    map_ = Teuchos::null;
    carry_ = CarryState{};
  }
  // The Newton solve ended (however): a kept MueLu hierarchy lets the solve's Jacobian go
  // (its finest level takes the next solve's when carried to it).  Collective.
  void endSolve() noexcept;
  // Frees `prec` (its hierarchy or factors, and its hold on the last Jacobian) unless it
  // was built for the unknowns `next`: one that cannot serve them would otherwise stay
  // alive while the next system is built.  Collective.
  void releaseUnlessFor(const Map& next, Thyra::PreconditionerBase<double>* prec) const;
  // Frees `prec` whatever it was built for; the next request builds anew.
  void release(Thyra::PreconditionerBase<double>* prec) const;

  bool isCompatible(const Thyra::LinearOpSourceBase<double>& fwdOpSrc) const override;
  Teuchos::RCP<Thyra::PreconditionerBase<double>> createPrec() const override;
  void initializePrec(const Teuchos::RCP<const Thyra::LinearOpSourceBase<double>>& fwdOpSrc,
                      Thyra::PreconditionerBase<double>* prec,
                      Thyra::ESupportSolveUse supportSolveUse) const override;
  void uninitializePrec(Thyra::PreconditionerBase<double>* prec,
                        Teuchos::RCP<const Thyra::LinearOpSourceBase<double>>* fwdOpSrc,
                        Thyra::ESupportSolveUse* supportSolveUse) const override;
  void setParameterList(const Teuchos::RCP<Teuchos::ParameterList>& list) override;
  Teuchos::RCP<Teuchos::ParameterList> getNonconstParameterList() override;
  Teuchos::RCP<Teuchos::ParameterList> unsetParameterList() override;

 private:
  bool worthRebuilding() const;
  // Frees what `prec` holds (its hierarchy or factors, and the operator it was built from).
  void startOver(Thyra::PreconditionerBase<double>* prec) const;
  // The decoupled rows of `op` if it is a matrix, none otherwise.
  static DecoupledRows decoupledRowsOf(const Tpetra::Operator<double, LO, GO, Node>& op);
  // Makes the kept preconditioner the operator of `prec`, for the Jacobian `op`: wrapped if
  // rows of `op` were decoupled since the build.  Collective.
  void serveKept(const Tpetra::Operator<double, LO, GO, Node>& op,
                 Thyra::PreconditionerBase<double>* prec) const;
  // Makes `op` the operator of `prec`.
  // (Non-const: MueLu refreshes the hierarchy it finds there.)
  static void serve(const Teuchos::RCP<Thyra::LinearOpBase<double>>& op,
                    Thyra::PreconditionerBase<double>* prec);

  Teuchos::RCP<Thyra::PreconditionerFactoryBase<double>> inner_;
  bool muelu_;
  ReuseRules rules_;
  NullSpace nullSpace_;
  // initializePrec() is const in Thyra's interface; what it remembers is not.
  mutable Teuchos::RCP<const Map> map_;  // the unknowns of the current preconditioner
  // The operator the inner factory built (served as it is, or wrapped).
  mutable Teuchos::RCP<Thyra::LinearOpBase<double>> kept_;
  // The decoupled rows of the Jacobian it was built from (MueLu's only).
  mutable DecoupledRows builtDecoupled_;
  mutable int firstIterations_ = -1;  // of the first solve after the last build
  mutable int lastIterations_ = 0;
  // -log10 of the two solves' tolerances (at least 1).
  mutable double firstDecades_ = 1.0, lastDecades_ = 1.0;
  mutable bool lastConverged_ = true;
  mutable ReuseCounts counts_;
  // A preconditioner kept from one Newton solve serves the next one's first linear solve (is
  // carried into the next step) while that pays.  The steps of a run move the particles by
  // much the same amounts, so one carry whose first solve goes past the rebuild limit stops
  // the carries until the preconditioner is forgotten (a checkpoint): on the 10^6-particle
  // column they took 66-443 Krylov iterations against about 20 for a new hierarchy, and the
  // long solves' round-off cost a second Newton iteration.  Reuse within a step goes on.
  struct CarryState {
    bool stopped = false;  // no more carries
    bool judging = false;  // the current preconditioner was carried; its first solve decides
  };
  mutable CarryState carry_;
  mutable bool solveStarted_ = false;
};

}  // namespace impm
