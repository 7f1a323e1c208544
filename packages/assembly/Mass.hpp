#pragma once
// Mass and the transfers between particles and grid (primer 1.2.1, 1.5.3), as kernels over
// particles with atomic updates of overlap-local arrays:
//   lumped mass        m_i = sum_p m_p phi_ip                           (eq. 1.49, 1.72)
//   consistent mass    M_ij = sum_p m_p phi_ip phi_jp                   (eq. 1.48, 1.71)
//   particle to grid   q_i = sum_p m_p phi_ip q_p  (momentum m v, or m a)
//   inertia force      (M a)_i, with a the grid acceleration: consistent
//                      sum_p m_p phi_ip (sum_j phi_jp a_j); the lumped m_i a_i is a pass over
//                      the grid once m_i is known (solver/GridSystem)

#include "assembly/Forces.hpp"

namespace impm {

enum class MassType { lumped, consistent };

// f(i, d) += sum_p m_p phi_ip q_p,d for every component d.
template <int Dim, class Space = DefaultExecSpace>
void particleToGrid(const ParticleGridMap<Dim, Space>& map, const EntryDofs<Space>& entryDofs,
                    const typename ParticleSet<Dim, Space>::Scalars& mass,
                    const typename ParticleSet<Dim, Space>::Vectors& q,
                    const LocalValuesMutable& f);

// m_i for every component (the lumped mass, and the row sums of the consistent mass).
template <int Dim, class Space = DefaultExecSpace>
void addLumpedMass(const ParticleGridMap<Dim, Space>& map, const EntryDofs<Space>& entryDofs,
                   const typename ParticleSet<Dim, Space>::Scalars& mass,
                   const LocalValuesMutable& m);

// f += M a with the consistent mass (a: grid accelerations, overlap-local).
template <int Dim, class Space = DefaultExecSpace>
void addConsistentInertiaForce(const ParticleGridMap<Dim, Space>& map,
                               const EntryDofs<Space>& entryDofs,
                               const typename ParticleSet<Dim, Space>::Scalars& mass,
                               const LocalValues& a, const LocalValuesMutable& f);

// K += scale M with the consistent mass (rows and columns: overlap-map indices, as in
// addTangent).
template <int Dim, class Space = DefaultExecSpace>
void addConsistentMassMatrix(double scale, const ParticleGridMap<Dim, Space>& map,
                             const EntryDofs<Space>& entryDofs,
                             const typename ParticleSet<Dim, Space>::Scalars& mass,
                             const LocalMatrix& K);

// K_ii += scale d_i for the rows of d (local indices; rows with d_i = 0 are left alone, so
// that rows without mass keep their pattern's values): the lumped mass matrix from m_i.
template <class Space = DefaultExecSpace>
void addDiagonal(double scale, const LocalValues& d, const LocalMatrix& K);

// Particle velocities and accelerations from the grid after a step:
//   FLIP v_p += sum_i phi_ip (v_i^new - v_i^old),  PIC v_p = sum_i phi_ip v_i^new,
//   v_p = flip * FLIP + (1 - flip) * PIC,  a_p = sum_i phi_ip a_i^new.
template <int Dim, class Space = DefaultExecSpace>
void gridToParticleVelocity(const ParticleGridMap<Dim, Space>& map,
                            const EntryDofs<Space>& entryDofs, const LocalValues& vOld,
                            const LocalValues& vNew, const LocalValues& aNew, double flip,
                            const ParticleSet<Dim, Space>& particles);

}  // namespace impm
