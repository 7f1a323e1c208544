#pragma once
// Grid to particles after a converged step: the displacement increment is mapped with
// u_p = sum_i phi_ip u_i (eq. 1.23) and the particle state is advanced:
//   u_p += sum_i phi_ip du_i,  x_p += sum_i phi_ip du_i,  F_p = trial F,
//   stress = P F^T / J (Cauchy; in 1-D the axial force per unit section);
// the domains follow the deformation, domain = F domain0 (eq. 1.36 CPDI vectors), and with
// updated-Lagrangian kinematics so does the volume, V_p = J V_p0.  (With total-Lagrangian
// kinematics the map is built at X_p, the reference domains and volumes; domain is then
// what the output draws.)

#include "assembly/Kinematics.hpp"

namespace impm {

template <int Dim, class Space = DefaultExecSpace>
void updateParticles(Kinematics kinematics, const ParticleGridMap<Dim, Space>& map,
                     const EntryDofs<Space>& entryDofs, const LocalValues& du,
                     const typename ParticleSet<Dim, Space>::Tensors& F,
                     const typename ParticleSet<Dim, Space>::Tensors& P,
                     const ParticleSet<Dim, Space>& particles);

}  // namespace impm
