#pragma once
// Local indices of the unknowns of the particle-grid map's entries.
//  - entryDofs: for every entry k, the index in the overlap map (the rows) of the first
//    displacement component of node(k); component d is that index + d, because DofMap lists
//    a node's components together (checked here).
//    The Jacobian's column map begins with the overlap map (assembly/Graph.hpp), so the
//    same index is also the component's column: entry k, component d sits in row and
//    column entryDofs(k) + d of the overlap matrix.

#include "basis/ParticleGridMap.hpp"
#include "core/TpetraTypes.hpp"

namespace impm {

template <int Dim, class Space = DefaultExecSpace>
Kokkos::View<LO*, typename Space::memory_space> entryDofs(const ParticleGridMap<Dim, Space>& map,
                                                          const Map& overlap) {
  Kokkos::View<LO*, typename Space::memory_space> lids("entry dofs", map.numEntries());
  auto local = overlap.getLocalMap();
  auto node = map.node;
  const LO rows = static_cast<LO>(overlap.getNodeNumElements());
  int bad = 0;  // 1: a node is not in the map; 2: its components are not consecutive
  Kokkos::parallel_reduce(
      "impm::entryDofs", RangePolicy<Space>(0, map.numEntries()),
      KOKKOS_LAMBDA(const std::size_t k, int& worst) {
        const GO first = node(k) * Dim;
        lids(k) = local.getLocalElement(first);
        if (lids(k) == Tpetra::Details::OrdinalTraits<LO>::invalid()) {
          worst = worst > 1 ? worst : 1;
          return;
        }
        for (int d = 1; d < Dim; ++d)
          if (lids(k) + d >= rows || local.getGlobalElement(lids(k) + d) != first + d)
            worst = 2;
      },
      Kokkos::Max<int>(bad));
  if (bad == 1)
    throw std::logic_error("a particle's node is missing from the map of its unknowns");
  if (bad == 2)
    throw std::logic_error("node components are not consecutive in the DOF map");
  return lids;
}

}  // namespace impm
