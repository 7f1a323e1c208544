#pragma once
// Energies of the particles, summed over all ranks:
//   kinetic   sum_p m_p |v_p|^2 / 2
//   strain    sum_p V_p0 A_p W(F_p, state_p)   (W from the material, per unit reference volume)
//   work of the body forces over a step, sum_p force_p . (u_p^new - u_p^old)

#include "core/ParticleSet.hpp"
#include "core/TpetraTypes.hpp"
#include "material/MaterialState.hpp"

namespace impm {

template <int Dim, class Space = DefaultExecSpace>
double kineticEnergy(const ParticleSet<Dim, Space>& particles, const Comm& comm);

template <int Dim>
double strainEnergy(const ParticleSet<Dim>& particles, const Materials<Dim>& materials,
                    const Comm& comm);

// Energy the materials have dissipated since the start (plastic work not stored).
template <int Dim>
double dissipatedEnergy(const ParticleSet<Dim>& particles, const Materials<Dim>& materials,
                        const Comm& comm);

template <int Dim, class Space = DefaultExecSpace>
double bodyForceWork(const ParticleSet<Dim, Space>& particles,
                     const typename ParticleSet<Dim, Space>::Vectors& uBefore, double scale,
                     const Comm& comm);

}  // namespace impm
