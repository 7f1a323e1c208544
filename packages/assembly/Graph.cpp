#include "assembly/Graph.hpp"

#include <algorithm>
#include <numeric>

#include <Tpetra_Distributor.hpp>

#include "core/Errors.hpp"

namespace impm {
namespace {

// The local columns of every row of the overlap map, from the particle-grid map and the
// extra couplings.  Node couplings are kept once per node, in one flat array, and expanded
// into a row's DOF columns when asked for.
template <int Dim>
class RowColumns {
 public:
  // `patches`: groups of nodes (overlap indices of their first DOFs) coupled as a particle's.
  RowColumns(const ParticleGridMap<Dim>& map, const Kokkos::View<LO*>& entryDofs,
             const Map& overlap, const std::vector<std::pair<GO, GO>>& extraCouplings,
             NodeCoupling coupling, const NodeGroups& patches)
      : numRows_(overlap.getNodeNumElements()),
        nodeStart_(numRows_ + 1, 0),
        nodeOfRow_(numRows_, -1),
        extra_(numRows_) {
    if (coupling == NodeCoupling::self)
      coupleNodesWithThemselves(entryDofs);
    else
      coupleNodes(map, entryDofs, patches);
    for (std::size_t r = 0; r < numRows_; ++r)
      if (nodeStart_[r + 1] > nodeStart_[r])
        for (int a = 0; a < Dim; ++a)
          nodeOfRow_[r + a] = static_cast<LO>(r);  // a node's rows follow its first DOF
    for (const auto& [row, col] : extraCouplings) {
      const LO r = overlap.getLocalElement(row), c = overlap.getLocalElement(col);
      if (r == Teuchos::OrdinalTraits<LO>::invalid() || c == Teuchos::OrdinalTraits<LO>::invalid())
        throw std::logic_error("boundary coupling outside the overlap map");
      extra_[r].push_back(c);
    }
  }

  std::size_t numRows() const { return numRows_; }

  // The node pairs, taken out when the rows are no longer needed.
  NodeAdjacency releaseAdjacency() {
    nodeColumns_.shrink_to_fit();  // reserved for twice the map's entries
    return NodeAdjacency{std::move(nodeStart_), std::move(nodeColumns_)};
  }

  // Row r's columns, sorted and unique (valid until the next call).
  const std::vector<LO>& operator()(std::size_t r) {
    cols_.clear();
    if (const LO node = nodeOfRow_[r]; node >= 0)
      for (std::size_t q = nodeStart_[node]; q < nodeStart_[node + 1]; ++q)
        for (int b = 0; b < Dim; ++b)
          cols_.push_back(nodeColumns_[q] + b);  // sorted: nodes' DOF ranges do not overlap
    if (!extra_[r].empty()) {
      cols_.insert(cols_.end(), extra_[r].begin(), extra_[r].end());
      std::sort(cols_.begin(), cols_.end());
      cols_.erase(std::unique(cols_.begin(), cols_.end()), cols_.end());
    }
    return cols_;
  }

