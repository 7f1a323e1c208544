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

#include "basis/ParticleGridMap.hpp"
#include "core/ParticleSet.hpp"
#include "core/TpetraTypes.hpp"
#include "material/Material.hpp"

namespace impm {

enum class Kinematics { totalLagrangian, updatedLagrangian };

template <int Dim>
using Tangents = typename Material<Dim>::Tangents;
// Local values of an overlap vector: (local index, column).
using LocalValues = Kokkos::View<const double**, Kokkos::LayoutLeft, DefaultMemSpace>;
using LocalValuesMutable = Kokkos::View<double**, Kokkos::LayoutLeft, DefaultMemSpace>;

template <int Dim>
void trialDeformationGradient(Kinematics kinematics, const ParticleGridMap<Dim>& map,
                              const Kokkos::View<LO*>& entryDofs, const LocalValues& du,
                              const typename ParticleSet<Dim>::Tensors& Fn,
                              typename ParticleSet<Dim>::Tensors& F);

template <int Dim>
void stressRelativeToStepStart(Kinematics kinematics, const typename ParticleSet<Dim>::Tensors& Fn,
                               const typename ParticleSet<Dim>::Tensors& P, const Tangents<Dim>& A,
                               typename ParticleSet<Dim>::Tensors& Pn, Tangents<Dim>& An);

// Determinant of the Dim x Dim matrix of particle p.
template <int Dim>
KOKKOS_INLINE_FUNCTION double determinant(const typename ParticleSet<Dim>::Tensors& F, int p) {
  if constexpr (Dim == 1)
    return F(p, 0, 0);
  else
    return F(p, 0, 0) * F(p, 1, 1) - F(p, 0, 1) * F(p, 1, 0);
}

}  // namespace impm
