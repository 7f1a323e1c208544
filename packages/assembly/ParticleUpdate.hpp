#pragma once
// Grid to particles after a converged step, in two parts that a stepper may run apart:
//   displaceParticles: the displacement increment mapped with u_p = sum_i phi_ip u_i
//     (eq. 1.23): u_p += sum_i phi_ip du_i, x_p += sum_i phi_ip du_i;
//   commitDeformation: F_p = trial F, stress = P F^T / J (Cauchy; in 1-D the axial force
//     per unit section); with updated-Lagrangian kinematics the domains follow the
//     deformation, domain = F domain0 (eq. 1.36 CPDI vectors), and so does the volume,
//     V_p = J V_p0.  (With total-Lagrangian kinematics the map is built at X_p, the
//     reference domains and volumes; domain is then what the output draws, made by
//     followDeformation before an output needs it.)
// Nothing in a step reads u_p or x_p on a fixed grid, where F comes from the grid's
// increments at the reference positions: there the displacement may wait for the step
// whose outputs read it (solver/DynamicStepper), the deformation may not (the next step
// starts from F and the laws' committed state).

#include "assembly/Kinematics.hpp"

namespace impm {

template <int Dim, class Space = DefaultExecSpace>
void displaceParticles(const ParticleGridMap<Dim, Space>& map, const EntryDofs<Space>& entryDofs,
                       const LocalValues& du, const ParticleSet<Dim, Space>& particles);

template <int Dim, class Space = DefaultExecSpace>
void commitDeformation(Kinematics kinematics, const typename ParticleSet<Dim, Space>::Tensors& F,
                       const typename ParticleSet<Dim, Space>::Tensors& P,
                       const ParticleSet<Dim, Space>& particles);

// domain = F domain0 for every particle.
template <int Dim, class Space = DefaultExecSpace>
void followDeformation(const ParticleSet<Dim, Space>& particles);

// domain_p = F_p domain0_p.
template <int Dim, class Tensors>
KOKKOS_INLINE_FUNCTION void deformedDomain(const Tensors& F, const Tensors& domain0,
                                           const Tensors& domain, int p) {
  for (int a = 0; a < Dim; ++a)
    for (int k = 0; k < Dim; ++k) {
      double s = 0;
      for (int c = 0; c < Dim; ++c)
        s += F(p, a, c) * domain0(p, c, k);
      domain(p, a, k) = s;
    }
}

}  // namespace impm
