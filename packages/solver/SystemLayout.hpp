#pragma once
// The layout of a step's grid system: the unknowns (DofMap), the graph, the importer from
// the owned to the overlap unknowns and the nodal mask; beside it (LaidOut) the overlap
// index of every particle-grid map entry, which is also its column.  In updated-Lagrangian runs
// building them is most of a step's set-up, yet they depend only on
//   - the (particle, node) pairs of the map (its rows and their nodes, in order),
//   - the nodes and extra unknowns the contributions add (Contribution::prepare),
//   - the couplings the contributions add (Contribution::couplings),
//   - the ownership of the nodes (a repartition changes it),
//   - which nodes a node couples with (assembly/Graph.hpp: all that share a particle, or
//     itself alone in explicit steps with the lumped mass),
// not on the weights phi_ip, G_ip.  A stepper keeps the last layout in a LayoutCache; the
// next system takes it over when all of these are the same on every rank (no particle
// entered or left a node's support, no migration reordered the particles), and builds a
// new one otherwise.  A reused layout is identical to the one that would be built, so the
// results do not change at all.
// When each node couples with itself alone, only the overlap indices of the entries depend
// on the (particle, node) pairs; the rest depends on the set of nodes the map touches.  The
// key is then that set, and a kept layout serves with the entries' indices made anew (an
// explicit MPM step whose particles moved within the same nodes' supports).
// A static step may also take over a kept layout whose unknowns and graph cover the new
// map (a LayoutCache made with allowRetired): every node the map and the contributions touch is
// one of its unknowns and every node pair of the map has its entries in its graph.  The
// nodes the map no longer touches are retired: their rows, which no particle sums into,
// hold the prescribed-row diagonal and their increments are fixed at zero (GridSystem's
// constrained rows), which is what leaving them out of the system gives.  A compressed body
// leaves nodes at its ends every load step without ever reaching new ones, and its
// particles cross nodes whose pairs its other particles already couple; such steps then
// keep the unknowns and the graph, up to 5 % of the unknowns retired (covering()).  The
// answers equal those of a built layout to round-off (the zero rows and entries change the
// order of sums; on the columns they are bit for bit the same).
// Where the preconditioner serves retired nodes (a multigrid hierarchy: setKeepUnknowns),
// a new layout also keeps the kept one's unknowns that nothing touches any more, retired
// under the same share: while no node is new, the unknowns, and the hierarchy built for
// them, stay the same as the particles leave nodes.

#include <functional>
#include <memory>
#include <optional>
#include <utility>
#include <vector>

#include "assembly/FBar.hpp"
#include "assembly/GhostPenalty.hpp"
#include "assembly/Graph.hpp"
#include "assembly/Kinematics.hpp"
#include "core/DofMap.hpp"
#include "solver/Contribution.hpp"

namespace impm {

template <int Dim>
struct SystemLayout {
  SystemLayout(std::vector<int> extras, DofMap<Dim> unknowns, NodeCoupling nodes)
      : firstExtra(std::move(extras)), dofs(std::move(unknowns)), coupling(nodes) {}

  std::vector<int> firstExtra;  // each contribution's first extra unknown
  DofMap<Dim> dofs;
  NodeCoupling coupling;  // the graph's
  Teuchos::RCP<const Import> importer;
  Teuchos::RCP<const Vector> nodalMask;      // 1 on nodal unknowns, 0 on extra unknowns
  std::vector<LO> extraRows;                 // the owned rows of extra unknowns
  std::vector<std::pair<GO, GO>> couplings;  // the contributions' and the padding's entries
  Teuchos::RCP<FECrsGraph> graph;
  NodeAdjacency adjacency;  // the graph's node pairs (shared coupling)
};

// What the unknowns are built from (the first three items above), on this rank.
template <int Dim>
struct LayoutKey {
  const NodeOwnership<Dim>* ownership = nullptr;
  int ownershipRevision = -1;
  NodeCoupling coupling = NodeCoupling::shared;
  std::vector<std::size_t> rowPtr;   // the map's rows
  std::vector<GlobalId> touched;     // the map's nodes, then the contributions', the faces'
  std::vector<GlobalId> extraNodes;  // the anchor node of every extra unknown
  // Nodes the graph couples beyond a particle's (group k: groupNodes[groupStart[k] ...
  // groupStart[k + 1]), sorted): F-bar's cells (the nodes of each cell's particles), then
  // the ghost penalty's faces (the nodes of their two cells); empty without either.
  std::vector<std::size_t> groupStart;
  std::vector<GlobalId> groupNodes;

  bool operator==(const LayoutKey& o) const {
    return ownership == o.ownership && ownershipRevision == o.ownershipRevision &&
           coupling == o.coupling && rowPtr == o.rowPtr && touched == o.touched &&
           extraNodes == o.extraNodes && groupStart == o.groupStart && groupNodes == o.groupNodes;
  }
};

// A system's layout and the overlap index of each entry of its map (kept beside the layout:
// a layout kept with self coupling or with retired nodes serves maps with other entries).
template <int Dim>
struct LaidOut {
  std::shared_ptr<const SystemLayout<Dim>> layout;
  EntryDofs<> entryDofs;
  std::vector<LO> retired;  // owned rows of retired nodes (every component), ascending
  bool anyRetired = false;  // on any rank
};

template <int Dim>
class LayoutCache {
 public:
  // `allowRetired`: whether a kept layout may serve a map that touches fewer nodes (static
  // steps: the retired nodes have no mass to divide by).
  explicit LayoutCache(bool enabled = true, bool allowRetired = false)
      : enabled_(enabled), allowRetired_(allowRetired) {}

