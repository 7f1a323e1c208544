#pragma once
// The unknowns of one solve, as Tpetra maps: the displacement components of the *active*
// grid nodes (those that some integration point touches, so that no row of the system is
// empty) plus extra unknowns such as the boundary forces F(0), F(L) of the primer's
// nu_n + 2 system (eq. 1.18-1.19).
//
// Numbering: component d of node n is n * Dim + d; extra unknown k is numNodes * Dim + k.
// The owned map lists, on each rank, its active nodes (ascending) with each extra unknown
// placed right after the DOFs of its anchor node; keeping a boundary force next to the
// nodes it acts on keeps incomplete factorisations (ILU) close to exact.
// The overlap map is the owned map followed by the other DOFs this rank's contributions
// reach, as Tpetra's FE assembly requires; asked to (OverlapHalo::neighbours), also the DOFs
// of the grid neighbours of those nodes that other ranks own and hold as unknowns.  Such a
// halo holds no entry of this step's particles; with it come its patches, the overlap nodes
// of the 2^Dim cells around each halo node (what one particle spanning up to two cells along
// each axis can touch there), which the graph couples as it couples a particle's nodes
// (assembly/Graph.hpp).  A layout kept for later steps (solver/SystemLayout.hpp) then still
// serves when a particle crosses a rank boundary and reaches one node further: a compressed
// column on two ranks built its layout anew for that in 17 of its 40 load steps.
//
// A rank that would own no unknown (no particle near its part of the grid) owns padding
// unknowns instead, fixed at zero by the grid system: Dim of them, numbered as the components
// of a node of their own after the extras, so that solvers that see the unknowns as blocks of
// Dim per node (MueLu's aggregation) find whole blocks on every rank.  Empty
// ranks are not allowed to reach the Krylov solver: Belos' Gram-Schmidt goes through Thyra to
// Tpetra::MultiVector::multiply, whose local product KokkosBlas::gemm returns without writing
// when the rank has no rows (Trilinos 13.2), so whatever the result buffer held is summed into
// every rank's inner products.  Belos' own Tpetra adapter zeroes that buffer first; the
// Thyra path NOX uses does not.  Found as NaNs in GMRES when freed memory was reused.

#include <vector>

#include "core/NodeOwnership.hpp"

namespace impm {

// Leaves the distinct ids of v, ascending.
void sortUnique(std::vector<GlobalId>& v);

// Whether the overlap map adds the neighbours of this rank's nodes that other ranks hold.
enum class OverlapHalo { none, neighbours };

// An extra unknown, owned by the rank that owns its anchor node.
struct ExtraDof {
  GlobalId anchorNode;
};

template <int Dim>
class DofMap {
 public:
  // Collective.  `touched`: the grid nodes this rank's contributions reach (any order,
  // repeats allowed).  `extras`: the same list on every rank.  `halo`: the same on every rank.
  DofMap(const NodeOwnership<Dim>& ownership, std::vector<GlobalId> touched,
         const std::vector<ExtraDof>& extras, OverlapHalo halo = OverlapHalo::none);

  const Teuchos::RCP<const Map>& ownedMap() const { return owned_; }
  const Teuchos::RCP<const Map>& overlapMap() const { return overlap_; }

  GO nodeDof(GlobalId node, int component) const { return node * Dim + component; }
  // The inverse of nodeDof: the node and the component of a nodal DOF (and of a padding
  // DOF, numbered as the components of a node of its own).
  static constexpr GlobalId nodeOf(GO dof) { return dof / Dim; }
  static constexpr int componentOf(GO dof) { return static_cast<int>(dof % Dim); }
  GO extraDof(int k) const { return numNodes_ * Dim + k; }
  // Extra unknowns and the padding unknowns: not displacement components of a node.
  bool isExtraDof(GO dof) const { return dof >= numNodes_ * Dim; }
  // This rank's padding unknowns (see above): none, or Dim.
  const std::vector<GO>& paddingDofs() const { return padding_; }
  int numExtras() const { return numExtras_; }
  // Active nodes owned by this rank, ascending.
  const std::vector<GlobalId>& ownedActiveNodes() const { return ownedActive_; }
  GlobalId numActiveNodes() const { return numActiveNodes_; }
  // The halo's patches (OverlapHalo::neighbours, several ranks): patch k's nodes are
  // haloPatchNodes()[haloPatchStart()[k] ... haloPatchStart()[k + 1]).
  const std::vector<std::size_t>& haloPatchStart() const { return haloPatchStart_; }
  const std::vector<GlobalId>& haloPatchNodes() const { return haloPatchNodes_; }

 private:
  // The patches of the halo nodes (see above); `touched` and `haloNodes` ascending.
  void addHaloPatches(const GridGeometry<Dim>& grid, const std::vector<GlobalId>& touched,
                      const std::vector<GlobalId>& haloNodes);

  GlobalId numNodes_;
  int numExtras_;
  std::vector<GlobalId> ownedActive_;
  GlobalId numActiveNodes_ = 0;
  std::vector<GO> padding_;
  std::vector<std::size_t> haloPatchStart_{0};
  std::vector<GlobalId> haloPatchNodes_;
  Teuchos::RCP<const Map> owned_, overlap_;
};

}  // namespace impm
