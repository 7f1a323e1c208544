#pragma once
// Ghost penalty: stiffness for grid nodes that a body reaches by a sliver (doc/theory.md,
// "Nodes that a particle barely reaches"; Burman, C. R. Acad. Sci. Paris 2010; Burman &
// Hansbo, Appl. Numer. Math. 2012; Coombs et al. for implicit MPM, IJNME 2023).  A node
// whose support holds a tiny share of the body has a tiny row in the stiffness: the system
// is nearly singular and Newton's steps move that node without bound.  The penalty
//   j(du, dv) = gamma M sum_F h_F int_F [[d_n du]] . [[d_n dv]] dS
// on the faces F between two active cells of which one is cut, M the largest modulus of the
// laws, ties such a node to its neighbours' gradients.  The jump of the normal derivative
// vanishes for every field linear across the face, so the patch tests stay exact (a
// homogeneous deformation has linear increments), and for smooth fields it is O(h) per
// face: the penalty is weakly consistent and keeps the rates of convergence.
//
// Active cell: every node of it in one particle's support (the map's node list), on any rank.
// Cut cell: an active cell next to (sharing a node with) a cell of the grid that is not
// active, i.e. a cell of the body's boundary layer.  The penalty acts on increments (the
// unknowns of every step), so it adds to the residual K_g du and to the Jacobian K_g.
//
// On a face F normal to axis a, between cell A and cell B = A + e_a, the nodes are those of
// A and B: offset o_a in {0, 1, 2} along a, o_t in {0, 1} along the other axes; node j of the
// face has o_a = j % 3 and the bits of j / 3 as o_t.  For the multilinear shape functions
//   [[d_a N_j]] = c(o_a) / h_a prod_t phi_{o_t}(xi_t),   c = (1, -2, 1),
// so that exactly
//   h_a int_F [[d_a N_j]] [[d_a N_l]] dS = c(o_a) c(o'_a) prod_t h_t m(o_t, o'_t) / h_a
// with m the 1-D mass matrix of a unit element, (1/3, 1/6; 1/6, 1/3).

#include <vector>

#include "assembly/Forces.hpp"
#include "core/NodeOwnership.hpp"

namespace impm {

// Nodes of a face: those of its two cells.
template <int Dim>
inline constexpr int kFaceNodes = 3 << (Dim - 1);

// The faces this rank assembles: those whose lower cell A it owns.
struct GhostFaces {
  std::vector<int> axis;        // the face's normal direction
  std::vector<GlobalId> nodes;  // kFaceNodes<Dim> per face, in the face's node order

  std::size_t size() const { return axis.size(); }
};

// The faces the penalty holds on this map (see above).  The active cells are gathered from
// every rank into a table over the grid's cells, as the decomposition's table of owners is.
// Collective.
template <int Dim>
GhostFaces ghostFaces(const NodeOwnership<Dim>& ownership, const ParticleGridMap<Dim>& map);

// h_a int_F [[d_a N_j]] [[d_a N_l]] dS on a face normal to `axis`, row-major,
// kFaceNodes^2 values.
template <int Dim>
std::vector<double> ghostFaceMatrix(const GridGeometry<Dim>& grid, int axis);

// The faces as the kernels read them: the overlap index of each face node's first DOF and
// the face matrices times gamma M.
template <class Space = DefaultExecSpace>
struct GhostFaceDofs {
  Kokkos::View<int*, typename Space::memory_space> axis;
  Kokkos::View<LO**, Kokkos::LayoutRight, typename Space::memory_space> dof;
  Kokkos::View<double***, Kokkos::LayoutRight, typename Space::memory_space> matrix;

  std::size_t size() const { return axis.extent(0); }
};

// `scale`: gamma M.  Every face node must be on the overlap map.
template <int Dim, class Space = DefaultExecSpace>
GhostFaceDofs<Space> ghostFaceDofs(const GhostFaces& faces, const GridGeometry<Dim>& grid,
                                   const Map& overlap, double scale);

// f_ja += sum_l K_jl du_la over the faces' nodes j, l and components a (du, f: overlap-local).
template <int Dim, class Space = DefaultExecSpace>
void addGhostForce(const GhostFaceDofs<Space>& faces, const LocalValues& du,
                   const LocalValuesMutable& f);

// J_ja,la += K_jl over the faces (rows and columns: overlap indices).
template <int Dim, class Space = DefaultExecSpace>
void addGhostTangent(const GhostFaceDofs<Space>& faces, const LocalMatrix& K);

}  // namespace impm
