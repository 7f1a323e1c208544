#pragma once
// Linear solvers through Stratimikos: MUMPS's sparse direct solve (solver/MumpsSolveStrategy,
// on any number of ranks), or Belos Krylov methods preconditioned by Ifpack2 or MueLu (both
// registered with the builder, which Trilinos 13.2 does not do by itself).  The deck's
// Solver/Linear Solver sublist is a plain Stratimikos list, merged over impm's default for
// the kind of operator the run solves (doc/performance.md records what was measured to
// choose them):
//   - 1-D systems (with their Robin rows): GMRES + the banded LU (exact on one rank);
//   - small grids (fewer than 4000 nodes in 2-D, 300 in 3-D) and stiffness-dominated
//     operators whose tangent may be non-symmetric (plasticity): MUMPS's LU.  Near a limit load the
//     plastic tangent is nearly singular: ILUT-preconditioned GMRES took 30-90 iterations a solve
//     there, and the strip footing's 10^4 particles ran 1508 s against 14 s;
//   - stiffness-dominated operators in 2-D and 3-D whose tangent is symmetric (hyperelastic laws,
//   the
//     prescribed unknowns eliminated symmetrically: static steps, Newmark with time steps
//     beyond twice the wave transit time of a cell): CG + MueLu smoothed aggregation, Dim
//     unknowns per node, the rigid-body modes as near-null space, symmetric Gauss-Seidel
//     smoothing, a direct coarse solve on one rank and an iterative one on several (Amesos2
//     KLU2 is wrong there);
//   - mass-dominated operators (explicit steps, Newmark with short time steps: M/(beta dt^2)
//     outweighs K): CG + Jacobi, no factorisation.

#include <Teuchos_ParameterList.hpp>
#include <Thyra_LinearOpWithSolveFactoryBase.hpp>

#include <string>

#include "core/TpetraTypes.hpp"

namespace impm {

enum class OperatorKind { small, stiffness, symmetricStiffness, massDominated };

// impm's default Stratimikos list for an operator of that kind on `ranks` ranks.
Teuchos::ParameterList defaultLinearSolverParameters(OperatorKind kind, int dim, int ranks);

// The deck's list over the default.  A deck that configures one preconditioner's sublist
// ("Preconditioner Types/X") without naming "Preconditioner Type" gets X.
Teuchos::ParameterList mergedLinearSolverParameters(const Teuchos::ParameterList& deck,
                                                    OperatorKind kind, int dim, int ranks);

// A few words naming the solver a full list (see mergedLinearSolverParameters) chooses, for
// the run's first line: "MUMPS LU", "GMRES + MueLu", "CG + Ifpack2 RELAXATION".
std::string describeLinearSolver(const Teuchos::ParameterList& params);

// The Stratimikos strategy for the full list `params` (see mergedLinearSolverParameters). Validates
// the list by solving a small system with rows on every rank of `comm` (so that Belos, Ifpack2 and
// MueLu check their sublists before any output exists); throws InputError(path, reason) when it is
// wrong.
Teuchos::RCP<Thyra::LinearOpWithSolveFactoryBase<double>> createLinearSolveStrategy(
    const Teuchos::ParameterList& params, const Teuchos::RCP<const Comm>& comm,
    const std::string& path);

// Solves A x = b with the strategy (x holds the guess on entry).  Throws NumericalError
// when the solver does not converge.
void solveLinearSystem(const Thyra::LinearOpWithSolveFactoryBase<double>& lows,
                       const Teuchos::RCP<const CrsMatrix>& A, const Vector& b, Vector& x);

}  // namespace impm
