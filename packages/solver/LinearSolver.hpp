#pragma once
// Linear solvers through Stratimikos: Belos Krylov methods preconditioned by Ifpack2 or
// MueLu (both registered with the builder, which Trilinos 13.2 does not do by itself), or
// Amesos2 direct solvers on one rank.  The deck's Solver/Linear Solver sublist is a plain
// Stratimikos list, merged over impm's default (GMRES + ILUT).

#include <Teuchos_ParameterList.hpp>
#include <Thyra_LinearOpWithSolveFactoryBase.hpp>

#include "core/TpetraTypes.hpp"

namespace impm {

// impm's default Stratimikos list.
Teuchos::ParameterList defaultLinearSolverParameters();

// The Stratimikos strategy for `params` merged over the default.  Validates the list by
// solving a small system with rows on every rank of `comm` (so that Belos, Ifpack2 and MueLu check
// their sublists before any output exists); throws InputError(path, reason) when it is wrong.
Teuchos::RCP<Thyra::LinearOpWithSolveFactoryBase<double>> createLinearSolveStrategy(
    const Teuchos::ParameterList& params, const Teuchos::RCP<const Comm>& comm,
    const std::string& path);

// Solves A x = b with the strategy (x holds the guess on entry).  Throws NumericalError
// when the solver does not converge.
void solveLinearSystem(const Thyra::LinearOpWithSolveFactoryBase<double>& lows,
                       const Teuchos::RCP<const CrsMatrix>& A, const Vector& b, Vector& x);

}  // namespace impm
