#include "solver/LinearSolver.hpp"

#include <algorithm>

#include <Stratimikos_DefaultLinearSolverBuilder.hpp>
#include <Stratimikos_MueLuHelpers.hpp>
#include <Teuchos_AbstractFactoryStd.hpp>
#include <Thyra_LinearOpWithSolveFactoryHelpers.hpp>
#include <Thyra_TpetraThyraWrappers.hpp>
#include <Thyra_VectorStdOps.hpp>

#include "core/Errors.hpp"
#include "solver/BandedLU.hpp"
#include "solver/Ifpack2Factory.hpp"
#include "solver/MumpsSolveStrategy.hpp"

namespace impm {

namespace {

// A 1-D Laplacian with the same number of rows on every rank: each rank takes part with a
// non-empty matrix (subdomain direct solvers fail on empty ones, which impm's grid systems
// never have), and enough rows that multigrid builds more than its coarse level, so that
// MueLu checks the smoother's parameters too.
void solveProbe(Thyra::LinearOpWithSolveFactoryBase<double>& lows,
                const Teuchos::RCP<const Comm>& comm) {
  constexpr LO rows = 2046;  // a multiple of 1, 2 and 3: whole nodes of any dimension on each rank
  const GO n = GO(rows) * comm->getSize();
  auto map = Teuchos::rcp(new Map(n, rows, 0, comm));
  auto A = Teuchos::rcp(new CrsMatrix(map, 3));
  for (LO k = 0; k < rows; ++k) {
    const GO i = map->getGlobalElement(k);
    for (GO j = std::max<GO>(i - 1, 0); j <= std::min<GO>(i + 1, n - 1); ++j)
      A->insertGlobalValues(i, Teuchos::tuple<GO>(j), Teuchos::tuple<double>(i == j ? 2.0 : -1.0));
  }
  A->fillComplete();
  // The guess is the solution: the set-up checks every sublist, the solve costs nothing.
  auto b = Teuchos::rcp(new Vector(map)), x = Teuchos::rcp(new Vector(map));
  x->putScalar(1.0);
  A->apply(*x, *b);
  auto op = Thyra::createConstLinearOp<double, LO, GO, Node>(
      Teuchos::rcp_implicit_cast<const Tpetra::Operator<double, LO, GO, Node>>(A));
  auto solver = Thyra::linearOpWithSolve(lows, op);
  solver->solve(Thyra::NOTRANS, *Thyra::createConstVector<double, LO, GO, Node>(b),
                Thyra::createVector<double, LO, GO, Node>(x).ptr());
}

}  // namespace

void solveLinearSystem(const Thyra::LinearOpWithSolveFactoryBase<double>& lows,
                       const Teuchos::RCP<const CrsMatrix>& A, const Vector& b, Vector& x) {
  auto op = Thyra::createConstLinearOp<double, LO, GO, Node>(
      Teuchos::rcp_implicit_cast<const Tpetra::Operator<double, LO, GO, Node>>(A));
  auto solver = Thyra::linearOpWithSolve(lows, op);
  auto tb = Thyra::createConstVector<double, LO, GO, Node>(Teuchos::rcpFromRef(b));
  auto tx = Thyra::createVector<double, LO, GO, Node>(Teuchos::rcpFromRef(x));
  const auto status = solver->solve(Thyra::NOTRANS, *tb, tx.ptr());
  if (status.solveStatus == Thyra::SOLVE_STATUS_UNCONVERGED)
    throw NumericalError("a linear solve did not converge (" + status.message + ")");
}

namespace {

Teuchos::ParameterList& belos(Teuchos::ParameterList& p, const std::string& method) {
  p.set("Linear Solver Type", "Belos");
  auto& belos = p.sublist("Linear Solver Types").sublist("Belos");
  belos.set("Solver Type", method);
  auto& solver = belos.sublist("Solver Types").sublist(method);
  solver.set("Maximum Iterations", 1000);
  solver.set("Convergence Tolerance", 1e-10);
  return solver;
}

void ilut(Teuchos::ParameterList& p) {
  p.set("Preconditioner Type", "Ifpack2");
  auto& ifpack2 = p.sublist("Preconditioner Types").sublist("Ifpack2");
  ifpack2.set("Prec Type", "ILUT");
  auto& settings = ifpack2.sublist("Ifpack2 Settings");
  settings.set("fact: ilut level-of-fill", 2.0);
  settings.set("fact: drop tolerance", 0.0);
}

void jacobi(Teuchos::ParameterList& p) {
  p.set("Preconditioner Type", "Ifpack2");
  auto& ifpack2 = p.sublist("Preconditioner Types").sublist("Ifpack2");
  ifpack2.set("Prec Type", "RELAXATION");
  ifpack2.sublist("Ifpack2 Settings").set("relaxation: type", "Jacobi");
}

void smoothedAggregation(Teuchos::ParameterList& p, int dim, int ranks) {
  p.set("Preconditioner Type", "MueLu");
  auto& muelu = p.sublist("Preconditioner Types").sublist("MueLu");
  muelu.set("verbosity", "none");
  muelu.set("number of equations", dim);
  muelu.set("multigrid algorithm", "sa");
  // Weak couplings (nodes a body barely touches) left out of the aggregation graph: the
  // iterations of a compressed column stop growing with the grid (doc/performance.md).
  muelu.set("aggregation: drop tol", 0.05);
  // One forward Gauss-Seidel sweep before the coarse correction and one backward after: a
  // symmetric V-cycle (CG needs one) at half the work of a symmetric sweep on both sides;
  // 5-10 % faster on the tall columns though it takes a quarter more iterations.
  muelu.set("smoother: pre type", "RELAXATION");
  muelu.sublist("smoother: pre params").set("relaxation: type", "Gauss-Seidel");
  muelu.set("smoother: post type", "RELAXATION");
  auto& post = muelu.sublist("smoother: post params");
  post.set("relaxation: type", "Gauss-Seidel");
  post.set("relaxation: backward mode", true);
  muelu.set("coarse: max size", 1000);
  if (ranks == 1) {
    muelu.set("coarse: type", "KLU2");
  } else {  // KLU2 is wrong on several ranks in 13.2 (doc/performance.md)
    // Sweeps enough to come close to the exact coarse solve (below 1000 rows they are
    // cheap): 30 against 4 took the 2-rank Krylov iterations of a 128 x 1024 column from
    // 431 to 333 and its run from 28.1 s to 25.1 s; more gained nothing.
    muelu.set("coarse: type", "RELAXATION");
    auto& coarse = muelu.sublist("coarse: params");
    coarse.set("relaxation: type", "Symmetric Gauss-Seidel");
    coarse.set("relaxation: sweeps", 30);
  }
  // A rebuild on unchanged unknowns keeps the aggregates and the tentative prolongator.
  // Not RP (the smoothed prolongator too): with the drop tolerance the filtered matrix's
  // pattern moves with the values, and MueLu 13.2 then fails inserting into P's static graph.
  muelu.set("reuse: type", "tP");
}

// MUMPS's sparse direct solve (solver/MumpsSolveStrategy.hpp), LDL^T for symmetric matrices.
void direct(Teuchos::ParameterList& p, bool symmetric) {
  p.set("Linear Solver Type", "MUMPS");
  p.set("Preconditioner Type", "None");
  p.sublist("Linear Solver Types").sublist("MUMPS").set("Symmetric", symmetric);
}

// The Krylov method and preconditioner for an operator of that kind.
Teuchos::ParameterList iterativeLinearSolverParameters(OperatorKind kind, int dim, int ranks) {
  Teuchos::ParameterList p("Linear Solver");
  switch (kind) {
    case OperatorKind::small:
      belos(p, "Pseudo Block GMRES").set("Num Blocks", 200);
      ilut(p);
      if (dim == 1)
        p.set("Preconditioner Type", "Banded LU");
      break;
    case OperatorKind::stiffness:
      belos(p, "Pseudo Block GMRES").set("Num Blocks", 200);
      smoothedAggregation(p, dim, ranks);
      break;
    case OperatorKind::symmetricStiffness:
      belos(p, "Pseudo Block CG");
      smoothedAggregation(p, dim, ranks);
      break;
    case OperatorKind::massDominated:
      belos(p, "Pseudo Block CG");
      jacobi(p);
      break;
  }
  return p;
}

}  // namespace

Teuchos::ParameterList defaultLinearSolverParameters(OperatorKind kind, int dim, int ranks) {
  // Direct where a factorisation costs little (small 2-D grids) or the Krylov methods
  // struggle (non-symmetric tangents of plastic flow, nearly singular near a limit load).
  if (dim > 1 && (kind == OperatorKind::small || kind == OperatorKind::stiffness)) {
    Teuchos::ParameterList p("Linear Solver");
    direct(p, false);
    return p;
  }
  return iterativeLinearSolverParameters(kind, dim, ranks);
}

namespace {

// Whether a deck's MueLu list names a parameter that begins with prefix.
bool namesMueLu(const Teuchos::ParameterList& deck, const std::string& prefix) {
  if (!deck.isSublist("Preconditioner Types") ||
      !deck.sublist("Preconditioner Types").isSublist("MueLu"))
    return false;
  const auto& muelu = deck.sublist("Preconditioner Types").sublist("MueLu");
  for (auto it = muelu.begin(); it != muelu.end(); ++it)
    if (muelu.name(it).rfind(prefix, 0) == 0)
      return true;
  return false;
}

// The preconditioner type a deck's list chooses: named, or its one configured sublist.
std::string chosenPreconditioner(const Teuchos::ParameterList& deck) {
  if (deck.isType<std::string>("Preconditioner Type"))
    return deck.get<std::string>("Preconditioner Type");
  if (deck.isSublist("Preconditioner Types") &&
      deck.sublist("Preconditioner Types").numParams() == 1)
    return deck.sublist("Preconditioner Types").name(deck.sublist("Preconditioner Types").begin());
  return {};
}

}  // namespace

Teuchos::ParameterList mergedLinearSolverParameters(const Teuchos::ParameterList& deck,
                                                    OperatorKind kind, int dim, int ranks) {
  auto p = defaultLinearSolverParameters(kind, dim, ranks);
  // A deck that names a Krylov solver or a preconditioner where the default solves directly
  // starts from impm's iterative settings for the problem; one that names MUMPS, from MUMPS.
  const bool defaultDirect = p.get<std::string>("Linear Solver Type") == "MUMPS";
  const std::string preconditioner = chosenPreconditioner(deck);
  const bool wantsDirect =
      deck.isType<std::string>("Linear Solver Type")
          ? deck.get<std::string>("Linear Solver Type") == "MUMPS"
          : defaultDirect && (preconditioner.empty() || preconditioner == "None");
  if (wantsDirect && !defaultDirect)
    direct(p, kind == OperatorKind::symmetricStiffness);
  else if (!wantsDirect && defaultDirect)
    p = iterativeLinearSolverParameters(kind, dim, ranks);
  // A deck that chooses MueLu where the default is another preconditioner (2-D grids under
  // 4000 nodes (3-D: 300), mass-dominated steps) starts from impm's multigrid settings for the
  // problem (Dim unknowns per node, the smoother, the coarse solve), not from MueLu's own defaults
  // (one unknown per node: 50-63 Krylov iterations per load step on columns 16-20 cells
  // wide, against 16-18 with these settings).
  if (chosenPreconditioner(deck) == "MueLu" && p.get<std::string>("Preconditioner Type") != "MueLu")
    smoothedAggregation(p, dim, ranks);
  // The default's Ifpack2 settings belong to its Prec Type: a deck that names another one
  // starts from none (ILUT's fill level means nothing to a block relaxation, which rejects
  // it), while a deck that tunes the default's own Prec Type keeps the rest of them.
  const auto precType = [](const Teuchos::ParameterList& list) -> std::string {
    if (!list.isSublist("Preconditioner Types") ||
        !list.sublist("Preconditioner Types").isSublist("Ifpack2"))
      return {};
    const auto& ifpack2 = list.sublist("Preconditioner Types").sublist("Ifpack2");
    return ifpack2.isType<std::string>("Prec Type") ? ifpack2.get<std::string>("Prec Type") : "";
  };
  const std::string ifpack2Type = precType(deck);
  if (!ifpack2Type.empty() && ifpack2Type != precType(p))
    p.sublist("Preconditioner Types").sublist("Ifpack2").remove("Ifpack2 Settings", false);
  // Likewise the default's MueLu smoother is one choice: a deck that names any `smoother:`
  // parameter starts from none (MueLu would take the default's `smoother: pre type` over the
  // deck's `smoother: type`); and a deck that names its coarse solver drops the default's
  // coarse parameters, which belong to the default's coarse type (Gauss-Seidel sweeps mean
  // nothing to a direct solver, which rejects them).
  if (p.get<std::string>("Preconditioner Type") == "MueLu") {  // impm's MueLu settings
    auto& muelu = p.sublist("Preconditioner Types").sublist("MueLu");
    if (namesMueLu(deck, "smoother:"))
      for (const char* key : {"smoother: pre type", "smoother: pre params", "smoother: post type",
                              "smoother: post params"})
        muelu.remove(key, false);
    if (namesMueLu(deck, "coarse: type"))
      muelu.remove("coarse: params", false);
  }
  p.setParameters(deck);
  if (const auto chosen = chosenPreconditioner(deck); !chosen.empty())
    p.set("Preconditioner Type", chosen);
  if (wantsDirect)
    p.set("Preconditioner Type", "None");  // MUMPS takes none
  return p;
}

std::string describeLinearSolver(const Teuchos::ParameterList& params) {
  const auto type = params.get<std::string>("Linear Solver Type");
  const auto& types = params.sublist("Linear Solver Types");
  if (type == "MUMPS") {
    const auto& mumps = types.sublist("MUMPS");
    const bool symmetric = mumps.isType<bool>("Symmetric") && mumps.get<bool>("Symmetric");
    return std::string("MUMPS ") + (symmetric ? "LDL^T" : "LU");
  }
  std::string method = type;
  if (type == "Belos" && types.sublist("Belos").isType<std::string>("Solver Type")) {
    method = types.sublist("Belos").get<std::string>("Solver Type");
    for (const std::string prefix : {"Pseudo Block ", "Block "})
      if (method.rfind(prefix, 0) == 0)
        method = method.substr(prefix.size());
  }
  const auto preconditioner = params.get<std::string>("Preconditioner Type");
  if (preconditioner == "None")
    return method;
  std::string name = preconditioner;
  if (preconditioner == "Ifpack2") {
    const auto& ifpack2 = params.sublist("Preconditioner Types").sublist("Ifpack2");
    if (ifpack2.isType<std::string>("Prec Type"))
      name += " " + ifpack2.get<std::string>("Prec Type");
  }
  return method + " + " + name;
}

Teuchos::RCP<Thyra::LinearOpWithSolveFactoryBase<double>> createLinearSolveStrategy(
    const Teuchos::ParameterList& params, const Teuchos::RCP<const Comm>& comm,
    const std::string& path) {
  Stratimikos::DefaultLinearSolverBuilder builder;
  using Base = Thyra::PreconditionerFactoryBase<double>;
  builder.setPreconditioningStrategyFactory(Teuchos::abstractFactoryStd<Base, Ifpack2Factory>(),
                                            "Ifpack2");
  builder.setPreconditioningStrategyFactory(Teuchos::abstractFactoryStd<Base, BandedLUFactory>(),
                                            "Banded LU");
  Stratimikos::enableMueLu<LO, GO, Node>(builder);
  builder.setLinearSolveStrategyFactory(
      Teuchos::abstractFactoryStd<Thyra::LinearOpWithSolveFactoryBase<double>,
                                  MumpsSolveStrategy>(),
      "MUMPS");

  auto list = Teuchos::rcp(new Teuchos::ParameterList(params));
  Teuchos::RCP<Thyra::LinearOpWithSolveFactoryBase<double>> lows;
  try {
    builder.setParameterList(list);
    lows = builder.createLinearSolveStrategy("");
    solveProbe(*lows, comm);
  } catch (const std::exception& e) {
    throw InputError(path, "Stratimikos rejected the list: " + trilinosMessage(e.what()));
  }
  return lows;
}

}  // namespace impm
