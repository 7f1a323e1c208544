#include "core/DofMap.hpp"

#include <algorithm>

#include <Teuchos_CommHelpers.hpp>

namespace impm {

// v lists a node per particle-node pair, so each node many times, within a range of ids not
// much wider than the list: there a mark per id finds them in one pass (sorting them took a quarter
// of an explicit MPM step); otherwise they are sorted.
void sortUnique(std::vector<GlobalId>& v) {
  if (v.empty())
    return;
  const auto [low, high] = std::minmax_element(v.begin(), v.end());
  const GlobalId first = *low, range = *high - *low + 1;
  if (range > 4 * static_cast<GlobalId>(v.size())) {
    std::sort(v.begin(), v.end());
    v.erase(std::unique(v.begin(), v.end()), v.end());
    return;
  }
  std::vector<char> seen(static_cast<std::size_t>(range), 0);
  for (const GlobalId g : v)
    seen[static_cast<std::size_t>(g - first)] = 1;
  v.clear();
  for (GlobalId k = 0; k < range; ++k)
    if (seen[static_cast<std::size_t>(k)])
      v.push_back(first + k);
}

namespace {

// 1 on the owned nodes that some rank touches, 0 on the others: every rank marks the nodes
// it touches, and an Export with ADD brings the marks to the owners.
template <int Dim>
Vector activeNodes(const NodeOwnership<Dim>& ownership, const std::vector<GlobalId>& touched) {
  const auto& nodeMap = ownership.nodeMap();
  const std::vector<GO> gids(touched.begin(), touched.end());
  auto touchedMap = Teuchos::rcp(new Map(Teuchos::OrdinalTraits<Tpetra::global_size_t>::invalid(),
                                         Teuchos::ArrayView<const GO>(gids), 0, ownership.comm()));
  Vector marks(touchedMap);
  marks.putScalar(1.0);
  Vector active(nodeMap);
  active.doExport(marks, Export(touchedMap, nodeMap), Tpetra::ADD);
  return active;
}

std::vector<GlobalId> ownedActive(const Vector& active) {
  std::vector<GlobalId> result;
  const auto& nodeMap = *active.getMap();
  auto values = active.getData();
  for (decltype(values.size()) k = 0; k < values.size(); ++k)
    if (values[k] > 0.0)
      result.push_back(nodeMap.getGlobalElement(static_cast<LO>(k)));
  return result;  // ascending: the node map lists owned nodes in ascending order
}

// Calls f(id) for every grid node at `at` + (o_0 + first, ..., o_Dim-1 + first) with each
// o_d in [0, 3): the 3^Dim nodes from `first` steps below `at` along each axis.
template <int Dim, class F>
void forNodesAround(const GridGeometry<Dim>& grid, const int at[Dim], int first, F&& f) {
  int offsets = 1;
  for (int d = 0; d < Dim; ++d)
    offsets *= 3;
  for (int o = 0; o < offsets; ++o) {
    int next[Dim];
    bool inside = true;
    for (int d = 0, code = o; d < Dim; ++d, code /= 3) {
      next[d] = at[d] + first + code % 3;
      inside = inside && next[d] >= 0 && next[d] <= grid.cells[d];
    }
    if (inside)
      f(grid.nodeId(next));
  }
}

// The grid neighbours (the nodes of the cells around) of the touched nodes that other ranks
// own and this rank does not touch, ascending.
template <int Dim>
std::vector<GlobalId> neighboursOwnedElsewhere(const NodeOwnership<Dim>& ownership,
                                               const std::vector<GlobalId>& touched) {
  const int rank = ownership.comm()->getRank();
  std::vector<GlobalId> result;
  for (const GlobalId node : touched) {
    int at[Dim];
    ownership.grid().nodeIndex(node, at);
    forNodesAround(ownership.grid(), at, -1, [&](GlobalId other) {
      if (ownership.ownerOfNode(other) != rank &&
          !std::binary_search(touched.begin(), touched.end(), other))
        result.push_back(other);
    });
  }
  sortUnique(result);
  return result;
}

// Of `nodes` (ascending), those that `active` marks on their owners.  Collective.
std::vector<GlobalId> activeAmong(const Vector& active, const std::vector<GlobalId>& nodes) {
  const std::vector<GO> gids(nodes.begin(), nodes.end());
  auto nodesMap =
      Teuchos::rcp(new Map(Teuchos::OrdinalTraits<Tpetra::global_size_t>::invalid(),
                           Teuchos::ArrayView<const GO>(gids), 0, active.getMap()->getComm()));
  Vector marks(nodesMap);
  marks.doImport(active, Import(active.getMap(), nodesMap), Tpetra::INSERT);
  std::vector<GlobalId> result;
  auto values = marks.getData();
  for (decltype(values.size()) k = 0; k < values.size(); ++k)
    if (values[k] > 0.0)
      result.push_back(nodes[k]);
  return result;
}

}  // namespace

template <int Dim>
DofMap<Dim>::DofMap(const NodeOwnership<Dim>& ownership, std::vector<GlobalId> touched,
                    const std::vector<ExtraDof>& extras, OverlapHalo halo)
    : numNodes_(ownership.grid().numNodes()), numExtras_(static_cast<int>(extras.size())) {
  const auto& comm = ownership.comm();
  const int rank = comm->getRank();
  sortUnique(touched);
  const Vector active = activeNodes(ownership, touched);
  ownedActive_ = ownedActive(active);
  const GlobalId localActive = static_cast<GlobalId>(ownedActive_.size());
  Teuchos::reduceAll(*comm, Teuchos::REDUCE_SUM, localActive, Teuchos::outArg(numActiveNodes_));

  // Owned DOFs: node components ascending, each extra right after its anchor node.
  std::vector<GO> owned;
  owned.reserve(ownedActive_.size() * Dim + extras.size());
  std::vector<std::pair<GlobalId, int>> myExtras;  // (anchor, k), sorted by anchor
  for (int k = 0; k < numExtras_; ++k)
    if (ownership.ownerOfNode(extras[k].anchorNode) == rank)
      myExtras.emplace_back(extras[k].anchorNode, k);
  std::sort(myExtras.begin(), myExtras.end());
  auto nextExtra = myExtras.begin();
  for (GlobalId node : ownedActive_) {
    for (; nextExtra != myExtras.end() && nextExtra->first < node; ++nextExtra)
      owned.push_back(extraDof(nextExtra->second));
    for (int d = 0; d < Dim; ++d)
      owned.push_back(nodeDof(node, d));
    for (; nextExtra != myExtras.end() && nextExtra->first == node; ++nextExtra)
      owned.push_back(extraDof(nextExtra->second));
  }
  for (; nextExtra != myExtras.end(); ++nextExtra)
    owned.push_back(extraDof(nextExtra->second));
  if (owned.empty()) {
    const GO first = (extraDof(numExtras_) + Dim - 1) / Dim * Dim + GO(rank) * Dim;
    for (int d = 0; d < Dim; ++d)
      padding_.push_back(first + d);
    owned = padding_;
  }

  // Overlap DOFs: the owned ones first, then touched nodes owned elsewhere.
  std::vector<GO> overlap = owned;
  for (GlobalId node : touched)
    if (ownership.ownerOfNode(node) != rank)
      for (int d = 0; d < Dim; ++d)
        overlap.push_back(nodeDof(node, d));
  if (halo == OverlapHalo::neighbours && comm->getSize() > 1) {
    const auto haloNodes = activeAmong(active, neighboursOwnedElsewhere(ownership, touched));
    for (GlobalId node : haloNodes)
      for (int d = 0; d < Dim; ++d)
        overlap.push_back(nodeDof(node, d));
    addHaloPatches(ownership.grid(), touched, haloNodes);
  }

  const auto invalid = Teuchos::OrdinalTraits<Tpetra::global_size_t>::invalid();
  owned_ = Teuchos::rcp(new Map(invalid, Teuchos::ArrayView<const GO>(owned), 0, comm));
  overlap_ = Teuchos::rcp(new Map(invalid, Teuchos::ArrayView<const GO>(overlap), 0, comm));
}

template <int Dim>
void DofMap<Dim>::addHaloPatches(const GridGeometry<Dim>& grid,
                                 const std::vector<GlobalId>& touched,
                                 const std::vector<GlobalId>& haloNodes) {
  const auto inOverlap = [&](GlobalId node) {
    return std::binary_search(touched.begin(), touched.end(), node) ||
           std::binary_search(haloNodes.begin(), haloNodes.end(), node);
  };
  for (const GlobalId node : haloNodes) {
    int at[Dim];
    grid.nodeIndex(node, at);
    forNodesAround(grid, at, -2, [&](GlobalId corner) {  // the patches' lowest nodes
      int from[Dim];
      grid.nodeIndex(corner, from);
      forNodesAround(grid, from, 0, [&](GlobalId member) {
        if (inOverlap(member))
          haloPatchNodes_.push_back(member);
      });
      haloPatchStart_.push_back(haloPatchNodes_.size());
    });
  }
}

template class DofMap<1>;
template class DofMap<2>;
template class DofMap<3>;

}  // namespace impm
