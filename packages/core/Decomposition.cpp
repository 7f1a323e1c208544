#include "core/Decomposition.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace impm {

namespace {

// Split `numRanks` into per-direction block counts proportional to the cell counts, so that
// blocks are as cubic as the factorisation allows: every factorisation px * py * ... = numRanks
// with no more blocks than cells along a direction is tried, and the one whose block has the
// least surface per volume (the communication per unit work), sum_d 1 / (block length)_d,
// wins; ties go to the first found, fewer blocks along x first.
template <int Dim>
void tryBlocks(const GridGeometry<Dim>& g, int remaining, int d, std::array<int, Dim>& blocks,
               std::array<int, Dim>& best, double& bestCost) {
  if (d == Dim - 1) {
    if (remaining > g.cells[d])
      return;
    blocks[d] = remaining;
    double cost = 0.0;
    for (int k = 0; k < Dim; ++k)
      cost += blocks[k] / double(g.cells[k]);
    if (cost < bestCost)
      bestCost = cost, best = blocks;
    return;
  }
  for (int b = 1; b <= std::min(remaining, g.cells[d]); ++b)
    if (remaining % b == 0) {
      blocks[d] = b;
      tryBlocks<Dim>(g, remaining / b, d + 1, blocks, best, bestCost);
    }
}

template <int Dim>
std::array<int, Dim> chooseBlocks(const GridGeometry<Dim>& g, int numRanks) {
  std::array<int, Dim> best, blocks;
  best.fill(1);
  blocks.fill(1);
  if constexpr (Dim == 1) {
    best[0] = std::min(numRanks, g.cells[0]);
  } else {
    double bestCost = 1e300;
    tryBlocks<Dim>(g, numRanks, 0, blocks, best, bestCost);
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
template class Decomposition<3>;

}  // namespace impm
