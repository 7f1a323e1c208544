#include "solver/LinearSolver.hpp"

#include <Stratimikos_DefaultLinearSolverBuilder.hpp>
#include <Stratimikos_MueLuHelpers.hpp>
#include <Teuchos_AbstractFactoryStd.hpp>
#include <Thyra_Ifpack2PreconditionerFactory.hpp>
#include <Thyra_LinearOpWithSolveFactoryHelpers.hpp>
#include <Thyra_TpetraThyraWrappers.hpp>
#include <Thyra_VectorStdOps.hpp>

#include "core/Errors.hpp"

namespace impm {

namespace {

void solveOneByOne(Thyra::LinearOpWithSolveFactoryBase<double>& lows,
                   const Teuchos::RCP<const Comm>& comm) {
  // One row on rank 0, none elsewhere, so that every rank takes part.
  const std::size_t rows = comm->getRank() == 0 ? 1 : 0;
  auto map = Teuchos::rcp(new Map(1, rows, 0, comm));
  auto A = Teuchos::rcp(new CrsMatrix(map, 1));
  if (rows)
    A->insertGlobalValues(0, Teuchos::tuple<GO>(0), Teuchos::tuple<double>(2.0));
  A->fillComplete();
  auto b = Teuchos::rcp(new Vector(map)), x = Teuchos::rcp(new Vector(map));
  b->putScalar(1.0);
  auto op = Thyra::createConstLinearOp<double, LO, GO, Node>(
      Teuchos::rcp_implicit_cast<const Tpetra::Operator<double, LO, GO, Node>>(A));
  auto solver = Thyra::linearOpWithSolve(lows, op);
  auto tb = Thyra::createConstVector<double, LO, GO, Node>(b);
  auto tx = Thyra::createVector<double, LO, GO, Node>(x);
  solver->solve(Thyra::NOTRANS, *tb, tx.ptr());
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
  using Ifpack2Factory = Thyra::Ifpack2PreconditionerFactory<CrsMatrix>;
  builder.setPreconditioningStrategyFactory(Teuchos::abstractFactoryStd<Base, Ifpack2Factory>(),
                                            "Ifpack2");
  Stratimikos::enableMueLu<LO, GO, Node>(builder);

  auto list = Teuchos::rcp(new Teuchos::ParameterList(defaultLinearSolverParameters()));
  list->setParameters(params);
  Teuchos::RCP<Thyra::LinearOpWithSolveFactoryBase<double>> lows;
  try {
    builder.setParameterList(list);
    lows = builder.createLinearSolveStrategy("");
    solveOneByOne(*lows, comm);
  } catch (const std::exception& e) {
    throw InputError(path, "Stratimikos rejected the list: " + trilinosMessage(e.what()));
  }
  return lows;
}

}  // namespace impm
