// solver: Newton through NOX converges quadratically, the grid system's Jacobian is the
// derivative of its residual, and the Stratimikos strategies (Ifpack2, MueLu) solve on any
// number of ranks.

#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>

#include <Teuchos_DefaultComm.hpp>
#include <Thyra_LinearOpWithSolveFactoryHelpers.hpp>
#include <Thyra_TpetraThyraWrappers.hpp>

#include <cmath>

#include "core/Errors.hpp"
#include "core/Parameters.hpp"
#include "solver/BandedLU.hpp"
#include "solver/DecoupledRows.hpp"
#include "solver/LinearSolver.hpp"
#include "solver/LinearTarget.hpp"
#include "solver/NewtonSolver.hpp"
#include "solver/PreconditionerReuse.hpp"
#include "solver/RoundOffTest.hpp"

namespace impm {
namespace {

// R_i(x) = x_i^3 + x_i - b_i: nonlinear, with a diagonal Jacobian 3 x_i^2 + 1.
class CubicModel : public ResidualModel {
 public:
  explicit CubicModel(const Teuchos::RCP<const Comm>& comm)
      : map_(Teuchos::rcp(new Map(40, 0, comm))) {
    graph_ = Teuchos::rcp(new CrsGraph(map_, 1));
    for (std::size_t k = 0; k < map_->getNodeNumElements(); ++k) {
      const GO g = map_->getGlobalElement(k);
      graph_->insertGlobalIndices(g, Teuchos::tuple<GO>(g));
    }
    graph_->fillComplete();
  }
  Teuchos::RCP<const Map> unknownMap() const override { return map_; }
  Teuchos::RCP<CrsMatrix> createJacobian() const override {
    return Teuchos::rcp(new CrsMatrix(graph_));
  }
  void evaluate(const Vector& x, Vector* f, CrsMatrix* J) override {
    auto xv = x.getData();
    if (J)
      J->resumeFill();
    for (decltype(xv.size()) k = 0; k < xv.size(); ++k) {
      const double b = 1.0 + map_->getGlobalElement(k) % 5;
      if (f)
        f->replaceLocalValue(k, xv[k] * xv[k] * xv[k] + xv[k] - b);
      if (J) {
        const double d = 3 * xv[k] * xv[k] + 1;
        const LO col = static_cast<LO>(k);
        J->replaceLocalValues(static_cast<LO>(k), 1, &d, &col);
      }
    }
    if (J)
      J->fillComplete();
  }

 private:
  Teuchos::RCP<const Map> map_;
  Teuchos::RCP<CrsGraph> graph_;
};

Teuchos::ParameterList solverList(const std::string& lineSearch = "Full Step") {
  Teuchos::ParameterList p;
  p.set("Line Search", lineSearch);
  p.set("Relative Tolerance", 1e-13);
  p.set("Update Tolerance", 0.0);
  validateParameters(p, NewtonSolver::validParameters());
  return p;
}

TEST(NewtonSolver, ConvergesQuadratically) {
  auto comm = Teuchos::DefaultComm<int>::getComm();
  auto model = Teuchos::rcp(new CubicModel(comm));
  NewtonSolver newton(solverList(), comm);
  Vector x(model->unknownMap());
  x.putScalar(3.0);
  const auto report = newton.solve(model, x);
  ASSERT_TRUE(report.converged);
  const auto& r = report.residualNorms;
  ASSERT_GE(r.size(), 4u);
  // Quadratic: r_(k+1) <= C r_k^2 once in the basin; checked while above round-off.
  for (std::size_t k = 2; k + 1 < r.size(); ++k)
    if (r[k + 1] > 1e-12) {
      EXPECT_LT(r[k + 1] / (r[k] * r[k]), 10.0) << "iteration " << k;
    }
  EXPECT_LT(r.back(), 1e-13 * r.front());
  for (int n : report.linearIterations)
    EXPECT_GE(n, 1);
}

TEST(NewtonSolver, ReportsFailureWithinTheIterationLimit) {
  auto comm = Teuchos::DefaultComm<int>::getComm();
  auto model = Teuchos::rcp(new CubicModel(comm));
  auto params = solverList();
  params.set("Maximum Iterations", 2);
  NewtonSolver newton(params, comm);
  Vector x(model->unknownMap());
  x.putScalar(30.0);
  const auto report = newton.solve(model, x);
  EXPECT_FALSE(report.converged);
  EXPECT_NE(report.failure.find("no convergence in 2 iterations"), std::string::npos);
}

// R = K x - b, K lower bidiagonal (1 on the diagonal, -1 below), b = (1e8, 0.1, 0.1, ...):
// x_i = 1e8 + 0.1 i.  The differences x_i - x_(i-1) cancel to 0.1 from terms of 1e8, so the
// residual cannot fall below the unknowns' rounding, about 1e-8 an entry.
class ChainModel : public ResidualModel {
 public:
  explicit ChainModel(const Teuchos::RCP<const Comm>& comm)
      : map_(Teuchos::rcp(new Map(40, 0, comm))), b_(map_) {
    K_ = Teuchos::rcp(new CrsMatrix(map_, 2));
    for (std::size_t k = 0; k < map_->getNodeNumElements(); ++k) {
      const GO g = map_->getGlobalElement(k);
      if (g == 0)
        K_->insertGlobalValues(g, Teuchos::tuple<GO>(g), Teuchos::tuple(1.0));
      else
        K_->insertGlobalValues(g, Teuchos::tuple<GO>(g - 1, g), Teuchos::tuple(-1.0, 1.0));
      b_.replaceLocalValue(static_cast<LO>(k), g == 0 ? 1e8 : 0.1);
    }
    K_->fillComplete();
  }
  Teuchos::RCP<const Map> unknownMap() const override { return map_; }
  Teuchos::RCP<CrsMatrix> createJacobian() const override {
    return Teuchos::rcp(new CrsMatrix(*K_, Teuchos::Copy));
  }
  void evaluate(const Vector& x, Vector* f, CrsMatrix* /*J: constant*/) override {
    if (f) {
      K_->apply(x, *f);
      f->update(-1.0, b_, 1.0);
    }
  }
  const CrsMatrix& matrix() const { return *K_; }
  // The solution with a bump of 1 at unknown 7: a residual of about 1.4.
  Vector perturbedSolution() const {
    Vector x(map_);
    for (std::size_t k = 0; k < map_->getNodeNumElements(); ++k) {
      const GO g = map_->getGlobalElement(k);
      x.replaceLocalValue(static_cast<LO>(k), 1e8 + 0.1 * static_cast<double>(g) + (g == 7));
    }
    return x;
  }

