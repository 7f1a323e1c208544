#include "solver/NewtonSolver.hpp"

#include <NOX.H>
#include <NOX_Solver_LineSearchBased.H>
#include <NOX_Thyra.H>
#include <NOX_Thyra_Vector.H>
#include <NOX_Observer.hpp>
#include <NOX_Observer_Vector.hpp>
#include <NOX_SolverStats.hpp>
#include <Thyra_TpetraThyraWrappers.hpp>

#include <cmath>
#include <functional>
#include <iomanip>
#include <limits>
#include <ostream>
#include <sstream>

#include "core/CapturedOutput.hpp"
#include "core/Errors.hpp"
#include "core/StopRequest.hpp"

#include "core/Parameters.hpp"
#include "solver/LinearSolver.hpp"
#include "solver/LinearTarget.hpp"
#include "solver/ModelEvaluator.hpp"
#include "solver/NoxChoices.hpp"
#include "solver/RoundOffTest.hpp"

namespace impm {

namespace {

double stepLength(const NOX::Solver::Generic& solver) {
  const auto* lineSearch = dynamic_cast<const NOX::Solver::LineSearchBased*>(&solver);
  return lineSearch ? lineSearch->getStepSize() : 1.0;
}

// ||d|| / ||x_k||: the size of the last Newton direction d relative to the iterate, where
// x_k - x_(k-1) = step d (the line search may have shortened the step).
double relativeUpdate(const NOX::Solver::Generic& solver) {
  const auto& x = solver.getSolutionGroup().getX();
  auto dx = x.clone(NOX::DeepCopy);
  dx->update(-1.0, solver.getPreviousSolutionGroup().getX(), 1.0);
  const double nx = x.norm(), nd = dx->norm() / stepLength(solver);
  return nx > 0 ? nd / nx : (nd == 0 ? 0.0 : std::numeric_limits<double>::infinity());
}

// Converged when the Newton direction is smaller than `tolerance` relative to the iterate.
// The residual of a displacement discretisation has a round-off floor that grows with the
// number of cells (the strain F - 1 = sum_i G_ip u_i cancels terms of size |u|/h), so a
// relative residual test alone cannot pass on fine grids; the Newton direction, that floor
// damped by K^-1, can.  (At the floor the line search may also shorten steps.)
class RelativeUpdate : public NOX::StatusTest::Generic {
 public:
  explicit RelativeUpdate(double tolerance) : tolerance_(tolerance) {}
  NOX::StatusTest::StatusType checkStatus(const NOX::Solver::Generic& solver,
                                          NOX::StatusTest::CheckType /*type*/) override {
    status_ = NOX::StatusTest::Unconverged;
    if (solver.getNumIterations() == 0)
      return status_;
    ratio_ = relativeUpdate(solver);
    if (ratio_ <= tolerance_)
      status_ = NOX::StatusTest::Converged;
    return status_;
  }
  NOX::StatusTest::StatusType getStatus() const override { return status_; }
  std::ostream& print(std::ostream& out, int indent = 0) const override {
    for (int k = 0; k < indent; ++k)
      out << ' ';
    return out << status_ << " relative update " << ratio_ << " <= " << tolerance_ << "\n";
  }

 private:
  double tolerance_, ratio_ = 0.0;
  NOX::StatusTest::StatusType status_ = NOX::StatusTest::Unevaluated;
};

// The line-search step length, when it was not a full Newton step.
std::string stepNote(const NOX::Solver::Generic& solver) {
  if (stepLength(solver) == 1.0)
    return "";
  std::ostringstream s;
  s << "  (line search step " << stepLength(solver) << ")";
  return s.str();
}

// A linear system is solved by one Newton step whose linear solve converged.
class LinearSystemSolved : public NOX::StatusTest::Generic {
 public:
  NOX::StatusTest::StatusType checkStatus(const NOX::Solver::Generic& solver,
                                          NOX::StatusTest::CheckType /*type*/) override {
    const auto stats = solver.getSolverStatistics();
    status_ = solver.getNumIterations() >= 1 && stepLength(solver) == 1.0 &&
                      stats->linearSolve.lastLinearSolve_Converged
                  ? NOX::StatusTest::Converged
                  : NOX::StatusTest::Unconverged;
    return status_;
  }
  NOX::StatusTest::StatusType getStatus() const override { return status_; }
  std::ostream& print(std::ostream& out, int indent = 0) const override {
    for (int k = 0; k < indent; ++k)
      out << ' ';
    return out << status_ << " linear system solved\n";
  }

