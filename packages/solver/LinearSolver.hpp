#pragma once
// Linear solvers through Stratimikos: Belos Krylov methods preconditioned by Ifpack2 or
// MueLu (both registered with the builder, which Trilinos 13.2 does not do by itself), or
// Amesos2 direct solvers on one rank.  The deck's Solver/Linear Solver sublist is a plain
// Stratimikos list, merged over impm's default for the kind of operator the run solves
// (doc/performance.md records what was measured to choose them):
//   - small systems: every 1-D one (with its Robin rows) and 2-D grids of fewer than 4000
//     nodes: GMRES + ILUT (close to an exact factorisation of a banded matrix, right with
//     the boundary-force unknowns and with nodes that barely touch a body);
//   - stiffness-dominated operators in 2-D (static steps, Newmark with time steps beyond
//     twice the wave transit time of a cell): MueLu smoothed aggregation, Dim unknowns per
//     node, the rigid-body modes as near-null space, symmetric Gauss-Seidel smoothing, a
//     direct coarse solve on one rank and an iterative one on several (Amesos2 KLU2 is wrong
//     there); with CG when every material's tangent is symmetric (hyperelastic laws: the
//     prescribed unknowns are eliminated symmetrically), GMRES otherwise (plasticity);
//   - mass-dominated operators (explicit steps, Newmark with short time steps: M/(beta dt^2)
//     outweighs K): CG + Jacobi, no factorisation.

#include <Teuchos_ParameterList.hpp>
#include <Thyra_LinearOpWithSolveFactoryBase.hpp>

#include "core/TpetraTypes.hpp"

namespace impm {

enum class OperatorKind { small, stiffness, symmetricStiffness, massDominated };

// impm's default Stratimikos list for an operator of that kind on `ranks` ranks.
Teuchos::ParameterList defaultLinearSolverParameters(OperatorKind kind, int dim, int ranks);

// The deck's list over the default.  A deck that configures one preconditioner's sublist
// ("Preconditioner Types/X") without naming "Preconditioner Type" gets X.
Teuchos::ParameterList mergedLinearSolverParameters(const Teuchos::ParameterList& deck,
                                                    OperatorKind kind, int dim, int ranks);

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