 private:
  // For the node whose first DOF is r: the first DOFs of every node sharing a particle with
  // it, sorted, at nodeColumns_[nodeStart_[r] ...].  Through the transpose of Y (the
  // particles touching each node); a node already listed for r is marked with r, so only
  // the unique ones are sorted.
  // The patches count as particles numbered after the map's.
  void coupleNodes(const ParticleGridMap<Dim>& map, const Kokkos::View<LO*>& entryDofs,
                   const NodeGroups& patches) {
    auto rowPtr = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), map.rowPtr);
    auto lid = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), entryDofs);
    const std::size_t particles = map.numParticles();
    const auto forNodesOf = [&](std::size_t p, auto&& f) {
      if (p < particles)
        for (std::size_t k = rowPtr(p); k < rowPtr(p + 1); ++k)
          f(lid(k));
      else
        for (std::size_t k = patches.start[p - particles]; k < patches.start[p - particles + 1];
             ++k)
          f(patches.nodes[k]);
    };
    const std::size_t groups = particles + patches.start.size() - 1;
    std::vector<std::size_t> start(numRows_ + 1, 0);
    for (std::size_t p = 0; p < groups; ++p)
      forNodesOf(p, [&](LO node) { ++start[node + 1]; });
    for (std::size_t r = 0; r < numRows_; ++r)
      start[r + 1] += start[r];
    std::vector<std::size_t> fill(start.begin(), start.end() - 1);
    std::vector<std::size_t> particlesOf(start.back());
    for (std::size_t p = 0; p < groups; ++p)
      forNodesOf(p, [&](LO node) { particlesOf[fill[node]++] = p; });

    nodeColumns_.reserve(start.back() * 2);
    std::vector<std::size_t> listedFor(numRows_, numRows_);
    for (std::size_t r = 0; r < numRows_; ++r) {
      const std::size_t first = nodeColumns_.size();
      for (std::size_t q = start[r]; q < start[r + 1]; ++q)
        forNodesOf(particlesOf[q], [&](LO node) {
          if (listedFor[node] != r) {
            listedFor[node] = r;
            nodeColumns_.push_back(node);
          }
        });
      std::sort(nodeColumns_.begin() + first, nodeColumns_.end());
      nodeStart_[r + 1] = nodeColumns_.size();
    }
  }

  // Every node an integration point touches lists itself alone.
  void coupleNodesWithThemselves(const Kokkos::View<LO*>& entryDofs) {
    auto lid = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), entryDofs);
    std::vector<char> touched(numRows_, 0);
    for (std::size_t k = 0; k < lid.extent(0); ++k)
      touched[lid(k)] = 1;
    for (std::size_t r = 0; r < numRows_; ++r) {
      if (touched[r])
        nodeColumns_.push_back(static_cast<LO>(r));
      nodeStart_[r + 1] = nodeColumns_.size();
    }
  }

  std::size_t numRows_;
  std::vector<std::size_t> nodeStart_;
  std::vector<LO> nodeColumns_;
  std::vector<LO> nodeOfRow_;
  std::vector<std::vector<LO>> extra_;
  std::vector<LO> cols_;
};

// The column map: the overlap map's columns (in its order, so that a local index of the
// overlap map is the same column's local index here) and after them the columns that other
// ranks' shared rows bring to this rank's owned rows.  Those are learnt by sending every
// shared row's columns to the row's owner over `ownedToOverlap` in reverse, first their
// counts, then the global indices.  Collective.
template <int Dim>
Teuchos::RCP<const Map> columnMap(RowColumns<Dim>& columns, const Map& overlap,
                                  const Import& ownedToOverlap) {
  const auto shared = ownedToOverlap.getRemoteLIDs();  // the rows this rank sends
  std::vector<std::size_t> sendCounts;
  std::vector<GO> send;
  for (const LO r : shared) {
    const auto& local = columns(static_cast<std::size_t>(r));
    sendCounts.push_back(local.size());
    for (const LO c : local)
      send.push_back(overlap.getGlobalElement(c));
  }
  auto& distributor = ownedToOverlap.getDistributor();
  std::vector<std::size_t> receiveCounts(ownedToOverlap.getNumExportIDs());
  distributor.doReversePostsAndWaits<std::size_t>(sendCounts, 1, receiveCounts);
  std::vector<GO> received(
      std::accumulate(receiveCounts.begin(), receiveCounts.end(), std::size_t(0)));
  distributor.doReversePostsAndWaits<GO>(send, sendCounts, received, receiveCounts);

  std::vector<GO> gids(overlap.getNodeElementList().begin(), overlap.getNodeElementList().end());
  const std::size_t known = gids.size();
  for (const GO g : received)
    if (overlap.getLocalElement(g) == Teuchos::OrdinalTraits<LO>::invalid())
      gids.push_back(g);
  std::sort(gids.begin() + known, gids.end());
  gids.erase(std::unique(gids.begin() + known, gids.end()), gids.end());
  return Teuchos::rcp(new Map(Teuchos::OrdinalTraits<Tpetra::global_size_t>::invalid(),
                              Teuchos::ArrayView<const GO>(gids), 0, overlap.getComm()));
}

}  // namespace