 private:
  Teuchos::RCP<const Map> map_;
  Teuchos::RCP<CrsMatrix> K_;
  Vector b_;
};

TEST(RoundOff, AbsoluteProductNormTakesAbsoluteValuesEntryByEntry) {
  auto comm = Teuchos::DefaultComm<int>::getComm();
  const ChainModel model(comm);
  Vector x(model.unknownMap());
  const auto xi = [](GO g) { return (g % 2 ? -1.0 : 1.0) * static_cast<double>(g + 1); };
  for (std::size_t k = 0; k < x.getMap()->getNodeNumElements(); ++k)
    x.replaceLocalValue(static_cast<LO>(k), xi(x.getMap()->getGlobalElement(k)));
  double expected = 1.0;  // row 0: |1| |x_0|
  for (GO g = 1; g < 40; ++g)
    expected += std::pow(std::abs(xi(g)) + std::abs(xi(g - 1)), 2);  // K x would cancel to +-1
  EXPECT_NEAR(absoluteProductNorm(model.matrix(), x), std::sqrt(expected), 1e-12 * expected);
}

// The residual's floor lies above the relative tolerance: without the round-off test Newton
// cannot converge (the update test is off); with it, one Newton step ends the solve.
TEST(RoundOff, ResidualAtItsFloorEndsNewton) {
  auto comm = Teuchos::DefaultComm<int>::getComm();
  auto model = Teuchos::rcp(new ChainModel(comm));
  for (const double factor : {1.0, 0.0}) {
    auto params = solverList();
    params.set("Relative Tolerance", 1e-10);
    params.set("Maximum Iterations", 6);
    params.set("Round-off Factor", factor);
    NewtonSolver newton(params, comm);
    Vector x = model->perturbedSolution();
    const auto report = newton.solve(model, x);
    const auto& r = report.residualNorms;
    EXPECT_GT(r.back(), 1e-10 * r.front()) << "factor " << factor;
    if (factor > 0) {
      EXPECT_TRUE(report.converged);
      EXPECT_EQ(report.iterations(), 1);
      EXPECT_LE(r.back(), factor * 2.2205e-16 * absoluteProductNorm(model->matrix(), x));
    } else {
      EXPECT_FALSE(report.converged) << "the floor was reached: " << r.back();
    }
  }
}

TEST(LinearSolver, MisspeltListIsAnInputError) {
  auto comm = Teuchos::DefaultComm<int>::getComm();
  Teuchos::ParameterList bad;
  bad.set("Linear Solver Type", std::string("Belox"));
  try {
    createLinearSolveStrategy(
        mergedLinearSolverParameters(bad, OperatorKind::small, 1, comm->getSize()), comm,
        "Solver/Linear Solver");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.path(), "Solver/Linear Solver");
  }
}

// Teuchos reports an unknown parameter over three lines; the error keeps all of them.
TEST(LinearSolver, UnknownIfpack2SettingNamesItsSublist) {
  auto comm = Teuchos::DefaultComm<int>::getComm();
  Teuchos::ParameterList bad;
  bad.sublist("Preconditioner Types")
      .sublist("Ifpack2")
      .sublist("Ifpack2 Settings")
      .set("fact: ilut level-of-fil", 2.0);
  try {
    createLinearSolveStrategy(
        mergedLinearSolverParameters(bad, OperatorKind::small, 1, comm->getSize()), comm,
        "Solver/Linear Solver");
    FAIL() << "no error";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("fact: ilut level-of-fil"), std::string::npos) << what;
    EXPECT_NE(what.find("Ifpack2->Ifpack2 Settings"), std::string::npos) << what;
    EXPECT_NE(what.find("was not found in the list of valid parameters"), std::string::npos)
        << what;
  }
}

// 1-D Laplacian with Dirichlet ends, solved by every strategy impm documents: the full list.
// The 1-D Laplacian tridiag(-1, 2, -1) of n unknowns.
Teuchos::RCP<CrsMatrix> laplacian(const Teuchos::RCP<const Comm>& comm, GO n) {
  auto map = Teuchos::rcp(new Map(n, 0, comm));
  auto A = Teuchos::rcp(new CrsMatrix(map, 3));
  for (std::size_t k = 0; k < map->getNodeNumElements(); ++k) {
    const GO i = map->getGlobalElement(k);
    std::vector<GO> cols = {i};
    std::vector<double> vals = {2.0};
    if (i > 0)
      cols.push_back(i - 1), vals.push_back(-1.0);
    if (i < n - 1)
      cols.push_back(i + 1), vals.push_back(-1.0);
    A->insertGlobalValues(i, Teuchos::ArrayView<const GO>(cols),
                          Teuchos::ArrayView<const double>(vals));
  }
  A->fillComplete();
  return A;
}

Teuchos::RCP<const Thyra::LinearOpBase<double>> thyraOperator(const Teuchos::RCP<CrsMatrix>& A) {
  return Thyra::createConstLinearOp<double, LO, GO, Node>(
      Teuchos::rcp_implicit_cast<const Tpetra::Operator<double, LO, GO, Node>>(A));
}

// R_i(x) = (K x)_i + x_i^3 - 1, K the 1-D Laplacian (2 on the diagonal, -1 beside it) of n
// unknowns: a Jacobian K + diag(3 x_i^2) that unpreconditioned GMRES solves slowly.
class StiffCubicModel : public ResidualModel {
 public:
  StiffCubicModel(const Teuchos::RCP<const Comm>& comm, GO n) : K_(laplacian(comm, n)) {}
  Teuchos::RCP<const Map> unknownMap() const override { return K_->getRowMap(); }
  Teuchos::RCP<CrsMatrix> createJacobian() const override {
    return Teuchos::rcp(new CrsMatrix(*K_, Teuchos::Copy));
  }
  void evaluate(const Vector& x, Vector* f, CrsMatrix* J) override {
    auto xv = x.getData();
    if (f) {
      K_->apply(x, *f);
      for (decltype(xv.size()) k = 0; k < xv.size(); ++k)
        f->sumIntoLocalValue(static_cast<LO>(k), xv[k] * xv[k] * xv[k] - 1.0);
    }
    if (J) {  // K's off-diagonal entries (the Jacobian starts as a copy of K), a new diagonal
      J->resumeFill();
      for (decltype(xv.size()) k = 0; k < xv.size(); ++k) {
        const GO i = K_->getRowMap()->getGlobalElement(static_cast<LO>(k));
        J->replaceGlobalValues(i, Teuchos::tuple<GO>(i), Teuchos::tuple(2.0 + 3 * xv[k] * xv[k]));
      }
      J->fillComplete();
    }
  }

 private:
  Teuchos::RCP<CrsMatrix> K_;
};

// A Newton iteration whose residual is near the target solves its linear system only as far
// as the target needs (solver/LinearTarget.hpp): the last iteration's solve takes fewer
// Krylov iterations than the first, and the step still meets its tolerance.
TEST(NewtonSolver, LastLinearSolvesStopAtNewtonsTarget) {
  auto comm = Teuchos::DefaultComm<int>::getComm();
  auto model = Teuchos::rcp(new StiffCubicModel(comm, 100));
  auto params = solverList();
  params.set("Relative Tolerance", 1e-8);
  params.sublist("Linear Solver").set("Preconditioner Type", "None");
  NewtonSolver newton(params, comm);
  Vector x(model->unknownMap());
  x.putScalar(0.5);
  const auto report = newton.solve(model, x);
  ASSERT_TRUE(report.converged);
  ASSERT_GE(report.iterations(), 3);
  EXPECT_LE(report.residualNorms.back(), 1e-8 * report.residualNorms.front());
  const auto& linear = report.linearIterations;
  EXPECT_LT(2 * linear.back(), linear.front())
      << "first " << linear.front() << ", last " << linear.back();
}

