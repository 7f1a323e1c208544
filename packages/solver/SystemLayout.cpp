#include "solver/SystemLayout.hpp"

#include <algorithm>

#include <Teuchos_CommHelpers.hpp>

#include "assembly/EntryDofs.hpp"
#include "assembly/Graph.hpp"
#include "core/Collective.hpp"
#include "core/Diagnostics.hpp"
#include "core/Errors.hpp"
#include "core/Timers.hpp"

namespace impm {

namespace {

// The largest share of a kept layout's unknowns that may be retired (see covering()).
constexpr double kMaxRetiredShare = 0.05;

// The nodes the map and the contributions touch and the extra unknowns.  Calls every
// contribution's prepare(), which the step needs whether or not the layout is reused.
template <int Dim>
LayoutKey<Dim> keyOf(const NodeOwnership<Dim>& ownership, const ParticleGridMap<Dim>& map,
                     const Contributions<Dim>& contributions, NodeCoupling coupling,
                     std::vector<int>& firstExtra, std::vector<ExtraDof>& extras) {
  LayoutKey<Dim> key;
  key.ownership = &ownership;
  key.ownershipRevision = ownership.revision();
  key.coupling = coupling;
  std::vector<GlobalId> others;  // the nodes the contributions reach
  for (const auto& c : contributions) {
    firstExtra.push_back(static_cast<int>(extras.size()));
    c->prepare(ownership, extras, others);
  }
  for (const auto& e : extras)
    key.extraNodes.push_back(e.anchorNode);
  // The map's nodes, then the contributions', in one allocation.
  auto node = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), map.node);
  key.touched.reserve(node.extent(0) + others.size());
  key.touched.assign(node.data(), node.data() + node.extent(0));
  if (coupling == NodeCoupling::shared) {
    key.touched.insert(key.touched.end(), others.begin(), others.end());
    auto rowPtr = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), map.rowPtr);
    key.rowPtr.assign(rowPtr.data(), rowPtr.data() + rowPtr.extent(0));
    return key;
  }
  // Without node pairs in the graph the layout depends on which nodes the integration points
  // touch, not on which point touches which: the key lists the distinct nodes, those of the
  // map and those of the contributions apart (so that a kept layout's check that every
  // node is integrated still holds).
  sortUnique(key.touched);
  sortUnique(others);
  key.touched.insert(key.touched.end(), others.begin(), others.end());
  return key;
}

// F-bar: the nodes of each cell's particles, sorted, into the key's groups (shared coupling:
// `touched` lists every entry's node).
template <int Dim>
void addCellNodes(const CellGroups<>& cells, LayoutKey<Dim>& key) {
  auto start = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), cells.start);
  auto order = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), cells.order);
  for (std::size_t c = 0; c < cells.size(); ++c) {
    const std::size_t first = key.groupNodes.size();
    for (std::size_t m = start(c); m < start(c + 1); ++m) {
      const int p = order(m);
      key.groupNodes.insert(key.groupNodes.end(), key.touched.begin() + key.rowPtr[p],
                            key.touched.begin() + key.rowPtr[p + 1]);
    }
    std::sort(key.groupNodes.begin() + first, key.groupNodes.end());
    key.groupNodes.erase(std::unique(key.groupNodes.begin() + first, key.groupNodes.end()),
                         key.groupNodes.end());
    key.groupStart.push_back(key.groupNodes.size());
  }
}

// The ghost penalty's faces: their nodes into the key's touched nodes (after every entry's
// and the contributions') and, sorted, into its groups.
template <int Dim>
void addFaceNodes(const GhostFaces& faces, LayoutKey<Dim>& key) {
  key.touched.insert(key.touched.end(), faces.nodes.begin(), faces.nodes.end());
  for (std::size_t f = 0; f < faces.size(); ++f) {
    const auto first = faces.nodes.begin() + f * kFaceNodes<Dim>;
    const std::size_t at = key.groupNodes.size();
    key.groupNodes.insert(key.groupNodes.end(), first, first + kFaceNodes<Dim>);
    std::sort(key.groupNodes.begin() + at, key.groupNodes.end());
    key.groupStart.push_back(key.groupNodes.size());
  }
}

