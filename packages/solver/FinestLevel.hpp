#pragma once
// A multigrid hierarchy carried to a new Jacobian works on that Jacobian at its finest level.
//
// A kept MueLu hierarchy (solver/PreconditionerReuse.hpp) serves later Jacobians of the same
// unknowns: its prolongators and coarse operators stay those of the Jacobian it was built
// from.  Its finest level held that Jacobian too, for the fine residual and the smoothers,
// so a step whose particles reached new node pairs (a new graph, a new matrix) solved with
// two Jacobians alive.  Now the finest level lets its Jacobian go when the Newton solve
// ends (it holds the identity meanwhile, never applied) and takes the next solve's Jacobian
// when the hierarchy is carried to it, its smoothers set up again there (a diagonal for
// Gauss-Seidel).  The V-cycle then smooths the system being solved: on the
// 64 x 512 column the carried steps took 16-22 Krylov iterations instead of 23-30.

#include <Thyra_LinearOpBase.hpp>

#include "core/TpetraTypes.hpp"

namespace impm {

// Makes `jacobian` the finest-level matrix of the MueLu hierarchy behind `prec`, with its
// smoothers set up again on it.  Does nothing (returns false) when `prec` is not a MueLu
// hierarchy or its finest level already holds `jacobian`.  Collective.
bool moveFinestLevelTo(const Thyra::LinearOpBase<double>& prec,
                       const Teuchos::RCP<const CrsMatrix>& jacobian);

// Lets the finest level of the MueLu hierarchy behind `prec` drop its matrix (the identity
// takes its place, with smoothers on it) until moveFinestLevelTo.  Returns false when `prec`
// is not a MueLu hierarchy.  Collective.
bool releaseFinestLevel(const Thyra::LinearOpBase<double>& prec);

}  // namespace impm