// eta = min(0.1, max(Linear Tolerance, 0.5 tau / ||R_k||)).
TEST(LinearTarget, NoTighterThanNewtonNeeds) {
  Teuchos::ParameterList list;
  LinearTarget target(list, 1e-10, 1e-8);
  EXPECT_DOUBLE_EQ(target.tolerance(100.0), 1e-10);  // far from the target
  EXPECT_DOUBLE_EQ(target.tolerance(1e-5), 5e-4);
  EXPECT_DOUBLE_EQ(target.tolerance(2e-8), 0.1);  // a tenfold reduction at most
  EXPECT_DOUBLE_EQ(target.tolerance(0.0), 1e-10);
}

// Solves A x = 1 (A: the Laplacian of 200 unknowns unless given) with the full list.
// Returns the Krylov iterations.
int expectSolvesFull(const Teuchos::ParameterList& params, Teuchos::RCP<CrsMatrix> A = {}) {
  auto comm = Teuchos::DefaultComm<int>::getComm();
  if (A.is_null())
    A = laplacian(comm, 200);
  const auto map = A->getRowMap();
  auto lows = createLinearSolveStrategy(params, comm, "test");
  auto solver = Thyra::linearOpWithSolve(*lows, thyraOperator(A));
  auto b = Teuchos::rcp(new Vector(map)), x = Teuchos::rcp(new Vector(map));
  b->putScalar(1.0);
  auto status = solver->solve(Thyra::NOTRANS, *Thyra::createConstVector<double, LO, GO, Node>(b),
                              Thyra::createVector<double, LO, GO, Node>(x).ptr());
  Vector r(map);
  A->apply(*x, r);
  r.update(1.0, *b, -1.0);
  EXPECT_LT(r.norm2(), 1e-8 * b->norm2());
  return status.extraParameters.is_null()
             ? -1
             : status.extraParameters->get<int>("Belos/Iteration Count", -1);
}

// The same for a deck's list over the small-system default.
void expectSolves(const Teuchos::ParameterList& deck) {
  auto comm = Teuchos::DefaultComm<int>::getComm();
  expectSolvesFull(mergedLinearSolverParameters(deck, OperatorKind::small, 1, comm->getSize()));
}

// Small systems: GMRES with the banded LU in 1-D (its matrices are banded: exact on one
// rank), MUMPS's LU on small 2-D grids (whose band would be as wide as the grid); a deck that
// names a preconditioner there gets GMRES with ILUT beneath its own settings.
TEST(LinearSolver, SmallSystemDefaults) {
  expectSolves(Teuchos::ParameterList());
  auto comm = Teuchos::DefaultComm<int>::getComm();
  const auto oneD = defaultLinearSolverParameters(OperatorKind::small, 1, comm->getSize());
  const auto twoD = defaultLinearSolverParameters(OperatorKind::small, 2, comm->getSize());
  EXPECT_EQ(oneD.get<std::string>("Preconditioner Type"), "Banded LU");
  EXPECT_EQ(twoD.get<std::string>("Linear Solver Type"), "MUMPS");
  EXPECT_EQ(twoD.get<std::string>("Preconditioner Type"), "None");
  expectSolvesFull(twoD);
  Teuchos::ParameterList deck;
  deck.set("Preconditioner Type", std::string("Ifpack2"));
  const auto iterative =
      mergedLinearSolverParameters(deck, OperatorKind::small, 2, comm->getSize());
  EXPECT_EQ(iterative.get<std::string>("Linear Solver Type"), "Belos");
  EXPECT_EQ(
      iterative.sublist("Preconditioner Types").sublist("Ifpack2").get<std::string>("Prec Type"),
      "ILUT");
  expectSolvesFull(iterative);
}

// The defaults of the other operator kinds (MueLu with one unknown per node here, CG with
// Jacobi) solve it too, on any number of ranks (MueLu's coarse solve is iterative there).
TEST(LinearSolver, DefaultOfEveryKindSolves) {
  auto comm = Teuchos::DefaultComm<int>::getComm();
  for (auto kind :
       {OperatorKind::stiffness, OperatorKind::symmetricStiffness, OperatorKind::massDominated}) {
    auto p = defaultLinearSolverParameters(kind, 1, comm->getSize());
    expectSolvesFull(p);
  }
}

// Stiffness: CG + MueLu where the tangent is symmetric, MUMPS's LU where it may not be
// (plasticity near a limit load); a deck that names a Krylov solver there gets GMRES + MueLu.
TEST(LinearSolver, CgOnlyForSymmetricStiffness) {
  const auto symmetric = defaultLinearSolverParameters(OperatorKind::symmetricStiffness, 2, 1);
  EXPECT_EQ(
      symmetric.sublist("Linear Solver Types").sublist("Belos").get<std::string>("Solver Type"),
      "Pseudo Block CG");
  EXPECT_EQ(symmetric.get<std::string>("Preconditioner Type"), "MueLu");
  const auto general = defaultLinearSolverParameters(OperatorKind::stiffness, 2, 1);
  EXPECT_EQ(general.get<std::string>("Linear Solver Type"), "MUMPS");
  EXPECT_FALSE(general.sublist("Linear Solver Types").sublist("MUMPS").get<bool>("Symmetric"));
  Teuchos::ParameterList deck;
  deck.set("Linear Solver Type", std::string("Belos"));
  const auto krylov = mergedLinearSolverParameters(deck, OperatorKind::stiffness, 2, 1);
  EXPECT_EQ(krylov.sublist("Linear Solver Types").sublist("Belos").get<std::string>("Solver Type"),
            "Pseudo Block GMRES");
  EXPECT_EQ(krylov.get<std::string>("Preconditioner Type"), "MueLu");
}

// A deck list that configures one preconditioner without naming it selects it, beneath the
// iterative defaults.
TEST(LinearSolver, ConfiguredPreconditionerIsSelected) {
  Teuchos::ParameterList deck;
  deck.sublist("Preconditioner Types").sublist("Ifpack2").set("Prec Type", std::string("RILUK"));
  const auto p = mergedLinearSolverParameters(deck, OperatorKind::stiffness, 2, 1);
  EXPECT_EQ(p.get<std::string>("Preconditioner Type"), "Ifpack2");
  EXPECT_EQ(p.get<std::string>("Linear Solver Type"), "Belos");
  EXPECT_EQ(mergedLinearSolverParameters({}, OperatorKind::symmetricStiffness, 2, 1)
                .get<std::string>("Preconditioner Type"),
            "MueLu");
}

// A deck list that selects Ifpack2's `precType`: its `Ifpack2 Settings`, to fill in.
Teuchos::ParameterList& ifpack2Settings(Teuchos::ParameterList& deck, const std::string& precType) {
  auto& ifpack2 = deck.sublist("Preconditioner Types").sublist("Ifpack2");
  ifpack2.set("Prec Type", precType);
  return ifpack2.sublist("Ifpack2 Settings");
}

// The Ifpack2 settings that a deck list gives over the small-system default (ILUT).
Teuchos::ParameterList mergedIfpack2Settings(const Teuchos::ParameterList& deck) {
  return mergedLinearSolverParameters(deck, OperatorKind::small, 1, 1)
      .sublist("Preconditioner Types")
      .sublist("Ifpack2")
      .sublist("Ifpack2 Settings");
}

