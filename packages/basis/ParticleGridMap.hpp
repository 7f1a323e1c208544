#pragma once
// The particle-grid map: the primer's ragged array Y (eq. 1.39-1.40) with, for each entry,
// the weight phi_ip (the average of N_i over the particle's integration domain, eq. 1.38)
// and the gradient weight G_ip (the average of grad N_i).  Stored as CSR: the nodes of
// particle p are node(k) for rowPtr(p) <= k < rowPtr(p+1).
//
// This map is the only thing that distinguishes FEM, classic MPM, GIMP and CPDI: mass,
// forces, stiffness and the grid-to-particle mapping u_p = sum_i phi_ip u_i (eq. 1.23)
// read nothing else.

#include "core/Types.hpp"

namespace impm {

template <int Dim, class Space = DefaultExecSpace>
struct ParticleGridMap {
  using memory_space = typename Space::memory_space;

  Kokkos::View<std::size_t*, memory_space> rowPtr;  // numParticles + 1
  Kokkos::View<GlobalId*, memory_space> node;       // grid node ids, one per entry
  Kokkos::View<double*, memory_space> phi;          // phi_ip
  Kokkos::View<double* [Dim], memory_space> grad;   // G_ip

  std::size_t numParticles() const { return rowPtr.extent(0) ? rowPtr.extent(0) - 1 : 0; }
  std::size_t numEntries() const { return node.extent(0); }
};

}  // namespace impm
