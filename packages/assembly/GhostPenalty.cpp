#include "assembly/GhostPenalty.hpp"

#include <Teuchos_CommHelpers.hpp>
#include <algorithm>

#include "assembly/RowAccumulator.hpp"

namespace impm {

namespace {

// 1 where every node of the cell is in one particle's node list, on some rank.  A table over
// all cells: the grid's cell count per rank, as the decomposition's owners.  Collective.
template <int Dim>
std::vector<int> activeCells(const GridGeometry<Dim>& grid, const ParticleGridMap<Dim>& map,
                             const Comm& comm) {
  const auto cells = static_cast<int>(grid.numCells());
  std::vector<int> mine(cells, 0), all(cells, 0);
  auto rowPtr = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), map.rowPtr);
  auto node = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), map.node);
  std::vector<GlobalId> list;
  for (int p = 0; p < static_cast<int>(map.numParticles()); ++p) {
    list.assign(node.data() + rowPtr(p), node.data() + rowPtr(p + 1));
    std::sort(list.begin(), list.end());
    for (const GlobalId n : list) {
      int lower[Dim];
      grid.nodeIndex(n, lower);
      bool inside = true;
      for (int d = 0; d < Dim; ++d)
        inside = inside && lower[d] < grid.cells[d];
      for (int corner = 1; inside && corner < (1 << Dim); ++corner) {
        int at[Dim];
        for (int d = 0; d < Dim; ++d)
          at[d] = lower[d] + ((corner >> d) & 1);
        inside = std::binary_search(list.begin(), list.end(), grid.nodeId(at));
      }
      if (inside)
        mine[grid.cellId(lower)] = 1;
    }
  }
  Teuchos::reduceAll(comm, Teuchos::REDUCE_MAX, cells, mine.data(), all.data());
  return all;
}

// Whether an active cell has a cell of the grid that is not active among the 3^Dim - 1 that
// share a node with it (the grid's outside does not count: a body against the grid's edge
// fills its cells there).
template <int Dim>
bool isCut(const GridGeometry<Dim>& grid, const std::vector<int>& active, const int cell[Dim]) {
  int neighbours = 1;
  for (int d = 0; d < Dim; ++d)
    neighbours *= 3;
  for (int k = 0; k < neighbours; ++k) {
    int at[Dim], code = k;
    bool inside = true;
    for (int d = 0; d < Dim; ++d, code /= 3) {
      at[d] = cell[d] + code % 3 - 1;
      inside = inside && at[d] >= 0 && at[d] < grid.cells[d];
    }
    if (inside && !active[grid.cellId(at)])
      return true;
  }
  return false;
}

// The offsets of face node j from the lower cell's first node (see the header).
template <int Dim>
void faceNodeOffset(int axis, int j, int offset[Dim]) {
  offset[axis] = j % 3;
  int bits = j / 3;
  for (int d = 0; d < Dim; ++d)
    if (d != axis) {
      offset[d] = bits & 1;
      bits >>= 1;
    }
}

}  // namespace

template <int Dim>
GhostFaces ghostFaces(const NodeOwnership<Dim>& ownership, const ParticleGridMap<Dim>& map) {
  const auto& grid = ownership.grid();
  const auto active = activeCells(grid, map, *ownership.comm());
  std::vector<char> cut(active.size(), 0);
  for (std::size_t c = 0; c < active.size(); ++c) {
    int idx[Dim];
    grid.cellIndex(static_cast<GlobalId>(c), idx);
    cut[c] = active[c] && isCut(grid, active, idx);
  }
  GhostFaces faces;
  const int rank = ownership.comm()->getRank();
  for (const GlobalId a : ownership.decomposition().ownedCells(rank)) {
    if (!active[a])
      continue;
    int idx[Dim];
    grid.cellIndex(a, idx);
    for (int axis = 0; axis < Dim; ++axis) {
      if (idx[axis] + 1 >= grid.cells[axis])
        continue;
      int next[Dim];
      std::copy(idx, idx + Dim, next);
      ++next[axis];
      const GlobalId b = grid.cellId(next);
      if (!active[b] || !(cut[a] || cut[b]))
        continue;
      faces.axis.push_back(axis);
      for (int j = 0; j < kFaceNodes<Dim>; ++j) {
        int offset[Dim], at[Dim];
        faceNodeOffset<Dim>(axis, j, offset);
        for (int d = 0; d < Dim; ++d)
          at[d] = idx[d] + offset[d];
        faces.nodes.push_back(grid.nodeId(at));
      }
    }
  }
  return faces;
}