 private:
  NOX::StatusTest::StatusType status_ = NOX::StatusTest::Unevaluated;
};

// Records ||R|| and the linear iterations of every Newton iteration.
class IterationRecorder : public NOX::Observer {
 public:
  // `nox`: the solver's list, with the "Tolerance" each linear solve was given.
  IterationRecorder(NewtonReport& report, std::ostream* log, const std::string& indent,
                    ReusingPreconditionerFactory* reuse, Teuchos::ParameterList& nox)
      : report_(report), log_(log), indent_(indent), reuse_(reuse), nox_(nox) {}

  void runPostIterate(const NOX::Solver::Generic& solver) override {
    const double norm = solver.getSolutionGroup().getNormF();
    const auto stats = solver.getSolverStatistics();
    const int linear = stats->linearSolve.lastLinearSolve_NumIterations;
    if (reuse_)
      reuse_->recordSolve(linear, stats->linearSolve.lastLinearSolve_Converged,
                          linearSolveList(nox_).get<double>("Tolerance"));
    const double update = relativeUpdate(solver);
    report_.residualNorms.push_back(norm);
    report_.linearIterations.push_back(linear);
    if (!stats->linearSolve.lastLinearSolve_Converged && report_.unconvergedSolve.empty()) {
      std::ostringstream note;
      const double achieved = stats->linearSolve.lastLinearSolve_AchievedTolerance;
      note << "the linear solve of Newton iteration " << report_.iterations()
           << " stopped short of its tolerance " << linearSolveList(nox_).get<double>("Tolerance")
           << " after " << linear << " iterations";
      if (achieved > 0.0)
        note << " (relative residual " << achieved << ")";
      note << ", and |R| went from " << report_.residualNorms[report_.residualNorms.size() - 2]
           << " to " << norm;
      report_.unconvergedSolve = note.str();
    }
    if (log_)
      *log_ << indent_ << "newton " << std::setw(2) << report_.iterations()
            << "  |R| = " << std::scientific << std::setprecision(3) << norm
            << "  |dx|/|x| = " << update << "  linear iterations " << linear << std::defaultfloat
            << stepNote(solver) << "\n";
  }

