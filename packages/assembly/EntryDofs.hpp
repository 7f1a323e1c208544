#pragma once
// Local indices of the unknowns of the particle-grid map's entries.
//  - entryDofs: for every entry k, the index in the overlap map (the rows) of the first
//    displacement component of node(k); component d is that index + d, because DofMap lists
//    a node's components together (checked here).
//  - entryColumns: the index of every component in the Jacobian's column map.  Tpetra
//    builds that map and does not promise to keep a node's components together (on 4
//    ranks they were not), so each component is looked up.

#include "basis/ParticleGridMap.hpp"
#include "core/TpetraTypes.hpp"

namespace impm {

template <int Dim, class Space = DefaultExecSpace>
Kokkos::View<LO**, typename Space::memory_space> entryColumns(
    const ParticleGridMap<Dim, Space>& map, const Map& columns) {
  Kokkos::View<LO**, typename Space::memory_space> lids("entry columns", map.numEntries(), Dim);
  auto local = columns.getLocalMap();
  auto node = map.node;
  int missing = 0;
  Kokkos::parallel_reduce(
      "impm::entryColumns", RangePolicy<Space>(0, map.numEntries()),
      KOKKOS_LAMBDA(const std::size_t k, int& bad) {
        for (int d = 0; d < Dim; ++d) {
          lids(k, d) = local.getLocalElement(node(k) * Dim + d);
          if (lids(k, d) == Tpetra::Details::OrdinalTraits<LO>::invalid())
            ++bad;
        }
      },
      missing);
  if (missing)
    throw std::logic_error("a particle's node is missing from the map of its unknowns");
  return lids;
}

template <int Dim, class Space = DefaultExecSpace>
Kokkos::View<LO*, typename Space::memory_space> entryDofs(const ParticleGridMap<Dim, Space>& map,
                                                          const Map& overlap) {
  const auto all = entryColumns(map, overlap);
  Kokkos::View<LO*, typename Space::memory_space> lids("entry dofs", map.numEntries());
  int misplaced = 0;
  Kokkos::parallel_reduce(
      "impm::entryDofs", RangePolicy<Space>(0, map.numEntries()),
      KOKKOS_LAMBDA(const std::size_t k, int& bad) {
        lids(k) = all(k, 0);
        for (int d = 1; d < Dim; ++d)
          if (all(k, d) != lids(k) + d)
            ++bad;
      },
      misplaced);
  if (misplaced)
    throw std::logic_error("node components are not consecutive in the DOF map");
  return lids;
}

}  // namespace impm