template <int Dim>
std::vector<double> ghostFaceMatrix(const GridGeometry<Dim>& grid, int axis) {
  constexpr int n = kFaceNodes<Dim>;
  constexpr double c[3] = {1.0, -2.0, 1.0};
  std::vector<double> K(n * n);
  for (int j = 0; j < n; ++j)
    for (int l = 0; l < n; ++l) {
      int oj[Dim], ol[Dim];
      faceNodeOffset<Dim>(axis, j, oj);
      faceNodeOffset<Dim>(axis, l, ol);
      double value = c[oj[axis]] * c[ol[axis]] / grid.spacing[axis];
      for (int d = 0; d < Dim; ++d)
        if (d != axis)
          value *= grid.spacing[d] * (oj[d] == ol[d] ? 1.0 / 3.0 : 1.0 / 6.0);
      K[j * n + l] = value;
    }
  return K;
}

template <int Dim, class Space>
GhostFaceDofs<Space> ghostFaceDofs(const GhostFaces& faces, const GridGeometry<Dim>& grid,
                                   const Map& overlap, double scale) {
  constexpr int n = kFaceNodes<Dim>;
  GhostFaceDofs<Space> out;
  out.axis = decltype(out.axis)("ghost face axis", faces.size());
  out.dof = decltype(out.dof)("ghost face DOFs", faces.size(), n);
  out.matrix = decltype(out.matrix)("ghost face matrices", Dim, n, n);
  auto axis = Kokkos::create_mirror_view(out.axis);
  auto dof = Kokkos::create_mirror_view(out.dof);
  auto matrix = Kokkos::create_mirror_view(out.matrix);
  for (std::size_t f = 0; f < faces.size(); ++f) {
    axis(f) = faces.axis[f];
    for (int j = 0; j < n; ++j)
      dof(f, j) = overlap.getLocalElement(static_cast<GO>(faces.nodes[f * n + j]) * Dim);
  }
  for (int a = 0; a < Dim; ++a) {
    const auto K = ghostFaceMatrix(grid, a);
    for (int j = 0; j < n; ++j)
      for (int l = 0; l < n; ++l)
        matrix(a, j, l) = scale * K[j * n + l];
  }
  Kokkos::deep_copy(out.axis, axis);
  Kokkos::deep_copy(out.dof, dof);
  Kokkos::deep_copy(out.matrix, matrix);
  return out;
}

template <int Dim, class Space>
void addGhostForce(const GhostFaceDofs<Space>& faces, const LocalValues& du,
                   const LocalValuesMutable& f) {
  constexpr int n = kFaceNodes<Dim>;
  const auto axis = faces.axis;
  const auto dof = faces.dof;
  const auto matrix = faces.matrix;
  Kokkos::parallel_for(
      "impm::ghostForce", Kokkos::RangePolicy<Space>(0, faces.size()),
      KOKKOS_LAMBDA(const int face) {
        const int a = axis(face);
        for (int j = 0; j < n; ++j)
          for (int c = 0; c < Dim; ++c) {
            double s = 0.0;
            for (int l = 0; l < n; ++l)
              s += matrix(a, j, l) * du(dof(face, l) + c, 0);
            Kokkos::atomic_add(&f(dof(face, j) + c, 0), s);
          }
      });
}

template <int Dim, class Space>
void addGhostTangent(const GhostFaceDofs<Space>& faces, const LocalMatrix& K) {
  constexpr int n = kFaceNodes<Dim>;
  const auto axis = faces.axis;
  const auto dof = faces.dof;
  const auto matrix = faces.matrix;
  Kokkos::parallel_for(
      "impm::ghostTangent", Kokkos::RangePolicy<Space>(0, faces.size()),
      KOKKOS_LAMBDA(const int face) {
        const int a = axis(face);
        for (int j = 0; j < n; ++j)
          for (int c = 0; c < Dim; ++c) {
            RowAccumulator<LocalMatrix> row(K, dof(face, j) + c);
            for (int l = 0; l < n; ++l)
              row.add(dof(face, l) + c, matrix(a, j, l));
          }
      });
}

#define IMPM_INSTANTIATE(D)                                                                        \
  template GhostFaces ghostFaces<D>(const NodeOwnership<D>&, const ParticleGridMap<D>&);           \
  template std::vector<double> ghostFaceMatrix<D>(const GridGeometry<D>&, int);                    \
  template GhostFaceDofs<DefaultExecSpace> ghostFaceDofs<D, DefaultExecSpace>(                     \
      const GhostFaces&, const GridGeometry<D>&, const Map&, double);                              \
  template void addGhostForce<D, DefaultExecSpace>(const GhostFaceDofs<DefaultExecSpace>&,         \
                                                   const LocalValues&, const LocalValuesMutable&); \
  template void addGhostTangent<D, DefaultExecSpace>(const GhostFaceDofs<DefaultExecSpace>&,       \
                                                     const LocalMatrix&);
IMPM_INSTANTIATE(1)
IMPM_INSTANTIATE(2)
IMPM_INSTANTIATE(3)
#undef IMPM_INSTANTIATE

}  // namespace impm
