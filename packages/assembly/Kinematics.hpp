#pragma once
// Deformation of the integration points during a step.  The unknowns of a step are the
// grid displacement increments du_i (primer 1.5.3: the grid is reset every step).
//  - total Lagrangian: the map stays at the reference positions X_p and
//    F = F^n + sum_i du_i (x) G_ip (gradients with respect to X).  Forces are integrated over
//    the reference configuration with P itself.  With the 1-D laws written in eps = F - 1
//    this is the primer's small-deformation bar (eq. 1.54: eps = du/dx); it is also FEM on
//    the grid as a fixed mesh.
//  - updated Lagrangian (MPM): the map is built at the positions x^n of the start of the
//    step and F = (I + sum_i du_i (x) G_ip) F^n.  Forces are integrated over the
//    configuration at the start of the step with the first Piola stress relative to it,
//    P^n = P (F^n)^T / J^n, and its tangent A^n_aBcD = A_aEcG F^n_BE F^n_DG / J^n.
//
// Every kernel of this package takes the execution space as a template parameter; the
// libraries instantiate Kokkos' default space (Debian's Trilinos: Serial).

#include "basis/ParticleGridMap.hpp"
#include "core/ParticleSet.hpp"
#include "core/Tensor.hpp"
#include "core/TpetraTypes.hpp"
#include "material/Material.hpp"

namespace impm {

enum class Kinematics { totalLagrangian, updatedLagrangian };

template <int Dim, class Space = DefaultExecSpace>
using Tangents = typename Material<Dim, Space>::Tangents;
// Per map entry k: the overlap-map index of the first component of node(k) (EntryDofs.hpp).
template <class Space = DefaultExecSpace>
using EntryDofs = Kokkos::View<LO*, typename Space::memory_space>;
// Local values of an overlap vector: (local index, column).  Tpetra's own memory space.
using LocalValues = Kokkos::View<const double**, Kokkos::LayoutLeft, DefaultMemSpace>;
using LocalValuesMutable = Kokkos::View<double**, Kokkos::LayoutLeft, DefaultMemSpace>;

// F from du; `g`, when given (not empty), receives the deformation gradient relative to the
// map's configuration, what the map's gradients differentiate: F itself in total, I + grad du
// in updated Lagrangian (F-bar averages its determinant: assembly/FBar.hpp).
template <int Dim, class Space = DefaultExecSpace>
void trialDeformationGradient(Kinematics kinematics, const ParticleGridMap<Dim, Space>& map,
                              const EntryDofs<Space>& entryDofs, const LocalValues& du,
                              const typename ParticleSet<Dim, Space>::Tensors& Fn,
                              const typename ParticleSet<Dim, Space>::Tensors& F,
                              const typename ParticleSet<Dim, Space>::Tensors& g = {});

// Pn and An, the stress and tangent relative to the step start, from P and A (total
// Lagrangian: copies).  An may be A itself (the push-forward then overwrites A in place, as
// the step does: one tangent per particle held, not two).
template <int Dim, class Space = DefaultExecSpace>
void stressRelativeToStepStart(Kinematics kinematics,
                               const typename ParticleSet<Dim, Space>::Tensors& Fn,
                               const typename ParticleSet<Dim, Space>::Tensors& P,
                               const Tangents<Dim, Space>& A,
                               const typename ParticleSet<Dim, Space>::Tensors& Pn,
                               const Tangents<Dim, Space>& An);

}  // namespace impm
