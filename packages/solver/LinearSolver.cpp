#include "solver/LinearSolver.hpp"

#include <algorithm>

#include <Stratimikos_DefaultLinearSolverBuilder.hpp>
#include <Stratimikos_MueLuHelpers.hpp>
#include <Teuchos_AbstractFactoryStd.hpp>
#include <Thyra_LinearOpWithSolveFactoryHelpers.hpp>
#include <Thyra_TpetraThyraWrappers.hpp>
#include <Thyra_VectorStdOps.hpp>

#include "core/Errors.hpp"
#include "solver/Ifpack2Factory.hpp"

namespace impm {

namespace {

// A 1-D Laplacian with two rows on every rank: each rank takes part with a non-empty
// matrix (subdomain direct solvers fail on empty ones, which impm's grid systems never have).
void solveProbe(Thyra::LinearOpWithSolveFactoryBase<double>& lows,
                const Teuchos::RCP<const Comm>& comm) {
  const GO n = 2 * comm->getSize();
  auto map = Teuchos::rcp(new Map(n, 2, 0, comm));
  auto A = Teuchos::rcp(new CrsMatrix(map, 3));
  for (LO k = 0; k < 2; ++k) {
    const GO i = map->getGlobalElement(k);
    for (GO j = std::max<GO>(i - 1, 0); j <= std::min<GO>(i + 1, n - 1); ++j)
      A->insertGlobalValues(i, Teuchos::tuple<GO>(j), Teuchos::tuple<double>(i == j ? 2.0 : -1.0));
  }
  A->fillComplete();
  auto b = Teuchos::rcp(new Vector(map)), x = Teuchos::rcp(new Vector(map));
  b->putScalar(1.0);
  // Whether it converges is not checked: the deck's iteration limit may be meant for the
  // real systems.
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

Teuchos::ParameterList defaultLinearSolverParameters() {
  Teuchos::ParameterList p("Linear Solver");
  p.set("Linear Solver Type", "Belos");
  auto& belos = p.sublist("Linear Solver Types").sublist("Belos");
  belos.set("Solver Type", "Pseudo Block GMRES");
  auto& gmres = belos.sublist("Solver Types").sublist("Pseudo Block GMRES");
  gmres.set("Maximum Iterations", 1000);
  gmres.set("Num Blocks", 200);
  gmres.set("Convergence Tolerance", 1e-10);
  p.set("Preconditioner Type", "Ifpack2");
  auto& ifpack2 = p.sublist("Preconditioner Types").sublist("Ifpack2");
  ifpack2.set("Prec Type", "ILUT");
  auto& settings = ifpack2.sublist("Ifpack2 Settings");
  settings.set("fact: ilut level-of-fill", 2.0);
  settings.set("fact: drop tolerance", 0.0);
  return p;
}

Teuchos::RCP<Thyra::LinearOpWithSolveFactoryBase<double>> createLinearSolveStrategy(
    const Teuchos::ParameterList& params, const Teuchos::RCP<const Comm>& comm,
    const std::string& path) {
  Stratimikos::DefaultLinearSolverBuilder builder;
  using Base = Thyra::PreconditionerFactoryBase<double>;
  builder.setPreconditioningStrategyFactory(Teuchos::abstractFactoryStd<Base, Ifpack2Factory>(),
                                            "Ifpack2");
  Stratimikos::enableMueLu<LO, GO, Node>(builder);

  auto list = Teuchos::rcp(new Teuchos::ParameterList(defaultLinearSolverParameters()));
  list->setParameters(params);
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
