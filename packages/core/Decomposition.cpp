#include "core/Decomposition.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace impm {

namespace {

// Split `numRanks` into per-direction block counts proportional to the cell counts, so that
// blocks are as square as the factorisation allows.  Never more blocks than cells.
template <int Dim>
std::array<int, Dim> chooseBlocks(const GridGeometry<Dim>& g, int numRanks) {
  std::array<int, Dim> best;
  best.fill(1);
  static_assert(Dim == 1 || Dim == 2, "Decomposition: the block shapes of this dimension");
  if constexpr (Dim == 1) {
    best[0] = std::min(numRanks, g.cells[0]);
  } else {
    double bestCost = 1e300;
    for (int px = 1; px <= numRanks; ++px) {
      if (numRanks % px)
        continue;
      const int py = numRanks / px;
      if (px > g.cells[0] || py > g.cells[1])
        continue;
      // Perimeter of a block relative to its area: the communication per unit work.
      const double bx = double(g.cells[0]) / px, by = double(g.cells[1]) / py;
      const double cost = (bx + by) / (bx * by);
      if (cost < bestCost) {
        bestCost = cost;
        best = {px, py};
      }
    }
  }
  return best;
}

}  // namespace

template <int Dim>
Decomposition<Dim>::Decomposition(const GridGeometry<Dim>& grid, int numRanks)
    : grid_(grid), numRanks_(numRanks), blocks_(chooseBlocks<Dim>(grid, numRanks)) {
  for (int d = 0; d < Dim; ++d) {
    const int n = grid.cells[d], b = blocks_[d];
    start_[d].resize(b + 1);
    for (int k = 0; k <= b; ++k)
      start_[d][k] = static_cast<int>((static_cast<long>(n) * k) / b);
  }
}

template <int Dim>
Decomposition<Dim>::Decomposition(const GridGeometry<Dim>& grid, int numRanks,
                                  std::vector<int> cellOwners)
    : Decomposition(grid, numRanks) {
  if (static_cast<GlobalId>(cellOwners.size()) != grid.numCells())
    throw std::invalid_argument("a decomposition table needs one rank per cell");
  for (int owner : cellOwners)
    if (owner < 0 || owner >= numRanks)
      throw std::invalid_argument("a decomposition table names a rank that does not exist");
  owners_ = std::make_shared<const std::vector<int>>(std::move(cellOwners));
}

template <int Dim>
const std::vector<int>& Decomposition<Dim>::cellOwners() const {
  static const std::vector<int> none;
  return owners_ ? *owners_ : none;
}

template <int Dim>
int Decomposition<Dim>::blockOf(int d, int cell) const {
  const auto& s = start_[d];
  return static_cast<int>(std::upper_bound(s.begin(), s.end(), cell) - s.begin()) - 1;
}

template <int Dim>
int Decomposition<Dim>::rankOfCellIndex(const int cellIndex[Dim]) const {
  if (owners_)
    return (*owners_)[static_cast<std::size_t>(grid_.cellId(cellIndex))];
  int rank = 0;
  for (int d = Dim - 1; d >= 0; --d)
    rank = rank * blocks_[d] + blockOf(d, cellIndex[d]);
  return rank;
}

template <int Dim>
int Decomposition<Dim>::ownerOfCell(GlobalId cell) const {
  int idx[Dim];
  grid_.cellIndex(cell, idx);
  return rankOfCellIndex(idx);
}

template <int Dim>
int Decomposition<Dim>::ownerOfNode(GlobalId node) const {
  int idx[Dim];
  grid_.nodeIndex(node, idx);
  for (int d = 0; d < Dim; ++d)
    idx[d] = std::min(idx[d], grid_.cells[d] - 1);
  return rankOfCellIndex(idx);
}

template <int Dim>
int Decomposition<Dim>::ownerOfPoint(const double x[Dim]) const {
  int idx[Dim];
  for (int d = 0; d < Dim; ++d)
    idx[d] = grid_.cellAlong(d, x[d]);
  return rankOfCellIndex(idx);
}

template <int Dim>
std::vector<GlobalId> Decomposition<Dim>::owned(int rank, bool nodes) const {
  if (owners_) {  // every cell, or node, whose owner is rank: ascending by construction
    std::vector<GlobalId> ids;
    const GlobalId count = nodes ? grid_.numNodes() : grid_.numCells();
    for (GlobalId id = 0; id < count; ++id)
      if ((nodes ? ownerOfNode(id) : (*owners_)[static_cast<std::size_t>(id)]) == rank)
        ids.push_back(id);
    return ids;
  }
  // The rank's block of cells is [start_[d][b], start_[d][b + 1]) along each direction; its
  // nodes are the same range, plus the last node of the grid for the last block.
  int lo[Dim], hi[Dim];
  for (int d = 0, r = rank; d < Dim; ++d) {
    const int b = r % blocks_[d];
    r /= blocks_[d];
    lo[d] = start_[d][b];
    hi[d] = start_[d][b + 1] + ((nodes && b == blocks_[d] - 1) ? 1 : 0);
  }
  std::vector<GlobalId> ids;
  int idx[Dim];
  for (int d = 0; d < Dim; ++d)
    idx[d] = lo[d];
  while (true) {
    ids.push_back(nodes ? grid_.nodeId(idx) : grid_.cellId(idx));
    int d = 0;
    while (d < Dim && ++idx[d] == hi[d])
      idx[d] = lo[d], ++d;
    if (d == Dim)
      break;
  }
  std::sort(ids.begin(), ids.end());
  return ids;
}

template class Decomposition<1>;
template class Decomposition<2>;

}  // namespace impm
