#pragma once
// The sparsity graph of the grid system: node i couples with node j when one integration
// point touches both (the rows of the ragged array Y), every component with every other;
// plus the couplings that boundary conditions add (boundary-force unknowns and the nodes
// they act on).  Rows are built once with their exact length and handed to Tpetra's
// FECrsGraph with local indices of a column map made first: the overlap map's columns, in
// its order, then those that other ranks' shared rows will bring (exchanged ahead of the
// rows).  The FECrsGraph then exports shared rows to their owners.  An overlap-map index is
// thus also the column index of the same unknown, which the assembly kernels rely on.
// Where the overlap map holds a halo (core/DofMap.hpp), its patches are coupled as a
// particle's nodes are, so that a particle crossing a rank boundary later finds its entries.
// An explicit step with the lumped mass couples each node with itself only (its Jacobian's
// nodal block is diagonal): its graph is then the nodes' own blocks and the boundary
// couplings, a few entries per row instead of all the node pairs of the particles.

#include <utility>
#include <vector>

#include "basis/ParticleGridMap.hpp"
#include "core/DofMap.hpp"

namespace impm {

// Which nodes a node's rows couple with: every node that shares an integration point with
// it (the stiffness, the consistent mass), or itself alone (the lumped mass).
enum class NodeCoupling { shared, self };

// The node pairs of a graph built with shared coupling, by overlap index of the nodes'
// first components: the nodes that node `a` couples with are columns[start[a] ...
// start[a + 1]), sorted.  Kept with a layout, it tells whether a later map's node pairs all
// have their entries in that graph (solver/SystemLayout.hpp).
struct NodeAdjacency {
  std::vector<std::size_t> start;
  std::vector<LO> columns;

  bool couples(LO a, LO b) const;
};

// Groups of nodes by the overlap index of their first DOF: group k is
// nodes[start[k] ... start[k + 1]).
struct NodeGroups {
  std::vector<std::size_t> start{0};
  std::vector<LO> nodes;
};

// `adjacency`: if not null, receives the node pairs (shared coupling only).  `groups`: more
// nodes coupled as a particle's are (F-bar's cells: assembly/FBar.hpp), with shared coupling.
template <int Dim>
Teuchos::RCP<FECrsGraph> buildGraph(const ParticleGridMap<Dim>& map,
                                    const Kokkos::View<LO*>& entryDofs, const DofMap<Dim>& dofs,
                                    const std::vector<std::pair<GO, GO>>& extraCouplings,
                                    NodeCoupling coupling = NodeCoupling::shared,
                                    NodeAdjacency* adjacency = nullptr,
                                    const NodeGroups& groups = NodeGroups{});

}  // namespace impm