// Additive Schwarz with an exact LU of each rank's rows (Amesos2 KLU2 on a one-rank
// matrix), the settings Trilinos 13.2's Stratimikos list lacks (solver/Ifpack2Factory.hpp).
TEST(LinearSolver, SchwarzWithKlu2Subdomains) {
  Teuchos::ParameterList p;
  auto& settings = ifpack2Settings(p, "SCHWARZ");
  settings.set("schwarz: inner preconditioner name", std::string("AMESOS2"));
  auto& inner = settings.sublist("schwarz: inner preconditioner parameters");
  inner.set("Amesos2 solver name", std::string("klu2"));
  inner.sublist("Amesos2");
  expectSolves(p);
}

// LAPACK's banded LU of each rank's rows through Ifpack2 (block relaxation, one banded block
// per rank).  Over the default ILUT its settings are not merged with ILUT's, which a block
// relaxation rejects; ILUT's own settings still merge.
TEST(LinearSolver, BandedLuOverTheIlutDefault) {
  Teuchos::ParameterList p;
  auto& settings = ifpack2Settings(p, "BLOCK_RELAXATION");
  settings.set("relaxation: container", std::string("Banded"));
  settings.set("partitioner: type", std::string("linear"));
  settings.set("partitioner: local parts", 1);
  settings.set("relaxation: type", std::string("Jacobi"));
  const auto merged = mergedIfpack2Settings(p);
  EXPECT_FALSE(merged.isParameter("fact: ilut level-of-fill"));
  EXPECT_EQ(merged.numParams(), 4);
  expectSolves(p);
  Teuchos::ParameterList tuned;
  ifpack2Settings(tuned, "ILUT").set("fact: ilut level-of-fill", 1.0);
  const auto kept = mergedIfpack2Settings(tuned);
  EXPECT_EQ(kept.get<double>("fact: ilut level-of-fill"), 1.0);
  EXPECT_TRUE(kept.isParameter("fact: drop tolerance"));
}

// A non-symmetric banded matrix of n unknowns, two bands below the diagonal and one above
// (row i: 4 at i, -1 at i - 1, -0.5 at i - 2, -2 at i + 1); with `withinRanks` only the
// couplings between unknowns of the same rank.  Its LU needs no row exchanges; with
// `exchanges` every tenth diagonal entry is 0.1, smaller than the one below it, so partial
// pivoting exchanges those rows (and the matrix stays well conditioned).
Teuchos::RCP<CrsMatrix> bandedMatrix(const Teuchos::RCP<const Comm>& comm, GO n, bool withinRanks,
                                     bool lastRankEmpty = false, bool exchanges = false) {
  const int ranks = comm->getSize(), filled = lastRankEmpty && ranks > 1 ? ranks - 1 : ranks;
  const int rank = comm->getRank();
  const GO share = n / filled, own = rank >= filled ? 0 : share + (rank < n % filled ? 1 : 0);
  auto map = Teuchos::rcp(new Map(n, static_cast<std::size_t>(own), 0, comm));
  auto A = Teuchos::rcp(new CrsMatrix(map, 4));
  for (std::size_t k = 0; k < map->getNodeNumElements(); ++k) {
    const GO i = map->getGlobalElement(k);
    const double diagonal = exchanges && i % 10 == 5 ? 0.1 : 4.0;
    std::vector<GO> cols;
    std::vector<double> vals;
    for (const auto& [j, v] :
         {std::pair<GO, double>{i - 2, -0.5}, {i - 1, -1.0}, {i, diagonal}, {i + 1, -2.0}})
      if (j >= 0 && j < n && (!withinRanks || map->isNodeGlobalElement(j)))
        cols.push_back(j), vals.push_back(v);
    A->insertGlobalValues(i, Teuchos::ArrayView<const GO>(cols),
                          Teuchos::ArrayView<const double>(vals));
  }
  A->fillComplete();
  return A;
}

// On a matrix without couplings between ranks the banded LU is its exact inverse, on any
// number of ranks: M (A x) = x, with the bandwidths read from the rows.  Both ways of
// solving with the factors are checked: the banded triangular solves of a factorisation
// without row exchanges, and LAPACK's dgbtrs with them.
TEST(BandedLU, InvertsEachRanksRowsExactly) {
  auto comm = Teuchos::DefaultComm<int>::getComm();
  for (const bool exchanges : {false, true}) {
    const auto A = bandedMatrix(comm, 101, true, false, exchanges);
    const BandedLU M(*A);
    EXPECT_EQ(M.lowerBandwidth(), 2);
    EXPECT_EQ(M.upperBandwidth(), 1);
    EXPECT_EQ(M.interchangedRows(), exchanges);
    Vector x(A->getRowMap()), b(A->getRowMap()), y(A->getRowMap());
    for (std::size_t k = 0; k < x.getLocalLength(); ++k)
      x.replaceLocalValue(k, std::sin(1.0 + A->getRowMap()->getGlobalElement(k)));
    A->apply(x, b);
    y.putScalar(7.0);  // beta = 0 overwrites it
    M.apply(b, y);
    y.update(-1.0, x, 1.0);
    EXPECT_LT(y.normInf(), 1e-13) << "row exchanges " << exchanges;
    // Y = alpha M X + beta Y
    Vector z(x, Teuchos::Copy);
    M.apply(b, z, Teuchos::NO_TRANS, 2.0, -1.0);  // 2 x - x
    z.update(-1.0, x, 1.0);
    EXPECT_LT(z.normInf(), 1e-13) << "row exchanges " << exchanges;
    M.apply(b, z, Teuchos::NO_TRANS, 3.0, 0.0);  // 3 x
    z.update(-3.0, x, 1.0);
    EXPECT_LT(z.normInf(), 3e-13) << "row exchanges " << exchanges;
  }
}

// Where the rows couple across ranks, the banded LU restores the couplings exactly: M (A x)
// = x on any number of ranks, also with a rank that holds no rows.  Each rank boundary
// adds kl + ku = 3 interface unknowns.  Without the coupling (block Jacobi) it is not the
// inverse on several ranks.
TEST(BandedLU, InvertsTheMatrixAcrossRanks) {
  auto comm = Teuchos::DefaultComm<int>::getComm();
  for (const auto& [lastRankEmpty, exchanges] :
       {std::pair{false, false}, {true, false}, {false, true}}) {
    const auto A = bandedMatrix(comm, 101, false, lastRankEmpty, exchanges);
    const int boundaries = comm->getSize() - (lastRankEmpty && comm->getSize() > 1 ? 2 : 1);
    const auto error = [&](bool acrossRanks, double alpha, double beta) {
      const BandedLU M(*A, acrossRanks);
      EXPECT_EQ(M.interfaceSize(), acrossRanks ? 3 * boundaries : 0);
      Vector x(A->getRowMap()), b(A->getRowMap());
      for (std::size_t k = 0; k < x.getLocalLength(); ++k)
        x.replaceLocalValue(k, std::sin(1.0 + A->getRowMap()->getGlobalElement(k)));
      A->apply(x, b);
      Vector y(x, Teuchos::Copy);  // beta x, so that alpha + beta times x is expected
      M.apply(b, y, Teuchos::NO_TRANS, alpha, beta);
      y.update(-(alpha + beta), x, 1.0);
      return y.normInf();
    };
    for (const auto& [alpha, beta] : {std::pair{1.0, 0.0}, {2.0, -1.0}, {3.0, 0.0}})
      EXPECT_LT(error(true, alpha, beta), 1e-13 * (alpha + std::abs(beta)))
          << "alpha " << alpha << " beta " << beta << " last rank empty " << lastRankEmpty
          << " row exchanges " << exchanges;
    if (boundaries > 0) {
      EXPECT_GT(error(false, 1.0, 0.0), 1e-3);
    }
  }
}

