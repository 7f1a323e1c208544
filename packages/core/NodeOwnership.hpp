#pragma once
// Which rank owns which grid node, as a Tpetra map over all grid nodes (built with the
// decomposition, again when it is repartitioned).  Used to find the active nodes of a step and
// to gather nodal output.

#include <Teuchos_RCP.hpp>

#include "core/Decomposition.hpp"
#include "core/TpetraTypes.hpp"

namespace impm {

template <int Dim>
class NodeOwnership {
 public:
  NodeOwnership(const GridGeometry<Dim>& grid, const Teuchos::RCP<const Comm>& comm);

  // The cells (and so the nodes) go to the ranks `decomposition` says.  Collective.  The
  // caller moves what lives on the old node map (core/Repartition.hpp).
  void repartition(Decomposition<Dim> decomposition);

  const GridGeometry<Dim>& grid() const { return grid_; }
  const Decomposition<Dim>& decomposition() const { return decomposition_; }
  const Teuchos::RCP<const Comm>& comm() const { return comm_; }
  // Map of all grid nodes, each owned by the rank of its cell.
  const Teuchos::RCP<const Map>& nodeMap() const { return nodeMap_; }
  int ownerOfNode(GlobalId node) const { return decomposition_.ownerOfNode(node); }
  // Counts the repartitions: what was built on the node map is stale when it changed.
  int revision() const { return revision_; }

 private:
  GridGeometry<Dim> grid_;
  Teuchos::RCP<const Comm> comm_;
  Decomposition<Dim> decomposition_;
  Teuchos::RCP<const Map> nodeMap_;
  int revision_ = 0;
};

}  // namespace impm
