#pragma once
// Energies of the particles, summed over all ranks:
//   kinetic   sum_p m_p |v_p|^2 / 2
//   strain    sum_p V_p0 A_p W(F_p, state_p)   (W from the material, per unit reference volume),
//             and likewise the dissipated energy
//   work of the body forces over a step, sum_p force_p . (u_p^new - u_p^old)

#include "core/ParticleSet.hpp"
#include "core/TpetraTypes.hpp"
#include "material/MaterialState.hpp"

namespace impm {

template <int Dim, class Space = DefaultExecSpace>
double kineticEnergy(const ParticleSet<Dim, Space>& particles, const Comm& comm);

struct MaterialEnergies {
  double strain = 0.0;      // sum_p V_p0 A_p W(F_p, state_p)
  double dissipated = 0.0;  // energy dissipated since the start (plastic work not stored)
};

// 1/2 v^T M v with a lumped (diagonal) M given as a vector: the grid's kinetic energy.
double lumpedKineticEnergy(const Vector& mass, const Vector& v);

// Both sums in one pass.  W and D are scratch arrays of at least the particle count (the
// stepper keeps them from step to step: allocating them cost more than the sums).
template <int Dim>
MaterialEnergies materialEnergies(const ParticleSet<Dim>& particles,
                                  const Materials<Dim>& materials, const Comm& comm,
                                  const typename ParticleSet<Dim>::Scalars& W,
                                  const typename ParticleSet<Dim>::Scalars& D);

// True when a particle on this rank carries an external force (loads are applied).
template <int Dim, class Space = DefaultExecSpace>
bool carriesForces(const ParticleSet<Dim, Space>& particles);

// The body forces' work over a step, sum_p force_p . (u_p^new - u_p^old), summed over all
// ranks (times scale).  loaded = false: this rank's particles carry no force and add 0
// (uBefore is not read).  Collective.
template <int Dim, class Space = DefaultExecSpace>
double bodyForceWork(const ParticleSet<Dim, Space>& particles,
                     const typename ParticleSet<Dim, Space>::Vectors& uBefore, bool loaded,
                     double scale, const Comm& comm);

}  // namespace impm
