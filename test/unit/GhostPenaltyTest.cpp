// assembly/GhostPenalty: the face matrix is the exact jump integral (zero on linear fields,
// 4 h_a^3 prod h_t on x_a^2), and the faces are those between two active cells of which one
// is on the body's boundary, each assembled once over the ranks.

#include <gtest/gtest.h>

#include <array>
#include <cmath>

#include <Teuchos_CommHelpers.hpp>
#include <Teuchos_DefaultComm.hpp>

#include "assembly/GhostPenalty.hpp"

namespace impm {
namespace {

// Face node j's offsets from the lower cell's first node, as the header states them.
template <int Dim>
std::array<int, Dim> offsets(int axis, int j) {
  std::array<int, Dim> o{};
  o[axis] = j % 3;
  int bits = j / 3;
  for (int d = 0; d < Dim; ++d)
    if (d != axis)
      o[d] = bits & 1, bits >>= 1;
  return o;
}

template <int Dim>
void checkFaceMatrix(const GridGeometry<Dim>& grid) {
  constexpr int n = kFaceNodes<Dim>;
  for (int axis = 0; axis < Dim; ++axis) {
    const auto K = ghostFaceMatrix(grid, axis);
    std::vector<std::array<double, Dim>> x(n);
    for (int j = 0; j < n; ++j)
      for (int d = 0; d < Dim; ++d)
        x[j][d] = 0.3 + offsets<Dim>(axis, j)[d] * grid.spacing[d];
    double size = 0.0;
    for (double k : K)
      size = std::max(size, std::abs(k));
    for (int j = 0; j < n; ++j)
      for (int l = 0; l < n; ++l)
        EXPECT_EQ(K[j * n + l], K[l * n + j]);
    // A linear field has no jump: K u = 0.
    for (int j = 0; j < n; ++j) {
      double Ku = 0.0;
      for (int l = 0; l < n; ++l) {
        double u = 0.7;
        for (int d = 0; d < Dim; ++d)
          u += (d + 1.5) * x[l][d];
        Ku += K[j * n + l] * u;
      }
      EXPECT_NEAR(Ku, 0.0, 1e-13 * size) << "axis " << axis << " node " << j;
    }
    // u = x_a^2: slopes h_a and 3 h_a on the two sides, a jump of 2 h_a over the face, so
    // h_a int_F jump^2 = 4 h_a^3 prod_t h_t.
    double uKu = 0.0, expected = 4.0 * std::pow(grid.spacing[axis], 3);
    for (int d = 0; d < Dim; ++d)
      if (d != axis)
        expected *= grid.spacing[d];
    for (int j = 0; j < n; ++j)
      for (int l = 0; l < n; ++l) {
        const double a = offsets<Dim>(axis, j)[axis] * grid.spacing[axis];
        const double b = offsets<Dim>(axis, l)[axis] * grid.spacing[axis];
        uKu += a * a * K[j * n + l] * b * b;
      }
    EXPECT_NEAR(uKu, expected, 1e-13 * expected) << "axis " << axis;
  }
}

TEST(GhostPenalty, FaceMatrixIsTheJumpIntegralAndVanishesOnLinearFields) {
  checkFaceMatrix(makeGridGeometry<1>({0.0}, {1.0}, {4}));
  checkFaceMatrix(makeGridGeometry<2>({0.0, 0.0}, {2.0, 1.0}, {4, 8}));
}

// A map whose particle k reaches the nodes of cell cells[k] (every rank has the same ones).
ParticleGridMap<2> mapOverCells(const GridGeometry<2>& grid,
                                const std::vector<std::array<int, 2>>& cells) {
  ParticleGridMap<2> map;
  const std::size_t count = cells.size();
  map.rowPtr = decltype(map.rowPtr)("rowPtr", count + 1);
  map.node = decltype(map.node)("node", 4 * count);
  map.phi = decltype(map.phi)("phi", 4 * count);
  map.grad = decltype(map.grad)("grad", 4 * count);
  for (std::size_t p = 0; p < count; ++p) {
    map.rowPtr(p + 1) = 4 * (p + 1);
    for (int k = 0; k < 4; ++k) {
      const int at[2] = {cells[p][0] + (k & 1), cells[p][1] + (k >> 1)};
      map.node(4 * p + k) = grid.nodeId(at);
    }
  }
  return map;
}

TEST(GhostPenalty, FacesJoinTheBoundaryCellsToTheirActiveNeighboursOnce) {
  auto comm = Teuchos::DefaultComm<int>::getComm();
  const auto grid = makeGridGeometry<2>({0.0, 0.0}, {1.0, 1.0}, {4, 4});
  NodeOwnership<2> own(grid, comm);
  // Active: the 2 x 2 block at the grid's corner and cell (2, 0).  Cell (0, 0) touches only
  // active cells and the grid's outside: not cut; the others touch an empty cell.  Faces
  // between active cells: (0,0)-(1,0), (1,0)-(2,0), (0,1)-(1,1) along x; (0,0)-(0,1),
  // (1,0)-(1,1) along y; each has a cut cell.
  const auto map = mapOverCells(grid, {{0, 0}, {1, 0}, {0, 1}, {1, 1}, {2, 0}});
  const auto faces = ghostFaces(own, map);
  ASSERT_EQ(faces.nodes.size(), faces.size() * kFaceNodes<2>);
  std::vector<int> mine(8, 0), all(8, 0);  // (axis, lower cell x, lower cell y) coded
  for (std::size_t f = 0; f < faces.size(); ++f) {
    int first[2];
    grid.nodeIndex(faces.nodes[f * kFaceNodes<2>], first);
    const int code = faces.axis[f] * 4 + first[1] * 3 + first[0];
    ASSERT_LT(code, 8);
    ++mine[code];
  }
  Teuchos::reduceAll(*comm, Teuchos::REDUCE_SUM, 8, mine.data(), all.data());
  // along x: (0,0) code 0, (1,0) code 1, (0,1) code 3; along y: (0,0) code 4, (1,0) code 5.
  EXPECT_EQ(all, (std::vector<int>{1, 1, 0, 1, 1, 1, 0, 0}));
}

TEST(GhostPenalty, NoFaceWhereEveryActiveCellIsSurrounded) {
  // A body filling the grid: nothing is cut.
  auto comm = Teuchos::DefaultComm<int>::getComm();
  const auto grid = makeGridGeometry<2>({0.0, 0.0}, {1.0, 1.0}, {2, 2});
  NodeOwnership<2> own(grid, comm);
  const auto map = mapOverCells(grid, {{0, 0}, {1, 0}, {0, 1}, {1, 1}});
  int mine = static_cast<int>(ghostFaces(own, map).size()), all = 0;
  Teuchos::reduceAll(*comm, Teuchos::REDUCE_SUM, mine, Teuchos::outArg(all));
  EXPECT_EQ(all, 0);
}

}  // namespace
}  // namespace impm