// The key's groups as overlap indices of their first DOFs (invalid: not unknowns).
template <int Dim>
NodeGroups nodeGroups(const LayoutKey<Dim>& key, const DofMap<Dim>& dofs) {
  NodeGroups groups;
  if (key.groupStart.empty())
    return groups;
  groups.start = key.groupStart;
  const auto& overlap = *dofs.overlapMap();
  for (const GlobalId node : key.groupNodes)
    groups.nodes.push_back(overlap.getLocalElement(dofs.nodeDof(node, 0)));
  return groups;
}

// On the owned rows: non-zero where an entry's node is, zero elsewhere (the marks brought
// from the overlap rows to their owners).  Collective.
template <int Dim>
Vector integratedRows(const DofMap<Dim>& dofs, const Import& importer, const EntryDofs<>& entries) {
  Vector marks(dofs.overlapMap());
  {
    auto local = marks.getLocalViewHost(Tpetra::Access::ReadWrite);
    auto lids = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), entries);
    for (std::size_t k = 0; k < lids.extent(0); ++k)
      for (int d = 0; d < Dim; ++d)
        local(lids(k) + d, 0) = 1.0;
  }
  Vector owned(dofs.ownedMap());
  owned.doExport(marks, importer, Tpetra::ADD);
  return owned;
}

// The owned rows that no entry marks: nodes only a boundary condition reaches would have
// empty rows (an error); nodes of `kept` that nothing touches any more are retired (their
// rows, every component, are returned).  Collective.
template <int Dim>
std::vector<LO> rowsNotIntegrated(const GridGeometry<Dim>& grid, const SystemLayout<Dim>& l,
                                  const EntryDofs<>& entries, const std::vector<GlobalId>& kept,
                                  const std::vector<GlobalId>& contributionNodes) {
  const auto& dofs = l.dofs;
  const Vector owned = integratedRows(dofs, *l.importer, entries);
  std::vector<LO> retired;
  collectively(*dofs.ownedMap()->getComm(), [&] {
    auto values = owned.getData();
    const auto& map = *dofs.ownedMap();
    for (decltype(values.size()) k = 0; k < values.size(); ++k) {
      const GO dof = map.getGlobalElement(static_cast<LO>(k));
      if (values[k] > 0.0 || dofs.isExtraDof(dof))
        continue;
      const GlobalId node = DofMap<Dim>::nodeOf(dof);
      if (std::binary_search(kept.begin(), kept.end(), node) &&
          !std::binary_search(contributionNodes.begin(), contributionNodes.end(), node)) {
        retired.push_back(static_cast<LO>(k));
        continue;
      }
      throw NumericalError(
          nodeLabel(grid, node) +
          " is reached by a boundary condition but by no integration point, so its row of the "
          "system is empty (classic MPM does this when a body's end lies in a cell that holds "
          "no particle centre); use gimp or cpdi, or more particles per cell");
    }
  });
  return retired;
}

template <int Dim>
struct Numbered {
  std::shared_ptr<SystemLayout<Dim>> layout;
  EntryDofs<> entries;
  std::vector<LO> retired;  // owned rows of kept nodes that nothing touches (ascending)
};

// The unknowns, the entries' overlap indices, the importer and the mask.  `kept`: nodes
// that stay unknowns though nothing touches them (retired), ascending.  Collective.
template <int Dim>
Numbered<Dim> numberUnknowns(const NodeOwnership<Dim>& ownership, const ParticleGridMap<Dim>& map,
                             std::vector<int> firstExtra, std::vector<GlobalId> touched,
                             const std::vector<ExtraDof>& extras, NodeCoupling coupling,
                             const std::vector<GlobalId>& kept, OverlapHalo halo) {
  // The contributions' nodes follow the map's entries' in `touched` (keyOf; kept nodes come
  // only with shared coupling, whose key lists every entry's node).
  std::vector<GlobalId> contributionNodes;
  if (!kept.empty()) {
    contributionNodes.assign(touched.begin() + map.node.extent(0), touched.end());
    sortUnique(contributionNodes);
  }
  touched.insert(touched.end(), kept.begin(), kept.end());
  auto l = std::make_shared<SystemLayout<Dim>>(
      std::move(firstExtra), DofMap<Dim>(ownership, std::move(touched), extras, halo), coupling);
  const auto& dofs = l->dofs;
  // A failure on one rank must stop every rank (the next steps are collective).
  EntryDofs<> entries;
  collectively(*ownership.comm(), [&] { entries = impm::entryDofs(map, *dofs.overlapMap()); });
  l->importer = Teuchos::rcp(new Import(dofs.ownedMap(), dofs.overlapMap()));
  auto mask = Teuchos::rcp(new Vector(dofs.ownedMap()));
  {
    auto m = mask->getLocalViewHost(Tpetra::Access::OverwriteAll);
    const auto& owned = *dofs.ownedMap();
    for (std::size_t k = 0; k < owned.getNodeNumElements(); ++k) {
      const bool extra = dofs.isExtraDof(owned.getGlobalElement(static_cast<LO>(k)));
      m(k, 0) = extra ? 0.0 : 1.0;
      if (extra)
        l->extraRows.push_back(static_cast<LO>(k));
    }
  }
  l->nodalMask = mask;
  auto retired = rowsNotIntegrated(ownership.grid(), *l, entries, kept, contributionNodes);
  return {l, entries, std::move(retired)};
}

