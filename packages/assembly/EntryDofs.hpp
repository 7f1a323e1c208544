#pragma once
// For every entry k of the particle-grid map, the local index, in `map` (the overlap map for
// rows, the graph's column map for columns), of the first displacement component of
// node(k).  Component d is that index + d: DofMap lists a node's components together and
// Tpetra's column maps keep them together (owned in domain-map order, remote sorted by
// owner then index); checked here.

#include "basis/ParticleGridMap.hpp"
#include "core/TpetraTypes.hpp"

namespace impm {

template <int Dim, class Space = DefaultExecSpace>
Kokkos::View<LO*, typename Space::memory_space> entryDofs(const ParticleGridMap<Dim, Space>& map,
                                                          const Map& overlap) {
  Kokkos::View<LO*, typename Space::memory_space> lids("entry dofs", map.numEntries());
  auto local = overlap.getLocalMap();
  auto node = map.node;
  int misplaced = 0;
  Kokkos::parallel_reduce(
      "impm::entryDofs", RangePolicy<Space>(0, map.numEntries()),
      KOKKOS_LAMBDA(const std::size_t k, int& bad) {
        lids(k) = local.getLocalElement(node(k) * Dim);
        for (int d = 1; d < Dim; ++d)
          if (local.getLocalElement(node(k) * Dim + d) != lids(k) + d)
            ++bad;
        if (lids(k) == Tpetra::Details::OrdinalTraits<LO>::invalid())
          ++bad;
      },
      misplaced);
  if (misplaced)
    throw std::logic_error("node components are not consecutive in the DOF map");
  return lids;
}

}  // namespace impm
