#pragma once
// Sums over particles into the grid system, as Kokkos kernels with atomic updates of the
// overlap (owned + shared) local arrays; Tpetra's FE objects then export shared rows.
//
//  internal force   f_ia += w_p sum_b P^n_ab G_ipb            (eq. 1.63; 1.34/1.37 when linear)
//  external force   f_ia -= s phi_ip force_pa                 (eq. 1.35/1.38, force = f V_p)
//  tangent          K_ia,jc += w_p sum_bd G_ipb A^n_abcd G_jpd (eq. 1.16, 1.34, 1.37)
// with w_p = section_p V_p the particle's volume.  The residual of the grid system is
// f_int - f_ext - boundary forces, whose Jacobian is K.

#include "assembly/Kinematics.hpp"

namespace impm {

using LocalMatrix = FECrsMatrix::local_matrix_device_type;

template <int Dim, class Space = DefaultExecSpace>
void addInternalForce(const ParticleGridMap<Dim, Space>& map, const EntryDofs<Space>& entryDofs,
                      const ParticleSet<Dim, Space>& particles,
                      const typename ParticleSet<Dim, Space>::Tensors& Pn,
                      const LocalValuesMutable& f);

template <int Dim, class Space = DefaultExecSpace>
void addExternalForce(const ParticleGridMap<Dim, Space>& map, const EntryDofs<Space>& entryDofs,
                      const typename ParticleSet<Dim, Space>::Vectors& force, double scale,
                      const LocalValuesMutable& f);

// Rows and columns are overlap-map indices (the column map begins with the overlap map).
// `scale`, when given (not empty), multiplies each particle's term (F-bar's theta_p).
template <int Dim, class Space = DefaultExecSpace>
void addTangent(const ParticleGridMap<Dim, Space>& map, const EntryDofs<Space>& entryDofs,
                const ParticleSet<Dim, Space>& particles, const Tangents<Dim, Space>& An,
                const LocalMatrix& K, const typename ParticleSet<Dim, Space>::Scalars& scale = {});

// s_ia += w_p sum_B |G_ipB| sum_cD |An_aBcD| |g_cD|: how far the internal force moves, per
// unit relative rounding, when the laws see g rounded to doubles (g: the deformation gradient
// relative to the map's configuration; empty: the identity, the updated-Lagrangian step's to
// round-off).  The residual's round-off floor from the stress: a stiff law at a small strain
// (lambda eps for F - I near I) puts it far above eps |K| |du| (solver/RoundOffTest.hpp).
template <int Dim, class Space = DefaultExecSpace>
void addStressRoundOffScale(const ParticleGridMap<Dim, Space>& map,
                            const EntryDofs<Space>& entryDofs,
                            const ParticleSet<Dim, Space>& particles,
                            const Tangents<Dim, Space>& An,
                            const typename ParticleSet<Dim, Space>::Tensors& g,
                            const LocalValuesMutable& s);

}  // namespace impm