// Whether the retired rows exceed the share a layout may keep (covering()), and whether
// there are any, on every rank.  Collective.
std::pair<bool, bool> retiredBeyondShareAndAny(const std::vector<LO>& retired, const Map& owned) {
  const long long mine = static_cast<long long>(retired.size());
  long long all = 0;
  Teuchos::reduceAll(*owned.getComm(), Teuchos::REDUCE_SUM, mine, Teuchos::outArg(all));
  return {static_cast<double>(all) > kMaxRetiredShare * owned.getGlobalNumElements(), all > 0};
}

}  // namespace

template <int Dim>
std::optional<LaidOut<Dim>> LayoutCache<Dim>::reusable(const LayoutKey<Dim>& key,
                                                       const ParticleGridMap<Dim>& map,
                                                       const Comm& comm) {
  if (!enabled_)
    return std::nullopt;
  if (!onEveryRank(layout_ && key == key_, comm)) {
    entries_ = EntryDofs<>();  // the kept key's: not held while the next ones are made
    return covering(key, map, comm);
  }
  LaidOut<Dim> kept{layout_, entries_, retired_, anyRetired_};
  if (key.coupling == NodeCoupling::self)  // the same nodes, other entries
    collectively(comm, [&] { kept.entryDofs = impm::entryDofs(map, *layout_->dofs.overlapMap()); });
  return kept;
}

template <int Dim>
std::optional<LaidOut<Dim>> LayoutCache<Dim>::covering(const LayoutKey<Dim>& key,
                                                       const ParticleGridMap<Dim>& map,
                                                       const Comm& comm) const {
  if (!onEveryRank(comparableWith(key), comm))
    return std::nullopt;
  const Map& overlap = *layout_->dofs.overlapMap();
  bool found = false;
  EntryDofs<> entries;
  collectively(comm, [&] { entries = impm::entryDofs(map, overlap, &found); });
  if (!onEveryRank(found && pairsCovered(key, entries), comm))
    return std::nullopt;
  // The owned nodal rows that no entry marks are the retired ones.
  const Vector owned = integratedRows(layout_->dofs, *layout_->importer, entries);
  LaidOut<Dim> out{layout_, entries, {}, false};
  {
    auto values = owned.getLocalViewHost(Tpetra::Access::ReadOnly);
    const auto& rows = *layout_->dofs.ownedMap();
    for (LO r = 0; r < static_cast<LO>(values.extent(0)); ++r)
      if (values(r, 0) == 0.0 && !layout_->dofs.isExtraDof(rows.getGlobalElement(r)))
        out.retired.push_back(r);
  }
  // Retired rows still cost their share of every vector operation and factorisation: a
  // column compressed to a third of its height would end with two thirds of its rows
  // retired (the Hencky column took 8-14 % longer than with layouts built every step).
  // Past a small share, a new layout costs less than keeping them.
  const auto [beyond, any] = retiredBeyondShareAndAny(out.retired, *layout_->dofs.ownedMap());
  if (beyond)
    return std::nullopt;
  out.anyRetired = any;
  return out;
}

