#pragma once
// Block decomposition of the grid's cells among MPI ranks: 1-D slabs, 2-D rectangles of
// px x py blocks chosen from the rank count.  A node belongs to the rank that owns the cell
// of which it is the lower (lower-left) corner; the last node along a direction belongs to
// the last cell.  A particle lives on the rank that owns the cell containing its position.

#include <array>
#include <vector>

#include "core/Grid.hpp"

namespace impm {

template <int Dim>
class Decomposition {
 public:
  Decomposition(const GridGeometry<Dim>& grid, int numRanks);

  int numRanks() const { return numRanks_; }
  // Ranks along each direction and the first cell of each block.
  const std::array<int, Dim>& blocks() const { return blocks_; }

  int ownerOfCell(GlobalId cell) const;
  int ownerOfNode(GlobalId node) const;
  int ownerOfPoint(const double x[Dim]) const;

  // Nodes owned by `rank`, ascending.
  std::vector<GlobalId> ownedNodes(int rank) const { return owned(rank, true); }
  // Cells owned by `rank`, ascending.
  std::vector<GlobalId> ownedCells(int rank) const { return owned(rank, false); }

 private:
  int blockOf(int d, int cell) const;
  int rankOfBlockIndex(const int cellIndex[Dim]) const;
  std::vector<GlobalId> owned(int rank, bool nodes) const;

  GridGeometry<Dim> grid_;
  int numRanks_;
  std::array<int, Dim> blocks_;
  std::array<std::vector<int>, Dim> start_;  // start_[d][b] = first cell of block b; size blocks+1
};

}  // namespace impm
