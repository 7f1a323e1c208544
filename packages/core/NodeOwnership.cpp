#include "core/NodeOwnership.hpp"

namespace impm {

template <int Dim>
NodeOwnership<Dim>::NodeOwnership(const GridGeometry<Dim>& grid,
                                  const Teuchos::RCP<const Comm>& comm)
    : grid_(grid), comm_(comm), decomposition_(grid, comm->getSize()) {
  repartition(decomposition_);
}

template <int Dim>
void NodeOwnership<Dim>::repartition(Decomposition<Dim> decomposition) {
  decomposition_ = std::move(decomposition);
  ++revision_;
  const auto owned = decomposition_.ownedNodes(comm_->getRank());
  const std::vector<GO> gids(owned.begin(), owned.end());
  nodeMap_ = Teuchos::rcp(new Map(static_cast<Tpetra::global_size_t>(grid_.numNodes()),
                                  Teuchos::ArrayView<const GO>(gids), 0, comm_));
}

template class NodeOwnership<1>;
template class NodeOwnership<2>;
template class NodeOwnership<3>;

}  // namespace impm