// A zero row makes a block singular: a NumericalError naming the unknown on every rank (so
// that none waits for the others in a collective call), not a crash.
// A kept preconditioner on a Jacobian with rows decoupled since its build: the rows that
// hold their diagonal alone (an explicit zero beside it too, as in a kept graph) are found,
// solved by a division, and left out of the kept preconditioner's input; the other rows
// are the kept preconditioner's.  Y = alpha op(X) + beta Y, on any number of ranks.
TEST(DecoupledRows, SolvedExactlyAndLeftOutOfTheKeptPreconditioner) {
  auto comm = Teuchos::DefaultComm<int>::getComm();
  const auto M = bandedMatrix(comm, 101, false);  // stands for the kept preconditioner
  const auto map = M->getRowMap();
  auto J = Teuchos::rcp(new CrsMatrix(map, 4));
  auto decoupledAt = [](GO i) { return i % 7 == 3; };
  for (std::size_t k = 0; k < map->getNodeNumElements(); ++k) {
    const GO i = map->getGlobalElement(k);
    std::vector<GO> cols{i};
    std::vector<double> vals{decoupledAt(i) ? 2.0 + i : 4.0};
    for (GO j : {i - 1, i + 1})
      if (j >= 0 && j < 101)
        cols.push_back(j), vals.push_back(decoupledAt(i) ? 0.0 : -1.0);
    J->insertGlobalValues(i, Teuchos::ArrayView<const GO>(cols),
                          Teuchos::ArrayView<const double>(vals));
  }
  J->fillComplete();
  const DecoupledRows found = decoupledRows(*J);
  std::vector<LO> expected;
  for (std::size_t k = 0; k < map->getNodeNumElements(); ++k)
    if (decoupledAt(map->getGlobalElement(k)))
      expected.push_back(static_cast<LO>(k));
  const auto foundRows = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), found.rows);
  ASSERT_EQ(std::vector<LO>(foundRows.data(), foundRows.data() + foundRows.extent(0)), expected);

  auto space = Thyra::tpetraVectorSpace<double>(map);
  const auto W = withDecoupledRows(Thyra::tpetraLinearOp<double, LO, GO, Node>(
                                       space, space, Teuchos::rcp_const_cast<CrsMatrix>(M)),
                                   map, found);
  auto x = Teuchos::rcp(new Vector(map)), y = Teuchos::rcp(new Vector(map));
  Vector z(map), expectedY(map);
  for (std::size_t k = 0; k < map->getNodeNumElements(); ++k) {
    const GO i = map->getGlobalElement(k);
    x->replaceLocalValue(k, std::sin(1.0 + i));
    z.replaceLocalValue(k, decoupledAt(i) ? 0.0 : std::sin(1.0 + i));
  }
  M->apply(z, expectedY);  // M z on the coupled rows
  for (std::size_t k = 0; k < map->getNodeNumElements(); ++k) {
    const GO i = map->getGlobalElement(k);
    if (decoupledAt(i))
      expectedY.replaceLocalValue(k, std::sin(1.0 + i) / (2.0 + i));
  }
  y->putScalar(1.0);
  Teuchos::RCP<const Thyra::VectorSpaceBase<double>> base = space;
  Thyra::apply(*W, Thyra::NOTRANS,
               *Thyra::createConstVector<double, LO, GO, Node>(x.getConst(), base),
               Thyra::createVector<double, LO, GO, Node>(y, base).ptr(), 2.0, -3.0);  // 2 W x - 3
  expectedY.scale(2.0);
  Vector ones(map);
  ones.putScalar(1.0);
  expectedY.update(-3.0, ones, 1.0);
  y->update(-1.0, expectedY, 1.0);
  EXPECT_LT(y->normInf(), 1e-14);
}

TEST(BandedLU, SingularRowsAreANumericalError) {
  auto comm = Teuchos::DefaultComm<int>::getComm();
  auto map = Teuchos::rcp(new Map(GO(4 * comm->getSize()), 0, comm));
  auto A = Teuchos::rcp(new CrsMatrix(map, 1));
  for (std::size_t k = 0; k < map->getNodeNumElements(); ++k) {
    const GO i = map->getGlobalElement(k);
    const double v = k == 2 ? 0.0 : 1.0;
    A->insertGlobalValues(i, Teuchos::tuple<GO>(i), Teuchos::tuple<double>(v));
  }
  A->fillComplete();
  try {
    BandedLU M(*A);
    FAIL() << "no error";
  } catch (const NumericalError& e) {
    // every rank throws, naming the lowest zero pivot: rank 0's third unknown
    EXPECT_NE(std::string(e.what()).find("zero pivot at unknown 2"), std::string::npos) << e.what();
  }
}

// A matrix can be singular while every rank's block is not: all ones, one row per rank.
// The coupled banded LU then says so on every rank; block Jacobi (the identity here) builds.
TEST(BandedLU, SingularCouplingIsANumericalError) {
  auto comm = Teuchos::DefaultComm<int>::getComm();
  const GO n = comm->getSize();
  auto map = Teuchos::rcp(new Map(n, 0, comm));
  auto A = Teuchos::rcp(new CrsMatrix(map, n));
  for (std::size_t k = 0; k < map->getNodeNumElements(); ++k) {
    std::vector<GO> cols(n);
    std::iota(cols.begin(), cols.end(), GO(0));
    A->insertGlobalValues(map->getGlobalElement(k), Teuchos::ArrayView<const GO>(cols),
                          Teuchos::ArrayView<const double>(std::vector<double>(n, 1.0)));
  }
  A->fillComplete();
  EXPECT_NO_THROW(BandedLU(*A, false));
  if (n == 1) {
    EXPECT_NO_THROW(BandedLU(*A, true));
    return;
  }
  try {
    BandedLU M(*A, true);
    FAIL() << "no error";
  } catch (const NumericalError& e) {
    EXPECT_NE(std::string(e.what()).find("coupling across ranks is singular"), std::string::npos)
        << e.what();
  }
}

// Through Stratimikos as the deck's "Banded LU": exact on any number of ranks, so GMRES
// needs one iteration where the rows couple across ranks; block Jacobi when asked.
TEST(LinearSolver, BandedLuPreconditioner) {
  Teuchos::ParameterList p;
  p.set("Preconditioner Type", "Banded LU");
  expectSolves(p);
  auto comm = Teuchos::DefaultComm<int>::getComm();
  const auto coupled = bandedMatrix(comm, 200, false);
  const auto merged = mergedLinearSolverParameters(p, OperatorKind::small, 1, comm->getSize());
  EXPECT_EQ(expectSolvesFull(merged, coupled), 1);
  auto blocks = merged;
  blocks.sublist("Preconditioner Types").sublist("Banded LU").set("Across Ranks", "block Jacobi");
  const int iterations = expectSolvesFull(blocks, coupled);
  if (comm->getSize() > 1) {
    EXPECT_GT(iterations, 1);
  }
  blocks.sublist("Preconditioner Types").sublist("Banded LU").set("Across Ranks", "nearly");
  EXPECT_THROW(createLinearSolveStrategy(blocks, comm, "deck.xml"), InputError);
}