template <int Dim>
bool LayoutCache<Dim>::comparableWith(const LayoutKey<Dim>& key) const {
  return allowRetired_ && layout_ && key.coupling == NodeCoupling::shared &&
         key_.coupling == NodeCoupling::shared && key.ownership == key_.ownership &&
         key.ownershipRevision == key_.ownershipRevision && key.extraNodes == key_.extraNodes;
}

template <int Dim>
const std::vector<GlobalId>& LayoutCache<Dim>::nodesToKeep(const LayoutKey<Dim>& key,
                                                           const Comm& comm) const {
  static const std::vector<GlobalId> none;
  return onEveryRank(keepUnknowns_ && comparableWith(key), comm) ? layout_->dofs.ownedActiveNodes()
                                                                 : none;
}

template <int Dim>
bool LayoutCache<Dim>::pairsCovered(const LayoutKey<Dim>& key, const EntryDofs<>& entries) const {
  auto lid = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), entries);
  const std::size_t mapped = key.rowPtr.empty() ? 0 : key.rowPtr.back();
  // The contributions' nodes (after the map's in the key) must be integrated here.
  std::vector<char> integrated(layout_->dofs.overlapMap()->getNodeNumElements(), 0);
  for (std::size_t k = 0; k < mapped; ++k)
    integrated[lid(k)] = 1;
  const auto& overlap = *layout_->dofs.overlapMap();
  for (std::size_t k = mapped; k < key.touched.size(); ++k) {
    const LO node = overlap.getLocalElement(layout_->dofs.nodeDof(key.touched[k], 0));
    if (node == Teuchos::OrdinalTraits<LO>::invalid() || !integrated[node])
      return false;
  }
  const auto& adjacency = layout_->adjacency;
  // Every pair of a group (F-bar's cells, the ghost penalty's faces) must be in the graph.
  for (std::size_t g = 0; g + 1 < key.groupStart.size(); ++g)
    for (std::size_t i = key.groupStart[g]; i < key.groupStart[g + 1]; ++i) {
      const LO a = overlap.getLocalElement(layout_->dofs.nodeDof(key.groupNodes[i], 0));
      for (std::size_t j = key.groupStart[g]; j < key.groupStart[g + 1]; ++j) {
        const LO b = overlap.getLocalElement(layout_->dofs.nodeDof(key.groupNodes[j], 0));
        if (a == Teuchos::OrdinalTraits<LO>::invalid() ||
            b == Teuchos::OrdinalTraits<LO>::invalid() || !adjacency.couples(a, b))
          return false;
      }
    }
  // A particle that touches the nodes it touched in the kept key adds no pair; the kept
  // key's pairs are in the graph (it was built from them, or covered them).
  const bool sameParticles = key.rowPtr.size() == key_.rowPtr.size();
  for (std::size_t p = 0; p + 1 < key.rowPtr.size(); ++p) {
    const std::size_t first = key.rowPtr[p], last = key.rowPtr[p + 1];
    if (sameParticles && last - first == key_.rowPtr[p + 1] - key_.rowPtr[p] &&
        std::equal(key.touched.begin() + first, key.touched.begin() + last,
                   key_.touched.begin() + key_.rowPtr[p]))
      continue;
    for (std::size_t i = first; i < last; ++i)
      for (std::size_t j = first; j < last; ++j)
        if (!adjacency.couples(lid(i), lid(j)))
          return false;
  }
  return true;
}

template <int Dim>
bool LayoutCache<Dim>::sameCouplings(const std::vector<std::pair<GO, GO>>& couplings,
                                     const Comm& comm) const {
  return onEveryRank(layout_ && couplings == layout_->couplings, comm);
}

template <int Dim>
void LayoutCache<Dim>::forget() {
  key_ = LayoutKey<Dim>{};
  layout_.reset();
  entries_ = EntryDofs<>();
  retired_.clear();
  anyRetired_ = false;
}

template <int Dim>
void LayoutCache<Dim>::newUnknowns(const Map& owned) {
  forget();
  if (onNewUnknowns_)
    onNewUnknowns_(owned);
}

template <int Dim>
void LayoutCache<Dim>::keep(LayoutKey<Dim> key, const LaidOut<Dim>& laidOut) {
  const bool same = laidOut.layout == layout_;
  ++(same ? reused_ : built_);
  if (laidOut.anyRetired)
    ++(same ? reusedRetiring_ : builtRetiring_);
  if (laidOut.anyRetired && onRetiredNodes_)
    onRetiredNodes_();
  if (!enabled_)
    return;
  key_ = std::move(key);
  layout_ = laidOut.layout;
  entries_ = laidOut.entryDofs;
  retired_ = laidOut.retired;
  anyRetired_ = laidOut.anyRetired;
}

