#pragma once
// Energies of the particles, summed over all ranks:
//   kinetic   sum_p m_p |v_p|^2 / 2
//   strain    sum_p V_p0 A_p W(F_p)   (W from the material, per unit reference volume)
//   work of the body forces over a step, sum_p force_p . (u_p^new - u_p^old)

#include <memory>
#include <vector>

#include "core/ParticleSet.hpp"
#include "core/TpetraTypes.hpp"
#include "material/Material.hpp"

namespace impm {

template <int Dim>
double kineticEnergy(const ParticleSet<Dim>& particles, const Comm& comm);

template <int Dim>
double strainEnergy(const ParticleSet<Dim>& particles,
                    const std::vector<std::shared_ptr<Material<Dim>>>& materials, const Comm& comm);

template <int Dim>
double bodyForceWork(const ParticleSet<Dim>& particles,
                     const typename ParticleSet<Dim>::Vectors& uBefore, double scale,
                     const Comm& comm);

}  // namespace impm
