#pragma once
// Load balance under large deformation: when the particles crowd onto some ranks (a column
// compressed to a third of its height, bodies that fly into one rank's cells), the grid's
// cells are partitioned again, weighted by the particles they hold, with Zoltan2's
// multi-jagged partitioner (rectangular parts, the geometric partitioning of a structured
// grid), and the particles follow their cells (core/Migration).

#include <vector>

#include "core/Decomposition.hpp"
#include "core/ParticleSet.hpp"
#include "core/TpetraTypes.hpp"

namespace impm {

// The ranks' particle counts, max / mean (1: balanced; 0 particles: 1).  Collective.
double particleImbalance(std::size_t localParticles, const Comm& comm);

// A decomposition of the same grid into comm.getSize() parts of about equal particle counts,
// and the particle imbalance it will have: each rank passes the particles it holds, which lie
// in its cells under `current`.  Collective; every rank gets the whole cell-to-rank table.
template <int Dim>
struct CellPartition {
  Decomposition<Dim> decomposition;
  double imbalance;
};
template <int Dim>
CellPartition<Dim> repartitionCells(const Decomposition<Dim>& current,
                                    const ParticleSet<Dim>& particles,
                                    const Teuchos::RCP<const Comm>& comm);

}  // namespace impm