// The MueLu list of the 2-D symmetric default on `ranks` ranks, merged with a deck's list
// that sets MueLu's `key` to `value`.
template <class T>
Teuchos::ParameterList mergedMueLu(int ranks, const std::string& key, const T& value) {
  Teuchos::ParameterList deck;
  deck.sublist("Preconditioner Types").sublist("MueLu").set(key, value);
  return mergedLinearSolverParameters(deck, OperatorKind::symmetricStiffness, 2, ranks)
      .sublist("Preconditioner Types")
      .sublist("MueLu");
}

// The default's smoother is a forward sweep before and a backward one after; a deck that
// names any smoother parameter replaces it whole (MueLu takes `smoother: pre type` over
// `smoother: type`), one that names other MueLu parameters keeps it.
// A deck that chooses MueLu where impm's default is another preconditioner (grids under
// 4000 nodes, mass-dominated steps) gets impm's multigrid settings for the dimension, not
// MueLu's own (one unknown per node: 50-63 Krylov iterations per load step on the 2-D columns
// 16-20 cells wide against 16-18 with these settings, doc/performance.md); chosen by name
// or by configuring the MueLu sublist alone.
TEST(LinearSolver, DeckChoosingMueLuStartsFromImpmsSettings) {
  Teuchos::ParameterList named;
  named.set("Preconditioner Type", std::string("MueLu"));
  Teuchos::ParameterList configured;
  configured.sublist("Preconditioner Types").sublist("MueLu").set("verbosity", std::string("none"));
  for (const auto kind : {OperatorKind::small, OperatorKind::massDominated})
    for (const auto* deck : {&named, &configured}) {
      const auto p = mergedLinearSolverParameters(*deck, kind, 2, 1);
      ASSERT_EQ(p.get<std::string>("Preconditioner Type"), "MueLu");
      const auto& muelu = p.sublist("Preconditioner Types").sublist("MueLu");
      EXPECT_EQ(muelu.get<int>("number of equations"), 2);
      EXPECT_EQ(muelu.get<std::string>("smoother: pre type"), "RELAXATION");
      EXPECT_EQ(muelu.get<std::string>("coarse: type"), "KLU2");
    }
  // Another choice leaves the default's list as it was: no MueLu settings are added.
  Teuchos::ParameterList ilut;
  ilut.set("Preconditioner Type", std::string("Ifpack2"));
  const auto p = mergedLinearSolverParameters(ilut, OperatorKind::small, 2, 1);
  EXPECT_FALSE(p.sublist("Preconditioner Types").isSublist("MueLu"));
}

TEST(LinearSolver, DeckSmootherReplacesTheDefaultOne) {
  const auto kept = mergedMueLu(1, "coarse: max size", 500);
  EXPECT_EQ(kept.get<int>("coarse: max size"), 500);
  EXPECT_EQ(kept.sublist("smoother: pre params").get<std::string>("relaxation: type"),
            "Gauss-Seidel");
  EXPECT_TRUE(kept.sublist("smoother: post params").get<bool>("relaxation: backward mode"));
  const auto replaced = mergedMueLu(1, "smoother: type", std::string("CHEBYSHEV"));
  EXPECT_EQ(replaced.get<std::string>("smoother: type"), "CHEBYSHEV");
  for (const char* key : {"smoother: pre type", "smoother: pre params", "smoother: post type",
                          "smoother: post params"})
    EXPECT_FALSE(replaced.isParameter(key)) << key;
  EXPECT_EQ(replaced.get<double>("aggregation: drop tol"), 0.05);  // the rest stays
}

// On several ranks the default's coarse solver is Gauss-Seidel sweeps: a deck that names
// another coarse type drops their parameters (Amesos2's solvers reject them, Ifpack2's
// ignore them), one that only tunes the coarse level keeps them.
TEST(LinearSolver, DeckCoarseTypeReplacesTheDefaultCoarseParameters) {
  const auto kept = mergedMueLu(2, "coarse: max size", 500);
  EXPECT_EQ(kept.get<std::string>("coarse: type"), "RELAXATION");
  EXPECT_EQ(kept.sublist("coarse: params").get<int>("relaxation: sweeps"), 30);
  const auto replaced = mergedMueLu(2, "coarse: type", std::string("ILUT"));
  EXPECT_EQ(replaced.get<std::string>("coarse: type"), "ILUT");
  EXPECT_FALSE(replaced.isParameter("coarse: params"));
  EXPECT_EQ(replaced.get<double>("aggregation: drop tol"), 0.05);  // the rest stays
  // The 1-D default has no MueLu list, and naming none leaves it so.
  EXPECT_FALSE(mergedLinearSolverParameters(Teuchos::ParameterList(), OperatorKind::small, 1, 2)
                   .sublist("Preconditioner Types")
                   .isSublist("MueLu"));
}

TEST(LinearSolver, RilukByKokkosKernels) {
  Teuchos::ParameterList p;
  ifpack2Settings(p, "RILUK").set("fact: type", std::string("KSPILUK"));
  expectSolves(p);
}

TEST(LinearSolver, CgWithMueLu) {
  Teuchos::ParameterList p;
  p.set("Preconditioner Type", std::string("MueLu"));
  auto& belos = p.sublist("Linear Solver Types").sublist("Belos");
  belos.set("Solver Type", std::string("Block CG"));
  belos.sublist("Solver Types").sublist("Block CG").set("Maximum Iterations", 500);
  belos.sublist("Solver Types").sublist("Block CG").set("Convergence Tolerance", 1e-10);
  // KLU2 is unreliable on several ranks in Trilinos 13.2: relax on the coarse level.
  p.sublist("Preconditioner Types").sublist("MueLu").set("coarse: type", std::string("RELAXATION"));
  expectSolves(p);
}

}  // namespace
}  // namespace impm

#include "solver/DiagonalSolve.hpp"

