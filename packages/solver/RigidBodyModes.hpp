#pragma once
// The rigid-body modes of the grid's displacement unknowns: the near-null space of a
// stiffness matrix, which smoothed-aggregation multigrid interpolates exactly.  Dim
// translations and Dim (Dim - 1) / 2 infinitesimal rotations about the grid's centre
// (rotation in the a-b plane: u_a = -(x_b - c_b), u_b = x_a - c_a), one column each.
// Extra unknowns (boundary forces) hold zeros; padding unknowns the translations, so that
// no aggregate of them is empty.

#include "core/DofMap.hpp"
#include "core/Grid.hpp"
#include "core/TpetraTypes.hpp"

namespace impm {

template <int Dim>
Teuchos::RCP<MultiVector> rigidBodyModes(const GridGeometry<Dim>& grid, const DofMap<Dim>& dofs);

}  // namespace impm
