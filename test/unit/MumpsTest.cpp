// solver: MUMPS's sparse direct solve (solver/MumpsFactorization, solver/MumpsSolveStrategy)
// inverts distributed matrices exactly on any number of ranks, whatever their row maps,
// keeps its analysis while the pattern stays, and reports a singular matrix on every rank.

#include <gtest/gtest.h>

#include <cmath>

#include <Teuchos_DefaultComm.hpp>
#include <Thyra_LinearOpWithSolveFactoryHelpers.hpp>
#include <Thyra_TpetraThyraWrappers.hpp>

#include "core/Errors.hpp"
#include "solver/LinearSolver.hpp"
#include "solver/MumpsFactorization.hpp"

namespace impm {
namespace {

// Row i of an n x n matrix with entries at i - 2 .. i + 1: 4 at i, -1 at i - 1, -0.5 at
// i - 2 and -2 at i + 1 (non-symmetric); symmetric: 4 at i and -1 at i +- 1, i +- 2.
std::vector<std::pair<GO, double>> rowOf(GO i, GO n, bool symmetric) {
  std::vector<std::pair<GO, double>> row;
  const auto add = [&](GO j, double v) {
    if (j >= 0 && j < n)
      row.emplace_back(j, v);
  };
  add(i, 4.0 + 0.01 * double(i % 7));
  add(i - 1, -1.0);
  add(i - 2, symmetric ? -1.0 : -0.5);
  add(i + 1, symmetric ? -1.0 : -2.0);
  if (symmetric)
    add(i + 2, -1.0);
  return row;
}

// The matrix on a row map that is not contiguous: unknown i on rank (i * 7) % ranks, the
// last rank holding none when `lastRankEmpty` (MUMPS numbers the rows rank by rank).
Teuchos::RCP<CrsMatrix> scatteredMatrix(const Teuchos::RCP<const Comm>& comm, GO n, bool symmetric,
                                        bool lastRankEmpty = false) {
  const int ranks = comm->getSize();
  const int filled = lastRankEmpty && ranks > 1 ? ranks - 1 : ranks;
  std::vector<GO> mine;
  for (GO i = 0; i < n; ++i)
    if ((i * 7) % filled == comm->getRank())
      mine.push_back(i);
  auto map = Teuchos::rcp(new Map(n, Teuchos::ArrayView<const GO>(mine), 0, comm));
  auto A = Teuchos::rcp(new CrsMatrix(map, 5));
  for (const GO i : mine)
    for (const auto& [j, v] : rowOf(i, n, symmetric))
      A->insertGlobalValues(i, Teuchos::tuple<GO>(j), Teuchos::tuple<double>(v));
  A->fillComplete();
  return A;
}

// || A^-1 (A x) - x ||_inf for x_i = sin(1 + i), two columns (the second 3 x).
double inverseError(const CrsMatrix& A, MumpsFactorization& mumps) {
  MultiVector x(A.getRowMap(), 2), b(A.getRowMap(), 2), y(A.getRowMap(), 2);
  for (std::size_t k = 0; k < x.getLocalLength(); ++k) {
    const double v = std::sin(1.0 + double(A.getRowMap()->getGlobalElement(k)));
    x.replaceLocalValue(k, 0, v);
    x.replaceLocalValue(k, 1, 3.0 * v);
  }
  A.apply(x, b);
  mumps.solve(b, y);
  y.update(-1.0, x, 1.0);
  std::vector<double> norms(2);
  y.normInf(Teuchos::ArrayView<double>(norms));
  return std::max(norms[0], norms[1]);
}

TEST(Mumps, InvertsADistributedMatrixOnAnyRowMap) {
  auto comm = Teuchos::DefaultComm<int>::getComm();
  for (const bool lastRankEmpty : {false, true}) {
    const auto A = scatteredMatrix(comm, 103, false, lastRankEmpty);
    MumpsFactorization mumps(comm, MumpsOptions{});
    mumps.factor(*A);
    EXPECT_LT(inverseError(*A, mumps), 1e-13) << "last rank empty " << lastRankEmpty;
  }
}

// LDL^T from the lower triangle: the upper one is left out, not added to it.
TEST(Mumps, SymmetricFactorisationReadsOneTriangle) {
  auto comm = Teuchos::DefaultComm<int>::getComm();
  const auto A = scatteredMatrix(comm, 97, true);
  for (const auto* ordering : {"automatic", "amd", "metis", "scotch"}) {
    MumpsOptions options;
    options.symmetric = true;
    options.ordering = ordering;
    MumpsFactorization mumps(comm, options);
    mumps.factor(*A);
    EXPECT_LT(inverseError(*A, mumps), 1e-13) << ordering;
  }
}

// New values on the same pattern are factorised without a new analysis; a new pattern is
// analysed again.
TEST(Mumps, AnalysisKeptWhileThePatternStays) {
  auto comm = Teuchos::DefaultComm<int>::getComm();
  auto A = scatteredMatrix(comm, 60, false);
  MumpsFactorization mumps(comm, MumpsOptions{});
  mumps.factor(*A);
  A->resumeFill();
  A->scale(2.0);
  A->fillComplete();
  mumps.factor(*A);
  EXPECT_EQ(mumps.analyses(), 1);
  EXPECT_EQ(mumps.factorizations(), 2);
  EXPECT_LT(inverseError(*A, mumps), 1e-13);
  const auto B = scatteredMatrix(comm, 60, true);
  mumps.factor(*B);
  EXPECT_EQ(mumps.analyses(), 2);
  EXPECT_LT(inverseError(*B, mumps), 1e-13);
}

// A zero row: every rank throws the same NumericalError (none waits in a collective call).
TEST(Mumps, SingularMatrixIsANumericalErrorOnEveryRank) {
  auto comm = Teuchos::DefaultComm<int>::getComm();
  const GO n = 8 * comm->getSize();
  auto map = Teuchos::rcp(new Map(n, 0, comm));
  auto A = Teuchos::rcp(new CrsMatrix(map, 2));
  for (std::size_t k = 0; k < map->getNodeNumElements(); ++k) {
    const GO i = map->getGlobalElement(k);
    A->insertGlobalValues(i, Teuchos::tuple<GO>(i), Teuchos::tuple<double>(i == 5 ? 0.0 : 1.0));
  }
  A->fillComplete();
  MumpsFactorization mumps(comm, MumpsOptions{});
  try {
    mumps.factor(*A);
    FAIL() << "no error";
  } catch (const NumericalError& e) {
    EXPECT_NE(std::string(e.what()).find("linear solver failure: the matrix is singular"),
              std::string::npos)
        << e.what();
  }
}

// Through Stratimikos as the deck's "Linear Solver Type": the solve is exact, one
// "iteration"; an operator initialised again with new values solves the new system.
TEST(Mumps, LinearSolverTypeOfADeck) {
  auto comm = Teuchos::DefaultComm<int>::getComm();
  Teuchos::ParameterList deck;
  deck.set("Linear Solver Type", std::string("MUMPS"));
  const auto lows = createLinearSolveStrategy(
      mergedLinearSolverParameters(deck, OperatorKind::stiffness, 2, comm->getSize()), comm,
      "Solver/Linear Solver");
  auto A = scatteredMatrix(comm, 80, false);
  const auto op = Thyra::createConstLinearOp<double, LO, GO, Node>(
      Teuchos::rcp_implicit_cast<const Tpetra::Operator<double, LO, GO, Node>>(A));
  auto solver = Thyra::linearOpWithSolve(*lows, op);
  for (const double scale : {1.0, 0.5}) {
    if (scale != 1.0) {
      A->resumeFill();
      A->scale(scale);
      A->fillComplete();
      Thyra::initializeOp(*lows, op, solver.ptr());
    }
    Vector x(A->getRowMap()), b(A->getRowMap()), y(A->getRowMap());
    x.randomize();
    A->apply(x, b);
    const auto status = solver->solve(
        Thyra::NOTRANS, *Thyra::createConstVector<double, LO, GO, Node>(Teuchos::rcpFromRef(b)),
        Thyra::createVector<double, LO, GO, Node>(Teuchos::rcpFromRef(y)).ptr());
    EXPECT_EQ(status.solveStatus, Thyra::SOLVE_STATUS_CONVERGED);
    EXPECT_EQ(status.extraParameters->get<int>("Iteration Count"), 1);
    y.update(-1.0, x, 1.0);
    EXPECT_LT(y.normInf(), 1e-13) << "scale " << scale;
  }
}

// A misspelt option is the deck's error, found when the strategy is built.
TEST(Mumps, UnknownOrderingIsAnInputError) {
  auto comm = Teuchos::DefaultComm<int>::getComm();
  Teuchos::ParameterList deck;
  deck.set("Linear Solver Type", std::string("MUMPS"));
  deck.sublist("Linear Solver Types").sublist("MUMPS").set("Ordering", std::string("mettis"));
  try {
    createLinearSolveStrategy(
        mergedLinearSolverParameters(deck, OperatorKind::stiffness, 2, comm->getSize()), comm,
        "Solver/Linear Solver");
    FAIL() << "no error";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(
        what.find("\"Ordering\" parameter in the \"Linear Solver->Linear Solver Types->MUMPS\""),
        std::string::npos)
        << what;
  }
}

}  // namespace
}  // namespace impm
