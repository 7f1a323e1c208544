#pragma once
// Local indices of the unknowns of the particle-grid map's entries.
//  - entryDofs: for every entry k, the index in the overlap map (the rows) of the first
//    displacement component of node(k); component d is that index + d, because DofMap lists
//    a node's components together (checked here).
//  - entryColumns: the index of every component in the Jacobian's column map.  Tpetra
//    builds that map and does not promise to keep a node's components together (on 4
//    ranks they were not), so each component is looked up: once per overlap row, not once
//    per entry (a node has some 36 entries; the maps' global-to-local lookups are hashes).

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

// Rows are entryDofs' overlap-map indices; columns is the Jacobian's column map.
template <int Dim, class Space = DefaultExecSpace>
Kokkos::View<LO**, typename Space::memory_space> entryColumns(
    const Kokkos::View<LO*, typename Space::memory_space>& entryDofs, const Map& overlap,
    const Map& columns) {
  const LO rows = static_cast<LO>(overlap.getNodeNumElements());
  Kokkos::View<LO*, typename Space::memory_space> columnOfRow("column of row", rows);
  auto rowMap = overlap.getLocalMap();
  auto columnMap = columns.getLocalMap();
  Kokkos::parallel_for(
      "impm::columnOfRow", RangePolicy<Space>(0, rows), KOKKOS_LAMBDA(const LO r) {
        columnOfRow(r) = columnMap.getLocalElement(rowMap.getGlobalElement(r));
      });
  Kokkos::View<LO**, typename Space::memory_space> lids("entry columns", entryDofs.extent(0), Dim);
  int missing = 0;
  Kokkos::parallel_reduce(
      "impm::entryColumns", RangePolicy<Space>(0, entryDofs.extent(0)),
      KOKKOS_LAMBDA(const std::size_t k, int& bad) {
        for (int d = 0; d < Dim; ++d) {
          lids(k, d) = columnOfRow(entryDofs(k) + d);
          if (lids(k, d) == Tpetra::Details::OrdinalTraits<LO>::invalid())
            ++bad;
        }
      },
      missing);
  if (missing)
    throw std::logic_error("a particle's node is missing from the Jacobian's column map");
  return lids;
}

}  // namespace impm
