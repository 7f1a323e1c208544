#pragma once
// Particles move to the rank that owns the cell holding their position (the architecture's
// parallel layout).  Every field whose specification says so travels (ParticleSet::
// forEachField), so nothing a particle carries is lost.  Every rank keeps its particles in
// the order of their ids (the creation order), and rebuilds its per-material index lists.

#include "core/Decomposition.hpp"
#include "core/ParticleSet.hpp"
#include "core/TpetraTypes.hpp"

namespace impm {

// Sends every particle to `destination(p)`.  Collective.  Returns the number of particles
// this rank sent away.
template <int Dim>
std::size_t migrateParticles(ParticleSet<Dim>& particles, const std::vector<int>& destination,
                             const Comm& comm);

// Sends every particle to the owner of the cell holding its position.  Collective.
template <int Dim>
std::size_t migrateToOwners(ParticleSet<Dim>& particles, const Decomposition<Dim>& decomposition,
                            const Comm& comm);

}  // namespace impm
