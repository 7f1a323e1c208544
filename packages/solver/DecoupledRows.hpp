#pragma once
// A kept preconditioner made to fit a Jacobian whose rows were decoupled after it was built.
//
// A static step's layout may keep nodes that no particle reaches any more as unknowns
// (solver/SystemLayout.hpp: retired nodes), so that the unknowns, and with them a
// preconditioner built for an earlier Jacobian, stay the same.  A retired node's rows then
// hold their diagonal alone.  The kept preconditioner was built while those rows held the
// little stiffness of the particles about to leave, so it inverts them by large factors
// that the new diagonal does not have: the Krylov solve took 219 iterations instead of 16 on
// a 64 x 512 column.  Yet a row that holds its diagonal alone is solved exactly by a
// division, and the other rows do not see it.  So the kept preconditioner is applied to the
// coupled rows only (the decoupled rows' entries of the vector zeroed before it, its output
// there replaced by the divisions): 23-30 iterations on that column, with no rebuild.

#include <Thyra_LinearOpBase.hpp>

#include "core/TpetraTypes.hpp"
#include "core/Types.hpp"

namespace impm {

// The owned rows of a matrix whose only non-zero value is their diagonal, and the inverses
// of those diagonals (local).
struct DecoupledRows {
  Kokkos::View<LO*, DefaultMemSpace> rows;  // ascending
  Kokkos::View<double*, DefaultMemSpace> inverseDiagonal;
};

DecoupledRows decoupledRows(const CrsMatrix& matrix);

// Whether a and b list the same rows (local).
bool sameRows(const DecoupledRows& a, const DecoupledRows& b);

// `kept` on the coupled rows, the exact solve on `decoupled` (an operator on `map`).
Teuchos::RCP<Thyra::LinearOpBase<double>> withDecoupledRows(
    Teuchos::RCP<const Thyra::LinearOpBase<double>> kept, Teuchos::RCP<const Map> map,
    DecoupledRows decoupled);

}  // namespace impm