 private:
  NewtonReport& report_;
  std::ostream* log_;
  std::string indent_;
  ReusingPreconditionerFactory* reuse_;
  Teuchos::ParameterList& nox_;
};

}  // namespace

int NewtonReport::totalLinearIterations() const {
  int total = 0;
  for (int n : linearIterations)
    total += n;
  return total;
}

Teuchos::ParameterList NewtonSolver::validParameters() {
  Teuchos::ParameterList valid;
  declareChoice(valid, "Line Search", "Backtrack", {"Full Step", "Backtrack", "Polynomial"},
                "NOX line search of each Newton iteration");
  declareInt(valid, "Maximum Iterations", 20, "Newton iterations before a step counts as failed",
             Bounds::atLeast(1));
  declareDouble(valid, "Relative Tolerance", 1e-10,
                "Converged when ||R|| <= this times ||R|| of the initial guess",
                Bounds::positive());
  declareDouble(valid, "Round-off Factor", 1.0,
                "Also converged when ||R|| <= this times eps || |K| |x| || (0: not used), the "
                "change of R that rounding the unknowns x to doubles can cause (K = dR/dx, "
                "absolute values entry by entry): the residual's round-off floor",
                Bounds::nonNegative());
  declareDouble(valid, "Update Tolerance", 1e-9,
                "Also converged when the Newton direction is smaller than this relative to the "
                "unknowns (0: not used); needed on fine grids, where round-off bounds "
                "how far the residual can fall",
                Bounds::nonNegative());
  declareDouble(valid, "Absolute Tolerance", 0.0, "Also converged when ||R|| <= this (0: not used)",
                Bounds::nonNegative());
  declareDouble(valid, "Linear Tolerance", 1e-10,
                "Relative residual tolerance of each linear solve (overrides the Belos list's); "
                "see Adaptive Linear Tolerance",
                Bounds::positive());
  declareBool(valid, "Adaptive Linear Tolerance", true,
              "A Newton iteration whose ||R|| is near Newton's target solves its linear system "
              "only as far as the target needs: to 0.5 target / ||R|| (at most 0.1) when that is "
              "looser than Linear Tolerance (false: every solve to Linear Tolerance, for results "
              "that agree to round-off across rank counts or discretisations, or Newton's "
              "quadratic convergence seen to the end)");
  declareChoice(valid, "Preconditioner Reuse", "auto", {"auto", "on", "off"},
                "Keep the preconditioner across Newton iterations and steps while the unknowns "
                "stay the same and the Krylov iterations do not grow past Rebuild Factor times "
                "those right after it was built; once a step's first solve on the last step's "
                "preconditioner grows past that, later steps start with a new one until the next "
                "checkpoint (off: a new one for every linear solve; auto: on with the multigrid "
                "default of 2-D and 3-D stiffness-dominated steps)");
  declareDouble(valid, "Rebuild Factor", 2.0,
                "With Preconditioner Reuse: rebuild when a linear solve takes more than this "
                "times the iterations of the first solve after the last build (at least 5; per "
                "decade of residual reduction when their tolerances differ)",
                Bounds::atLeast(1.0));
  declareChoice(valid, "Near Null Space", "rigid-body modes", {"rigid-body modes", "translations"},
                "The vectors MueLu's smoothed aggregation must reproduce on its coarse levels, "
                "with Preconditioner Reuse on: the grid's rigid-body modes from the nodal "
                "coordinates (1 in 1-D, 3 in 2-D, 6 in 3-D) or only the translations (MueLu's "
                "own default: one constant vector per unknown of a node; without reuse MueLu "
                "always takes these)");
  declareBool(valid, "Graph Reuse", true,
              "Keep a step's unknowns, graph and importer for the next steps while the "
              "(particle, node) pairs, the boundary conditions' nodes and the ownership of the "
              "nodes stay the same (false: build them every step; the results are the same)");
  declareBool(valid, "Print Iterations", true,
              "Print every Newton iteration's residual norm and linear iteration count");
  declareOpaque(valid, "Linear Solver",
                "A Stratimikos parameter list, merged over impm's default for the problem (1-D: "
                "GMRES + the banded LU; grids under 4000 nodes (3-D: 300) and stiffness-dominated "
                "steps with a non-symmetric tangent (plasticity): the MUMPS direct solver; "
                "symmetric ones: CG + MueLu smoothed aggregation; mass-dominated steps: CG + "
                "Jacobi; see the user guide); MUMPS (Linear Solver Type), Ifpack2 and MueLu are "
                "registered.  Checked by Stratimikos, Belos, Ifpack2 and MueLu at start-up.");
  declareOpaque(valid, "NOX",
                "Extra NOX parameters (a NOX::Solver list), merged over the ones impm sets.  "
                "Checked by NOX.");
  return valid;
}

NewtonSolver::NewtonSolver(const Teuchos::ParameterList& params,
                           const Teuchos::RCP<const Comm>& comm, OperatorKind kind, int dim)
    : comm_(comm),
      relativeTolerance_(params.get<double>("Relative Tolerance")),
      absoluteTolerance_(params.get<double>("Absolute Tolerance")),
      updateTolerance_(params.get<double>("Update Tolerance")),
      linearTolerance_(params.get<double>("Linear Tolerance")),
      roundOffFactor_(params.get<double>("Round-off Factor")),
      adaptiveLinearTolerance_(params.get<bool>("Adaptive Linear Tolerance")),
      rigidBodyModes_(params.get<std::string>("Near Null Space") == "rigid-body modes"),
      maxIterations_(params.get<int>("Maximum Iterations")) {
  // The deck's lists are merged over impm's; a value where impm has a sublist (or the
  // reverse) is the deck's mistake.
  const auto merged = [](const std::string& path, const std::function<void()>& merge) {
    try {
      merge();
    } catch (const std::exception& e) {
      throw InputError(path, trilinosMessage(e.what()));
    }
  };
  Teuchos::ParameterList linear;
  merged("Solver/Linear Solver", [&] {
    linear =
        mergedLinearSolverParameters(params.sublist("Linear Solver"), kind, dim, comm->getSize());
  });
  lows_ = createLinearSolveStrategy(linear, comm, "Solver/Linear Solver");
  linearSolverName_ = describeLinearSolver(linear);
  // Reuse pays where building costs many Krylov iterations (multigrid); an ILUT of a small
  // system costs less than the iterations a stale one adds, and on the nearly singular
  // systems of nodes that barely touch a body a stale one can stall Newton.  Without reuse
  // the strategy builds a preconditioner for every linear solve.
  const auto& reuse = params.get<std::string>("Preconditioner Reuse");
  const bool stiffness =
      kind == OperatorKind::stiffness || kind == OperatorKind::symmetricStiffness;
  const bool reuseOn = reuse == "on" || (reuse == "auto" && stiffness);
  if (auto inner = lows_->getPreconditionerFactory(); reuseOn && !inner.is_null()) {
    ReuseRules rules;
    rules.rebuildFactor = params.get<double>("Rebuild Factor");
    reuse_ = Teuchos::rcp(new ReusingPreconditionerFactory(
        inner, linear.get<std::string>("Preconditioner Type") == "MueLu", rules));
    prec_ = reuse_->createPrec();
  }
  auto& p = noxParams_;
  p.set("Nonlinear Solver", "Line Search Based");
  p.sublist("Line Search").set("Method", params.get<std::string>("Line Search"));
  p.sublist("Direction").set("Method", "Newton");
  auto& newton = p.sublist("Direction").sublist("Newton");
  newton.set("Forcing Term Method", "Constant");
  newton.sublist("Linear Solver").set("Tolerance", linearTolerance_);
  p.sublist("Printing").set("Output Information", NOX::Utils::Error);
  // The deck's NOX list may set the linear tolerance itself; it is then the tightest one.
  merged("Solver/NOX", [&] {
    p.setParameters(params.sublist("NOX"));
    linearTolerance_ =
        p.sublist("Direction").sublist("Newton").sublist("Linear Solver").get<double>("Tolerance");
  });
  checkNoxList(p, comm);
}

NewtonReport NewtonSolver::solve(const Teuchos::RCP<ResidualModel>& model, Vector& x) const {
  NewtonReport report;
  std::ostream* log = (log_ && comm_->getRank() == 0) ? log_ : nullptr;
  auto me = Teuchos::rcp(new MpmModelEvaluator(model, lows_));
  auto guess = Thyra::createVector<double, LO, GO, Node>(Teuchos::rcpFromRef(x), me->get_x_space());
  // The reuse factory asks for the near-null space only while this model is being solved;
  // it must not keep the model alive after this solve, nor its hierarchy the solve's
  // Jacobian, however the solve ends.
  struct SolveLease {
    ReusingPreconditionerFactory* reuse;
    ~SolveLease() {
      if (reuse) {
        reuse->setNullSpace(nullptr);
        reuse->endSolve();
      }
    }
  } lease{reuse_.get()};
  if (lease.reuse) {
    if (rigidBodyModes_)
      lease.reuse->setNullSpace([model] { return model->nearNullSpace(); });
    lease.reuse->startSolve();
  }
  auto group = Teuchos::rcp(new NOX::Thyra::Group(NOX::Thyra::Vector(guess), me, me->create_W_op(),
                                                  lows_, prec_, reuse_, Teuchos::null));
  try {
    group->computeF();
  } catch (const NumericalError& e) {  // not finite, or a law outside its domain, at the guess
    report.failure = e.what();
    return report;
  }
  const double initial = group->getNormF();
  report.residualNorms.push_back(initial);
  if (log)
    *log << indent_ << "newton  0  |R| = " << std::scientific << std::setprecision(3) << initial
         << std::defaultfloat << "\n";
  if (initial == 0.0 || initial <= absoluteTolerance_) {
    report.converged = true;
    return report;
  }

  using namespace NOX::StatusTest;
  auto converged = Teuchos::rcp(new Combo(Combo::OR));
  converged->addStatusTest(Teuchos::rcp(new NormF(*group, relativeTolerance_)));
  if (absoluteTolerance_ > 0)
    converged->addStatusTest(Teuchos::rcp(new NormF(absoluteTolerance_)));
  // The update test first: it is a vector norm, the round-off test a pass over the Jacobian
  // (NOX's minimal check skips the tests after the first that passes).
  if (updateTolerance_ > 0)
    converged->addStatusTest(Teuchos::rcp(new RelativeUpdate(updateTolerance_)));
  if (roundOffFactor_ > 0)
    converged->addStatusTest(Teuchos::rcp(new RoundOffResidual(roundOffFactor_, *model)));
  if (model->isLinear())
    converged->addStatusTest(Teuchos::rcp(new LinearSystemSolved));
  auto tests = Teuchos::rcp(new Combo(Combo::OR));
  tests->addStatusTest(Teuchos::rcp(new FiniteValue));
  tests->addStatusTest(converged);
  tests->addStatusTest(Teuchos::rcp(new MaxIters(maxIterations_)));

  auto params = Teuchos::rcp(new Teuchos::ParameterList(noxParams_));
  auto observers = Teuchos::rcp(new NOX::ObserverVector);
  observers->pushBack(
      Teuchos::rcp(new IterationRecorder(report, log, indent_, reuse_.get(), *params)));
  // A linear step is solved by its first iteration (LinearSystemSolved); a forcing term in
  // the deck's NOX list sets the tolerance itself.
  const auto& newton = params->sublist("Direction").sublist("Newton");
  if (adaptiveLinearTolerance_ && !model->isLinear() &&
      newton.get<std::string>("Forcing Term Method") == "Constant")
    observers->pushBack(Teuchos::rcp(new LinearTarget(
        *params, linearTolerance_, std::max(relativeTolerance_ * initial, absoluteTolerance_))));
  params->sublist("Solver Options").set<Teuchos::RCP<NOX::Observer>>("Observer", observers);
  auto solver = NOX::Solver::buildSolver(group, tests, params);
  StatusType status = Unconverged;
  std::string printed;  // what the linear solvers printed (Ifpack2 a zero pivot, say)
  {
    const CapturedOutput quiet(CapturedOutput::Streams::error);
    try {
      status = solver->solve();
    } catch (const StopRequest&) {
      throw;  // not a failure of the step: the run stops (core/StopRequest.hpp)
    } catch (const NumericalError& e) {
      report.failure = e.what();
    } catch (const std::exception& e) {
      // Belos and Ifpack2 report breakdowns (NaN residuals, singular factors) by throwing.
      report.failure = "linear solver failure: " + trilinosMessage(e.what());
    }
    printed = quiet.firstLine();
  }

  const auto& solution = dynamic_cast<const NOX::Thyra::Vector&>(solver->getSolutionGroup().getX());
  auto tpetra = Thyra::TpetraOperatorVectorExtraction<double, LO, GO, Node>::getConstTpetraVector(
      solution.getThyraRCPVector());
  Tpetra::deep_copy(x, *tpetra);
  report.converged = status == Converged;
  if (!report.converged && report.failure.empty()) {
    const double last = report.residualNorms.back();
    report.failure = !std::isfinite(last) ? "the residual is not finite"
                     : report.iterations() >= maxIterations_
                         ? "no convergence in " + std::to_string(maxIterations_) + " iterations"
                         : "NOX stopped (line search or linear solve failure)";
  }
  if (!report.converged && !report.unconvergedSolve.empty() &&
      report.failure.rfind("linear solver failure", 0) != 0)
    report.failure =
        "linear solver failure: " + report.unconvergedSolve + "; then " + report.failure;
  if (!report.converged && !printed.empty())
    report.failure += "; the linear solver printed: " + printed;
  return report;
}

}  // namespace impm
