#pragma once
// Decomposition of the grid's cells among MPI ranks: at the start in blocks (1-D slabs, 2-D
// rectangles of px x py blocks chosen from the rank count), after a repartition
// (core/Repartition) by a table of every cell's rank.  A node belongs to the rank that owns
// the cell of which it is the lower (lower-left) corner; the last node along a direction
// belongs to the last cell.  A particle lives on the rank that owns the cell containing its
// position.

#include <array>
#include <memory>
#include <vector>

#include "core/Grid.hpp"

namespace impm {

template <int Dim>
class Decomposition {
 public:
  // Blocks.
  Decomposition(const GridGeometry<Dim>& grid, int numRanks);
  // A table: cellOwners[cell] is the rank of the cell, one entry per cell of the grid.
  Decomposition(const GridGeometry<Dim>& grid, int numRanks, std::vector<int> cellOwners);

  const GridGeometry<Dim>& grid() const { return grid_; }
  int numRanks() const { return numRanks_; }
  // Ranks along each direction (the blocks; a table keeps those it started from).
  const std::array<int, Dim>& blocks() const { return blocks_; }
  // The table of a repartition, empty for blocks.
  const std::vector<int>& cellOwners() const;

  int ownerOfCell(GlobalId cell) const;
  int ownerOfNode(GlobalId node) const;
  int ownerOfPoint(const double x[Dim]) const;

  // Nodes owned by `rank`, ascending.
  std::vector<GlobalId> ownedNodes(int rank) const { return owned(rank, true); }
  // Cells owned by `rank`, ascending.
  std::vector<GlobalId> ownedCells(int rank) const { return owned(rank, false); }

 private:
  int blockOf(int d, int cell) const;
  int rankOfCellIndex(const int cellIndex[Dim]) const;
  std::vector<GlobalId> owned(int rank, bool nodes) const;

  GridGeometry<Dim> grid_;
  int numRanks_;
  std::array<int, Dim> blocks_;
  std::array<std::vector<int>, Dim> start_;  // start_[d][b] = first cell of block b; size blocks+1
  // A repartition's table (shared by the copies of a decomposition; null: blocks).
  std::shared_ptr<const std::vector<int>> owners_;
};

}  // namespace impm
