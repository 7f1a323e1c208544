#pragma once
// CPDI2's corner update after a converged step: every tracked corner moves with the grid,
//   x_c += sum_i N_i(x_c) du_i,
// N_i evaluated where the step's map was built (updated Lagrangian: the corners at the start
// of the step; total Lagrangian: the reference corners).  The particle's map lists every node
// whose tent is non-zero at one of its corners (CornerWeights), so the sum runs over the map
// entries.  Corners outside the grid move with its edge (clipToGrid).

#include "assembly/EntryDofs.hpp"
#include "assembly/Kinematics.hpp"
#include "core/Grid.hpp"
#include "core/ParticleSet.hpp"

namespace impm {

// Does nothing when the particles carry no corners.
template <int Dim, class Space = DefaultExecSpace>
void moveCorners(Kinematics kinematics, const GridGeometry<Dim>& grid,
                 const ParticleGridMap<Dim, Space>& map, const EntryDofs<Space>& entryDofs,
                 const LocalValues& du, const ParticleSet<Dim, Space>& particles);

}  // namespace impm