  // The kept layout laid out for `map`, whose key is `key`: when `key` is the kept one on
  // every rank, or when retired nodes are allowed and the kept layout covers the map (see
  // above).  Collective.
  std::optional<LaidOut<Dim>> reusable(const LayoutKey<Dim>& key, const ParticleGridMap<Dim>& map,
                                       const Comm& comm);
  // True if `couplings` are the kept layout's on every rank.  Collective.
  bool sameCouplings(const std::vector<std::pair<GO, GO>>& couplings, const Comm& comm) const;
  void keep(LayoutKey<Dim> key, const LaidOut<Dim>& laidOut);
  // Told the owned unknowns of every newly numbered layout, before its graph is built (a
  // stepper frees the preconditioner that cannot serve them).
  void setOnNewUnknowns(std::function<void(const Map&)> f) { onNewUnknowns_ = std::move(f); }
  // New unknowns were numbered: the kept layout cannot serve them, so it goes before the
  // new graph is built, and the callback is told.  Collective.
  void newUnknowns(const Map& owned);
  // Drops the kept layout: the next system builds its own.
  void forget();
  // Told when a kept layout serves with retired nodes, before the step's matrix is made:
  // a stepper whose preconditioner does not serve retired nodes frees it, as it does for
  // new unknowns.  A factorisation built while the retired nodes were active, whose rows
  // held the little stiffness of the particles about to leave them, is a poor one once
  // they are fixed (GMRES took hundreds of iterations instead of 10 on a compressed column);
  // solved exactly on those rows (solver/DecoupledRows.hpp) it still took 853 iterations
  // against 611 on the Hencky column at 1 x 16384 cells, and it holds the last step's
  // Jacobian while the next is made (10 % more peak memory on that column).
  void setOnRetiredNodes(std::function<void()> f) { onRetiredNodes_ = std::move(f); }
  // Whether a new layout keeps the unknowns of the kept one that nothing touches any more
  // (as retired nodes, under the same share as covering()), so that the unknowns, and the
  // preconditioner built for them, stay the same while the particles leave nodes.  Where
  // the preconditioner serves retired nodes: a multigrid hierarchy (elsewhere the retired
  // rows would cost their share of every solve for nothing).  The 64 x 512 column, whose
  // top leaves a row of nodes every load step, then builds one hierarchy instead of ten.
  void setKeepUnknowns(bool keep) { keepUnknowns_ = keep; }
  // The kept layout's owned nodes, which a new layout for `key` keeps as unknowns, or none.
  // Collective.
  const std::vector<GlobalId>& nodesToKeep(const LayoutKey<Dim>& key, const Comm& comm) const;

  bool enabled() const { return enabled_; }
  bool allowsRetired() const { return allowRetired_; }
  int built() const { return built_; }
  int reused() const { return reused_; }
  // Of the reuses, those with retired nodes.
  int reusedRetiring() const { return reusedRetiring_; }
  // Of the layouts built, those that kept retired nodes as unknowns (setKeepUnknowns).
  int builtRetiring() const { return builtRetiring_; }

 private:
  // The kept layout if it covers `map` (key `key`), with the retired nodes.  Collective.
  std::optional<LaidOut<Dim>> covering(const LayoutKey<Dim>& key, const ParticleGridMap<Dim>& map,
                                       const Comm& comm) const;
  // Whether the kept layout's unknowns may serve `key` with retired nodes (local).
  bool comparableWith(const LayoutKey<Dim>& key) const;
  // Whether every node pair of the particles whose nodes differ from the kept key's has its
  // entries in the kept graph (local).
  bool pairsCovered(const LayoutKey<Dim>& key, const EntryDofs<>& entries) const;

  bool enabled_;
  bool allowRetired_ = false;
  bool keepUnknowns_ = false;
  LayoutKey<Dim> key_;
  std::shared_ptr<const SystemLayout<Dim>> layout_;
  EntryDofs<> entries_;  // of the kept key's map (with retired nodes, not the layout's own)
  std::vector<LO> retired_;
  bool anyRetired_ = false;
  std::function<void(const Map&)> onNewUnknowns_;
  std::function<void()> onRetiredNodes_;
  int built_ = 0, reused_ = 0, reusedRetiring_ = 0, builtRetiring_ = 0;
};

template <int Dim>
using Contributions = std::vector<std::shared_ptr<Contribution<Dim>>>;

// What a step's system is built on.
template <int Dim>
struct LayoutInputs {
  const NodeOwnership<Dim>& ownership;
  const ParticleGridMap<Dim>& map;
  const ParticleSet<Dim>& particles;
  const Contributions<Dim>& contributions;
  double time, loadFactor;  // for the contributions' context
  NodeCoupling coupling;
  const CellGroups<>* cells = nullptr;  // F-bar's groups, whose nodes the graph couples
  const GhostFaces* faces = nullptr;    // the ghost penalty's, whose nodes the graph couples
};

// The layout of the system on `in.map`: the cache's when nothing it depends on changed,
// otherwise a new one, which the cache keeps (a new graph only, when only the couplings
// changed).  Calls every contribution's prepare().  Collective; NumericalError when a node
// that a boundary condition reaches is reached by no integration point.
template <int Dim>
LaidOut<Dim> layoutOf(const LayoutInputs<Dim>& in, LayoutCache<Dim>& cache);

}  // namespace impm
