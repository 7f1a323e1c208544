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

namespace detail {

// For node ids lowest + j, j < table.extent(0): the overlap index of the node's first
// component, or invalid where the node has none.  One pass over the overlap map.
template <int Dim, class Memory>
Kokkos::View<LO*, Memory> nodeTable(const Map& overlap, GlobalId lowest, std::size_t range) {
  Kokkos::View<LO*, Memory> table(Kokkos::ViewAllocateWithoutInitializing("node table"), range);
  auto host = Kokkos::create_mirror_view(table);
  Kokkos::deep_copy(host, Tpetra::Details::OrdinalTraits<LO>::invalid());
  const auto gids = overlap.getNodeElementList();
  for (LO i = 0; i < static_cast<LO>(gids.size()); ++i) {
    const GO node = gids[i] / Dim - lowest;
    if (gids[i] % Dim == 0 && node >= 0 && node < static_cast<GO>(range))
      host(node) = i;
  }
  Kokkos::deep_copy(table, host);
  return table;
}

}  // namespace detail

// The overlap index of each entry's node is looked up in a table over the range of the
// entries' node ids when that range is not much wider than the list of entries (a rank's
// particles: one pass, where the map's hashed lookup per entry was a tenth of an explicit
// gimp step), and in the map otherwise.  A node missing from `overlap` is a logic_error,
// unless `allFound` is given: it then tells whether every node was found.
template <int Dim, class Space = DefaultExecSpace>
Kokkos::View<LO*, typename Space::memory_space> entryDofs(const ParticleGridMap<Dim, Space>& map,
                                                          const Map& overlap,
                                                          bool* allFound = nullptr) {
  using Memory = typename Space::memory_space;
  const std::size_t n = map.numEntries();
  Kokkos::View<LO*, Memory> lids(Kokkos::ViewAllocateWithoutInitializing("entry dofs"), n);
  auto local = overlap.getLocalMap();
  auto node = map.node;
  GlobalId lowest = 0, highest = -1;
  Kokkos::parallel_reduce(
      "impm::entryNodeRange", RangePolicy<Space>(0, n),
      KOKKOS_LAMBDA(const std::size_t k, GlobalId& lo, GlobalId& hi) {
        lo = node(k) < lo ? node(k) : lo;
        hi = node(k) > hi ? node(k) : hi;
      },
      Kokkos::Min<GlobalId>(lowest), Kokkos::Max<GlobalId>(highest));
  const std::size_t range = highest >= lowest ? static_cast<std::size_t>(highest - lowest + 1) : 0;
  const bool tabled = range <= 4 * n;
  const auto table = detail::nodeTable<Dim, Memory>(overlap, lowest, tabled ? range : 0);
  const LO rows = static_cast<LO>(overlap.getNodeNumElements());
  int bad = 0;  // 1: a node is not in the map; 2: its components are not consecutive
  Kokkos::parallel_reduce(
      "impm::entryDofs", RangePolicy<Space>(0, n),
      KOKKOS_LAMBDA(const std::size_t k, int& worst) {
        const GO first = node(k) * Dim;
        lids(k) = tabled ? table(node(k) - lowest) : local.getLocalElement(first);
        if (lids(k) == Tpetra::Details::OrdinalTraits<LO>::invalid()) {
          worst = worst > 1 ? worst : 1;
          return;
        }
        for (int d = 1; d < Dim; ++d)
          if (lids(k) + d >= rows || local.getGlobalElement(lids(k) + d) != first + d)
            worst = 2;
      },
      Kokkos::Max<int>(bad));
  if (allFound)
    *allFound = bad != 1;
  if (bad == 1 && !allFound)
    throw std::logic_error("a particle's node is missing from the map of its unknowns");
  if (bad == 2)
    throw std::logic_error("node components are not consecutive in the DOF map");
  return lids;
}

}  // namespace impm
