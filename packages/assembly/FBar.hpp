#pragma once
// F-bar: the volumetric part of each particle's deformation gradient replaced by its average
// over the particles of the particle's grid cell (doc/theory.md, "Volumetric locking and
// F-bar"; Coombs, Charlton, Cortis & Augarde, CMAME 2018; de Souza Neto et al. 1996).  With
// g_p the deformation gradient relative to the map's configuration (total Lagrangian: F_p
// itself; updated Lagrangian: the step's f_p = I + grad du), j_p = det g_p and w_p the weight
// of the internal force (section x volume):
//   jbar_c = sum_{q in c} w_q j_q / sum_{q in c} w_q,   theta_p = (jbar_c / j_p)^(1/Dim),
//   gbar_p = theta_p g_p,
// and the laws are evaluated at F = theta_p F_p^std (F^std: the kinematics' own trial F).  A
// cell of one particle has theta = 1 exactly, which leaves a one-particle-per-cell run as it
// was, bit for bit.
// The exact linearisation (dPn = An : dgbar) adds to theta_p times the standard tangent the
// rank-one coupling of the particle's nodes with every node of its cell:
//   K_ia,jc += Q_p,ia (sum_{q in c} omega_q b_jq,c - b_jp,c),
//   Q_p,ia = (1/Dim) w_p sum_B G_ipB sum_cD An_aBcD gbar_p,cD,
//   b_jq = g_q^-T G_jq,  omega_q = w_q j_q / sum_{r in c} w_r j_r,
// which is not symmetric, even for a hyperelastic law.
// Every particle of a cell lives on the cell's owner (particles migrate to the owner of the
// cell holding them: core/Decomposition.hpp), so the averages need no communication, and a
// cell's members are summed in index order, which is id order on any number of ranks.

#include <string>
#include <vector>

#include "assembly/Forces.hpp"
#include "core/Grid.hpp"

namespace impm {

enum class FBar { none, cell };

FBar parseFBar(const std::string& name);
std::string fbarName(FBar f);

// The total-Lagrangian F-bar keeps the compatible F (F^n + grad u, before the average) in this
// particle field: the next step's g starts from it.
inline constexpr const char* kCompatibleFField = "compatible_F";

// Declares the compatible F (total Lagrangian with F-bar), equal to F.
template <int Dim>
void declareFBarFields(ParticleSet<Dim>& particles, FBar fbar, Kinematics kinematics);
// The compatible F set to F (at a commit: the trial g).
template <int Dim>
void storeCompatibleF(const ParticleSet<Dim>& particles,
                      const typename ParticleSet<Dim>::Tensors& F);

// The particles of this rank grouped by the grid cell of their map position, in index order
// within a group: group k holds order(start(k) ... start(k + 1)).
template <class Space = DefaultExecSpace>
struct CellGroups {
  Kokkos::View<std::size_t*, typename Space::memory_space> start;
  Kokkos::View<int*, typename Space::memory_space> order;
  std::vector<GlobalId> cells;  // the cell of each group (host)

  std::size_t size() const { return cells.size(); }
};

// Groups by the cell of y (the map's positions: X in total, x^n in updated Lagrangian).
template <int Dim, class Space = DefaultExecSpace>
CellGroups<Space> groupByCell(const GridGeometry<Dim>& grid,
                              const typename ParticleSet<Dim, Space>::Vectors& y);

// theta_p and omega_p from the step's g (above); theta is NaN where j_p or jbar_c is not
// positive, which the stress check then names.
template <int Dim, class Space = DefaultExecSpace>
void averageDilatation(const CellGroups<Space>& groups, const ParticleSet<Dim, Space>& particles,
                       const typename ParticleSet<Dim, Space>::Tensors& g,
                       const typename ParticleSet<Dim, Space>::Scalars& theta,
                       const typename ParticleSet<Dim, Space>::Scalars& omega);

// F_p *= theta_p.
template <int Dim, class Space = DefaultExecSpace>
void scaleByTheta(const typename ParticleSet<Dim, Space>::Scalars& theta,
                  const typename ParticleSet<Dim, Space>::Tensors& F);

// The coupling term of the tangent (above), for groups of more than one particle.  Its
// columns are the nodes of the whole cell: the graph must hold them (assembly/Graph.hpp).
template <int Dim, class Space = DefaultExecSpace>
void addFBarTangent(const ParticleGridMap<Dim, Space>& map, const EntryDofs<Space>& entryDofs,
                    const ParticleSet<Dim, Space>& particles, const CellGroups<Space>& groups,
                    const typename ParticleSet<Dim, Space>::Tensors& g,
                    const typename ParticleSet<Dim, Space>::Scalars& theta,
                    const typename ParticleSet<Dim, Space>::Scalars& omega,
                    const Tangents<Dim, Space>& An, const LocalMatrix& K);

}  // namespace impm