template <int Dim>
LaidOut<Dim> layoutOf(const LayoutInputs<Dim>& in, LayoutCache<Dim>& cache) {
  const Comm& comm = *in.ownership.comm();
  std::vector<int> firstExtra;
  std::vector<ExtraDof> extras;
  auto key = keyOf(in.ownership, in.map, in.contributions, in.coupling, firstExtra, extras);
  if ((in.cells || in.faces) && in.coupling == NodeCoupling::shared)
    key.groupStart.assign(1, 0);
  if (in.cells && in.coupling == NodeCoupling::shared)
    addCellNodes(*in.cells, key);
  if (in.faces && in.coupling == NodeCoupling::shared)
    addFaceNodes(*in.faces, key);
  auto kept = cache.reusable(key, in.map, comm);
  std::shared_ptr<SystemLayout<Dim>> fresh;
  LaidOut<Dim> out;
  if (kept) {
    out = *kept;
  } else {
    // A layout that may cover later steps' maps takes the nodes just across the rank
    // boundaries into its overlap, for the particles that cross them (core/DofMap.hpp).
    // Also with Graph Reuse off, where nothing is kept: the two then build the same
    // overlap maps and column orders, so their answers stay the same bit for bit.
    const auto halo = cache.allowsRetired() ? OverlapHalo::neighbours : OverlapHalo::none;
    auto numbered = numberUnknowns(in.ownership, in.map, firstExtra, key.touched, extras,
                                   in.coupling, cache.nodesToKeep(key, comm), halo);
    auto [beyond, any] =
        retiredBeyondShareAndAny(numbered.retired, *numbered.layout->dofs.ownedMap());
    if (beyond) {
      numbered = numberUnknowns(in.ownership, in.map, firstExtra, key.touched, extras, in.coupling,
                                {}, halo);
      any = false;
    }
    cache.newUnknowns(*numbered.layout->dofs.ownedMap());
    fresh = numbered.layout;
    out = LaidOut<Dim>{fresh, std::move(numbered.entries), std::move(numbered.retired), any};
  }

  const SystemLayout<Dim>& unknowns = *out.layout;
  // The contributions' couplings, read against these unknowns.
  std::vector<std::pair<GO, GO>> couplings;
  for (std::size_t c = 0; c < in.contributions.size(); ++c)
    in.contributions[c]->couplings(
        ContributionContext<Dim>{in.ownership.grid(), in.particles, in.map, out.entryDofs,
                                 unknowns.dofs, in.time, in.loadFactor, unknowns.firstExtra[c]},
        couplings);
  for (GO padding : unknowns.dofs.paddingDofs())  // its row holds its diagonal only
    couplings.emplace_back(padding, padding);
  if (kept && cache.sameCouplings(couplings, comm)) {
    cache.keep(std::move(key), out);
    return out;
  }
  if (!fresh)
    fresh = std::make_shared<SystemLayout<Dim>>(*kept->layout);
  fresh->couplings = std::move(couplings);
  {
    IMPM_TIMER("graph");
    auto graphCouplings = fresh->couplings;  // and the retired rows' diagonals
    for (LO row : out.retired) {
      const GO dof = fresh->dofs.ownedMap()->getGlobalElement(row);
      graphCouplings.emplace_back(dof, dof);
    }
    fresh->graph = buildGraph(in.map, out.entryDofs, fresh->dofs, graphCouplings, fresh->coupling,
                              &fresh->adjacency, nodeGroups(key, fresh->dofs));
  }
  out.layout = fresh;
  cache.keep(std::move(key), out);
  return out;
}

template class LayoutCache<1>;
template class LayoutCache<2>;
template class LayoutCache<3>;
template LaidOut<1> layoutOf(const LayoutInputs<1>&, LayoutCache<1>&);
template LaidOut<2> layoutOf(const LayoutInputs<2>&, LayoutCache<2>&);
template LaidOut<3> layoutOf(const LayoutInputs<3>&, LayoutCache<3>&);

}  // namespace impm
