#include "assembly/Graph.hpp"

#include <algorithm>

#include "core/Errors.hpp"

namespace impm {

template <int Dim>
Teuchos::RCP<FECrsGraph> buildGraph(const ParticleGridMap<Dim>& map,
                                    const Kokkos::View<LO*>& entryDofs, const DofMap<Dim>& dofs,
                                    const std::vector<std::pair<GO, GO>>& extraCouplings) {
  const auto& overlap = *dofs.overlapMap();
  const std::size_t numRows = overlap.getNodeNumElements();
  auto rowPtr = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), map.rowPtr);
  auto lid = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), entryDofs);
  const std::size_t numParticles = map.numParticles();

  // Transpose of Y: the particles touching each node (indexed by the node's first DOF).
  std::vector<std::size_t> start(numRows + 1, 0);
  for (std::size_t k = 0; k < lid.extent(0); ++k)
    ++start[lid(k) + 1];
  for (std::size_t r = 0; r < numRows; ++r)
    start[r + 1] += start[r];
  std::vector<std::size_t> fill(start.begin(), start.end() - 1);
  std::vector<std::size_t> particlesOf(start.back());
  for (std::size_t p = 0; p < numParticles; ++p)
    for (std::size_t k = rowPtr(p); k < rowPtr(p + 1); ++k)
      particlesOf[fill[lid(k)]++] = p;

  // Extra couplings, in local indices, grouped by row.
  std::vector<std::vector<LO>> extra(numRows);
  for (const auto& [row, col] : extraCouplings) {
    const LO r = overlap.getLocalElement(row), c = overlap.getLocalElement(col);
    if (r == Teuchos::OrdinalTraits<LO>::invalid() || c == Teuchos::OrdinalTraits<LO>::invalid())
      throw std::logic_error("boundary coupling outside the overlap map");
    extra[r].push_back(c);
  }

  // Columns of every row: the DOFs of every node sharing a particle, plus extras.
  std::vector<std::vector<LO>> columns(numRows);
  std::vector<LO> nodes;
  for (std::size_t r = 0; r < numRows; ++r) {
    if (start[r + 1] > start[r]) {  // r is the first DOF of a node that particles touch
      nodes.clear();
      for (std::size_t q = start[r]; q < start[r + 1]; ++q) {
        const std::size_t p = particlesOf[q];
        for (std::size_t k = rowPtr(p); k < rowPtr(p + 1); ++k)
          nodes.push_back(lid(k));
      }
      std::sort(nodes.begin(), nodes.end());
      nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
      for (int a = 0; a < Dim; ++a) {
        auto& cols = columns[r + a];
        cols.reserve(nodes.size() * Dim);
        for (LO node : nodes)
          for (int b = 0; b < Dim; ++b)
            cols.push_back(node + b);
      }
    }
  }
  for (std::size_t r = 0; r < numRows; ++r) {
    auto& cols = columns[r];
    cols.insert(cols.end(), extra[r].begin(), extra[r].end());
    std::sort(cols.begin(), cols.end());
    cols.erase(std::unique(cols.begin(), cols.end()), cols.end());
  }

  Kokkos::DualView<std::size_t*, FECrsGraph::device_type> counts("row counts", numRows);
  for (std::size_t r = 0; r < numRows; ++r)
    counts.h_view(r) = columns[r].size();
  counts.modify_host();
  counts.sync_device();
  // Global indices: Tpetra builds the column map after exporting shared rows, so that the
  // columns other ranks send along with them are part of it.
  auto graph = Teuchos::rcp(new FECrsGraph(dofs.ownedMap(), dofs.overlapMap(), counts));
  graph->beginAssembly();
  std::vector<GO> gids;
  for (std::size_t r = 0; r < numRows; ++r) {
    if (columns[r].empty())
      continue;
    gids.clear();
    for (LO c : columns[r])
      gids.push_back(overlap.getGlobalElement(c));
    graph->insertGlobalIndices(overlap.getGlobalElement(static_cast<LO>(r)),
                               Teuchos::ArrayView<const GO>(gids));
  }
  graph->endAssembly();
  return graph;
}

template Teuchos::RCP<FECrsGraph> buildGraph<1>(const ParticleGridMap<1>&, const Kokkos::View<LO*>&,
                                                const DofMap<1>&,
                                                const std::vector<std::pair<GO, GO>>&);
template Teuchos::RCP<FECrsGraph> buildGraph<2>(const ParticleGridMap<2>&, const Kokkos::View<LO*>&,
                                                const DofMap<2>&,
                                                const std::vector<std::pair<GO, GO>>&);

}  // namespace impm