namespace impm {
namespace {

// Ifpack2's ILUT factory (the small systems' default preconditioner).
Teuchos::RCP<Thyra::PreconditionerFactoryBase<double>> ilutFactory(
    const Teuchos::RCP<const Comm>& comm) {
  Teuchos::ParameterList ilut;
  ilut.set("Preconditioner Type", "Ifpack2");
  return createLinearSolveStrategy(
             mergedLinearSolverParameters(ilut, OperatorKind::small, 1, comm->getSize()), comm,
             "test")
      ->getPreconditionerFactory();
}

// A reuse factory over it with the default rules.
Teuchos::RCP<ReusingPreconditionerFactory> ilutReuse(const Teuchos::RCP<const Comm>& comm) {
  return Teuchos::rcp(new ReusingPreconditionerFactory(ilutFactory(comm), false, ReuseRules{}));
}

// A kept preconditioner stays while the next unknowns are its own (to be reused), and goes,
// with its hold on the matrix it was built from, as soon as they differ.  Ifpack2's ILUT
// holds its matrix (the banded LU, the 1-D default, copies it into its band).
TEST(PreconditionerReuse, ReleasedWhenTheUnknownsChange) {
  auto comm = Teuchos::DefaultComm<int>::getComm();
  auto A = laplacian(comm, 200);
  const auto reuse = ilutReuse(comm);
  auto prec = reuse->createPrec();
  reuse->initializePrec(Thyra::defaultLinearOpSource(thyraOperator(A)), prec.get(),
                        Thyra::SUPPORT_SOLVE_UNSPECIFIED);
  ASSERT_FALSE(prec->getUnspecifiedPrecOp().is_null());
  EXPECT_GT(A.strong_count(), 1);
  reuse->releaseUnlessFor(*A->getRowMap(), prec.get());
  EXPECT_FALSE(prec->getUnspecifiedPrecOp().is_null());
  reuse->releaseUnlessFor(Map(201, 0, comm), prec.get());
  EXPECT_TRUE(prec->getUnspecifiedPrecOp().is_null());
  EXPECT_EQ(A.strong_count(), 1);
  // The next request builds a new one, also for the old unknowns.
  reuse->initializePrec(Thyra::defaultLinearOpSource(thyraOperator(A)), prec.get(),
                        Thyra::SUPPORT_SOLVE_UNSPECIFIED);
  EXPECT_EQ(reuse->counts().builds, 2);
  EXPECT_EQ(reuse->counts().reuses, 0);
}

// Drives an ILUT reuse factory through linear solves of given outcomes, on a Laplacian.
struct ReuseDriver {
  Teuchos::RCP<const Comm> comm = Teuchos::DefaultComm<int>::getComm();
  Teuchos::RCP<CrsMatrix> A = laplacian(comm, 200);
  Teuchos::RCP<ReusingPreconditionerFactory> reuse = ilutReuse(comm);
  Teuchos::RCP<Thyra::PreconditionerBase<double>> prec = reuse->createPrec();

  // One linear solve that took `iterations` to `tolerance`; `first`: the first of a Newton
  // solve.  Returns the builds and reuses so far.
  std::pair<int, int> solve(bool first, int iterations, double tolerance = 1e-10) {
    if (first)
      reuse->startSolve();
    reuse->initializePrec(Thyra::defaultLinearOpSource(thyraOperator(A)), prec.get(),
                          Thyra::SUPPORT_SOLVE_UNSPECIFIED);
    reuse->recordSolve(iterations, true, tolerance);
    return {reuse->counts().builds, reuse->counts().reuses};
  }
};

// A preconditioner kept from one Newton solve serves the next one's first linear solve (is
// carried into the next step) until a carry's first solve goes past the rebuild limit; from
// then on every Newton solve starts with a new one, while reuse within a solve goes on, until
// the preconditioner is forgotten (a checkpoint).
TEST(PreconditionerReuse, CarriesStopAfterOneThatDidNotPay) {
  ReuseDriver driver;
  const auto solve = [&](bool first, int iterations) { return driver.solve(first, iterations); };
  // The limit is 2 x 10 iterations.
  EXPECT_EQ(solve(true, 10), std::pair(1, 0));
  EXPECT_EQ(solve(true, 20), std::pair(1, 1));   // carried, within the limit
  EXPECT_EQ(solve(true, 21), std::pair(1, 2));   // carried, past it: carries stop
  EXPECT_EQ(solve(true, 10), std::pair(2, 2));   // rebuilt (the last solve went past)
  EXPECT_EQ(solve(false, 12), std::pair(2, 3));  // reused within the Newton solve
  EXPECT_EQ(solve(true, 10), std::pair(3, 3));   // not carried, though within the limit
  EXPECT_EQ(solve(true, 10), std::pair(4, 3));
  driver.reuse->forget();  // as a restarted run: carries again
  EXPECT_EQ(solve(true, 10), std::pair(5, 3));
  EXPECT_EQ(solve(true, 10), std::pair(5, 4));
}

// Solves to other tolerances compare by iterations per decade of residual reduction: a
// build whose first solve stopped early (a Newton iteration near its target, at 0.1) is
// not judged stale by the next full solve (to 1e-10) for taking more iterations.
TEST(PreconditionerReuse, SolvesToOtherTolerancesCompareByDecade) {
  ReuseDriver driver;
  const auto solve = [&](int iterations, double tolerance) {
    return driver.solve(false, iterations, tolerance);
  };
  EXPECT_EQ(solve(3, 0.1), std::pair(1, 0));     // 3 per decade: 30 expected at 1e-10
  EXPECT_EQ(solve(25, 1e-10), std::pair(1, 1));  // reused
  EXPECT_EQ(solve(25, 1e-10), std::pair(1, 2));  // within 2 x 30: reused again
  EXPECT_EQ(solve(61, 1e-10), std::pair(1, 3));  // past 2 x 30
  EXPECT_EQ(solve(20, 1e-10), std::pair(2, 3));  // so rebuilt
  EXPECT_EQ(solve(4, 0.1), std::pair(2, 4));     // 2 per decade expected; within the minimum
  EXPECT_EQ(solve(20, 1e-10), std::pair(2, 5));
}

// A MueLu hierarchy lets its Jacobian go when its Newton solve ends, before the next one is
// made (a new matrix: the particles reach other node pairs), is carried to the next one at
// its finest level (solver/FinestLevel.hpp), and preconditions it.
TEST(PreconditionerReuse, CarriedHierarchyLetsItsJacobianGo) {
  auto comm = Teuchos::DefaultComm<int>::getComm();
  // Enough unknowns for a second level (the coarse level is at most 1000 rows).
  auto built = laplacian(comm, 4000), next = laplacian(comm, 4000);
  const auto lows = createLinearSolveStrategy(
      defaultLinearSolverParameters(OperatorKind::symmetricStiffness, 2, comm->getSize()), comm,
      "test");
  const auto reuse = Teuchos::rcp(
      new ReusingPreconditionerFactory(lows->getPreconditionerFactory(), true, ReuseRules{}));
  auto prec = reuse->createPrec();
  reuse->startSolve();
  reuse->initializePrec(Thyra::defaultLinearOpSource(thyraOperator(built)), prec.get(),
                        Thyra::SUPPORT_SOLVE_UNSPECIFIED);
  reuse->recordSolve(10, true, 1e-10);
  EXPECT_GT(built.strong_count(), 1);
  reuse->endSolve();  // the Jacobian goes before the next one is made
  EXPECT_FALSE(prec->getUnspecifiedPrecOp().is_null());
  EXPECT_EQ(built.strong_count(), 1);
  reuse->startSolve();  // the next step: carried
  reuse->initializePrec(Thyra::defaultLinearOpSource(thyraOperator(next)), prec.get(),
                        Thyra::SUPPORT_SOLVE_UNSPECIFIED);
  EXPECT_EQ(reuse->counts().builds, 1);
  EXPECT_EQ(reuse->counts().reuses, 1);
  EXPECT_EQ(built.strong_count(), 1);

  auto solver = lows->createOp();
  Thyra::initializePreconditionedOp<double>(*lows, thyraOperator(next), prec, solver.ptr());
  const auto map = next->getRowMap();
  auto b = Teuchos::rcp(new Vector(map)), x = Teuchos::rcp(new Vector(map));
  b->putScalar(1.0);
  solver->solve(Thyra::NOTRANS, *Thyra::createConstVector<double, LO, GO, Node>(b),
                Thyra::createVector<double, LO, GO, Node>(x).ptr());
  Vector r(map);
  next->apply(*x, r);
  r.update(1.0, *b, -1.0);
  EXPECT_LT(r.norm2(), 1e-8 * b->norm2());
}

// Ifpack2's factory, made to throw in the build after `throwNext` is set; it records
// whether the preconditioner it was handed held an operator (was being refreshed).
class ThrowingFactory : public Thyra::PreconditionerFactoryBase<double> {
 public:
  explicit ThrowingFactory(Teuchos::RCP<Thyra::PreconditionerFactoryBase<double>> inner)
      : inner_(std::move(inner)) {}
  bool throwNext = false;
  mutable bool handedBuilt = false;