template <int Dim>
Teuchos::RCP<FECrsGraph> buildGraph(const ParticleGridMap<Dim>& map,
                                    const Kokkos::View<LO*>& entryDofs, const DofMap<Dim>& dofs,
                                    const std::vector<std::pair<GO, GO>>& extraCouplings,
                                    NodeCoupling coupling, NodeAdjacency* adjacency,
                                    const NodeGroups& groups) {
  const auto& overlap = *dofs.overlapMap();
  NodeGroups patches{dofs.haloPatchStart(), {}};
  for (const GlobalId node : dofs.haloPatchNodes())
    patches.nodes.push_back(overlap.getLocalElement(dofs.nodeDof(node, 0)));
  for (std::size_t k = 1; k < groups.start.size(); ++k)
    patches.start.push_back(patches.start.back() + groups.start[k] - groups.start[k - 1]);
  patches.nodes.insert(patches.nodes.end(), groups.nodes.begin(), groups.nodes.end());
  RowColumns<Dim> columns(map, entryDofs, overlap, extraCouplings, coupling, patches);
  Kokkos::DualView<std::size_t*, FECrsGraph::device_type> counts("row counts", columns.numRows());
  // Each row is expanded twice (here for its length, below for its columns) rather than
  // kept: all rows at once would hold the whole graph again (some 400 MB at 10^6 particles).
  for (std::size_t r = 0; r < columns.numRows(); ++r)
    counts.h_view(r) = columns(r).size();
  counts.modify_host();
  counts.sync_device();
  // With the column map known beforehand the rows go in as local indices: Tpetra then has
  // no global indices to convert and sort and no column map to make (a third of the graph's
  // time at 10^6 particles).  On one rank no row is shared and the overlap map is the
  // column map.
  Teuchos::RCP<const Map> columnsMap = dofs.overlapMap();
  Teuchos::RCP<const Import> ownedToOverlap;  // FECrsGraph's own, made once here
  if (overlap.getComm()->getSize() > 1) {
    ownedToOverlap = Teuchos::rcp(new Import(dofs.ownedMap(), dofs.overlapMap()));
    columnsMap = columnMap(columns, overlap, *ownedToOverlap);
  }
  auto graph = Teuchos::rcp(
      new FECrsGraph(dofs.ownedMap(), dofs.overlapMap(), columnsMap, counts, ownedToOverlap));
  graph->beginAssembly();
  for (std::size_t r = 0; r < columns.numRows(); ++r) {
    const auto& local = columns(r);
    if (!local.empty())
      graph->insertLocalIndices(static_cast<LO>(r), Teuchos::ArrayView<const LO>(local));
  }
  graph->endAssembly();
  if (adjacency && coupling == NodeCoupling::shared)
    *adjacency = columns.releaseAdjacency();
  return graph;
}

bool NodeAdjacency::couples(LO a, LO b) const {
  const auto first = columns.begin() + static_cast<std::ptrdiff_t>(start[a]);
  const auto last = columns.begin() + static_cast<std::ptrdiff_t>(start[a + 1]);
  return std::binary_search(first, last, b);
}

template Teuchos::RCP<FECrsGraph> buildGraph<1>(const ParticleGridMap<1>&, const Kokkos::View<LO*>&,
                                                const DofMap<1>&,
                                                const std::vector<std::pair<GO, GO>>&, NodeCoupling,
                                                NodeAdjacency*, const NodeGroups&);
template Teuchos::RCP<FECrsGraph> buildGraph<2>(const ParticleGridMap<2>&, const Kokkos::View<LO*>&,
                                                const DofMap<2>&,
                                                const std::vector<std::pair<GO, GO>>&, NodeCoupling,
                                                NodeAdjacency*, const NodeGroups&);
template Teuchos::RCP<FECrsGraph> buildGraph<3>(const ParticleGridMap<3>&, const Kokkos::View<LO*>&,
                                                const DofMap<3>&,
                                                const std::vector<std::pair<GO, GO>>&, NodeCoupling,
                                                NodeAdjacency*, const NodeGroups&);

}  // namespace impm