  bool isCompatible(const Thyra::LinearOpSourceBase<double>& src) const override {
    return inner_->isCompatible(src);
  }
  Teuchos::RCP<Thyra::PreconditionerBase<double>> createPrec() const override {
    return inner_->createPrec();
  }
  void initializePrec(const Teuchos::RCP<const Thyra::LinearOpSourceBase<double>>& src,
                      Thyra::PreconditionerBase<double>* prec,
                      Thyra::ESupportSolveUse use) const override {
    handedBuilt = !prec->getUnspecifiedPrecOp().is_null();
    if (throwNext)
      throw std::runtime_error("build failed");
    inner_->initializePrec(src, prec, use);
  }
  void uninitializePrec(Thyra::PreconditionerBase<double>* prec,
                        Teuchos::RCP<const Thyra::LinearOpSourceBase<double>>* src,
                        Thyra::ESupportSolveUse* use) const override {
    inner_->uninitializePrec(prec, src, use);
  }
  void setParameterList(const Teuchos::RCP<Teuchos::ParameterList>& list) override {
    inner_->setParameterList(list);
  }
  Teuchos::RCP<Teuchos::ParameterList> getNonconstParameterList() override {
    return inner_->getNonconstParameterList();
  }
  Teuchos::RCP<Teuchos::ParameterList> unsetParameterList() override {
    return inner_->unsetParameterList();
  }

 private:
  Teuchos::RCP<Thyra::PreconditionerFactoryBase<double>> inner_;
};

// A build that threw is not refreshed by the next request (a cut-back step's): MueLu's
// levels are then missing data, and every retry threw again ("Level::Clear found Internal
// data inconsistency") until the step could not be cut further.  The next build starts over.
TEST(PreconditionerReuse, ABuildThatThrewStartsOver) {
  auto comm = Teuchos::DefaultComm<int>::getComm();
  auto A = laplacian(comm, 200);
  const auto throwing = Teuchos::rcp(new ThrowingFactory(ilutFactory(comm)));
  ReusingPreconditionerFactory reuse(throwing, false, ReuseRules{});
  auto prec = reuse.createPrec();
  const auto build = [&] {
    reuse.initializePrec(Thyra::defaultLinearOpSource(thyraOperator(A)), prec.get(),
                         Thyra::SUPPORT_SOLVE_UNSPECIFIED);
  };
  build();
  reuse.recordSolve(100, false, 1e-10);  // a failed solve: the next request rebuilds
  build();
  EXPECT_TRUE(throwing->handedBuilt);  // refreshed in place, as it should be
  reuse.recordSolve(100, false, 1e-10);
  throwing->throwNext = true;
  EXPECT_THROW(build(), std::runtime_error);
  throwing->throwNext = false;
  build();
  EXPECT_FALSE(throwing->handedBuilt);
  EXPECT_EQ(reuse.counts().builds, 3);
}

// The explicit step's elimination against the direct solution: 6 nodal unknowns with a
// diagonal block and 2 extras coupled to a few of them (as Robin ends are), spread over the
// ranks: x must solve J x = b to round-off.
// The column map lists each rank's own columns first (as the grid system's does: the
// diagonal is read in place) or in reverse (Tpetra's diagonal copy).  On 3 ranks the last
// one holds the extras only, none of the nodal rows they couple to.
void expectEliminationSolves(bool ownColumnsFirst) {
  auto comm = Teuchos::DefaultComm<int>::getComm();
  const GO n = 8;  // 0..5 nodal, 6 and 7 extras
  auto map = Teuchos::rcp(new Map(n, 0, comm));
  // Dense J: diag 2 + i on nodal rows; extra 6 couples to nodes 0, 1; extra 7 to node 5.
  double J[8][8] = {};
  for (int i = 0; i < 6; ++i)
    J[i][i] = 2.0 + i;
  J[0][6] = -0.5, J[1][6] = -0.5, J[6][0] = 1.0, J[6][1] = 0.25, J[6][6] = 0.1;
  J[5][7] = -1.0, J[7][5] = 2.0, J[7][7] = 0.0;
  std::vector<GO> columns;
  for (GO g = 0; g < n; ++g)
    if (map->isNodeGlobalElement(g))
      columns.push_back(g);
  for (GO g = 0; g < n; ++g)
    if (!map->isNodeGlobalElement(g))
      columns.push_back(g);
  if (!ownColumnsFirst)
    std::reverse(columns.begin(), columns.end());
  auto columnMap = Teuchos::rcp(new Map(Teuchos::OrdinalTraits<Tpetra::global_size_t>::invalid(),
                                        Teuchos::ArrayView<const GO>(columns), 0, comm));
  CrsMatrix A(map, columnMap, 8);
  for (GO g = 0; g < n; ++g) {
    if (!map->isNodeGlobalElement(g))
      continue;
    std::vector<GO> cols;
    std::vector<double> vals;
    for (GO c = 0; c < n; ++c)
      if (J[g][c] != 0.0)
        cols.push_back(c), vals.push_back(J[g][c]);
    A.insertGlobalValues(g, Teuchos::ArrayView<const GO>(cols),
                         Teuchos::ArrayView<const double>(vals));
  }
  A.fillComplete();
  ASSERT_EQ(A.getColMap()->isLocallyFitted(*map), ownColumnsFirst);
  Vector nodal(map);
  for (GO g = 0; g < n; ++g)
    if (map->isNodeGlobalElement(g))
      nodal.replaceGlobalValue(g, g < 6 ? 1.0 : 0.0);
  // Eliminated once, solved for two right-hand sides (as an explicit run's steps do).
  const DiagonalElimination elimination(A, nodal, {6, 7});
  const double rhs[2][8] = {{1, -2, 3, 0.5, -1, 4, 0.3, -0.7}, {-4, 0, 2, 7, 1, -1, -2, 5}};
  for (const auto& values : rhs) {
    Vector b(map), x(map);
    for (GO g = 0; g < n; ++g)
      if (map->isNodeGlobalElement(g))
        b.replaceGlobalValue(g, values[g]);
    elimination.solve(b, x);
    // J x = b, checked row by row.
    Vector r(map);
    A.apply(x, r);
    r.update(-1.0, b, 1.0);
    EXPECT_LT(r.normInf(), 1e-14);
  }
}

TEST(DiagonalSolve, EliminatesTheExtrasAndDivides) {
  expectEliminationSolves(true);
  expectEliminationSolves(false);
}

}  // namespace
}  // namespace impm
