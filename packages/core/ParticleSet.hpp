#pragma once
// The material points.  Every field a particle carries lives here, in one Kokkos view per
// field, indexed by the local particle index p.  Particles carry the whole state of the
// body (primer 1.6.2): positions, velocity, deformation gradient, stress, volume, mass and
// the particle domain; the grid carries nothing between steps.
//
// In 1-D, `volume` is the particle length (the primer's V_p) and `section` the bar's cross
// section A(x_p), so that the particle's true volume is section * volume.  In 2-D, `volume`
// is the area and `section` the out-of-plane thickness (1: plane strain, per unit depth).

#include <string>

#include "core/Types.hpp"

namespace impm {

// Number of per-particle material parameters (E(x_p), ...) a material may store.
constexpr int kMaxMaterialProps = 4;

template <int Dim, class Space = DefaultExecSpace>
struct ParticleSet {
  using memory_space = typename Space::memory_space;
  using Scalars = Kokkos::View<double*, memory_space>;
  using Vectors = Kokkos::View<double* [Dim], memory_space>;
  using Tensors = Kokkos::View<double* [Dim][Dim], memory_space>;

  Kokkos::View<GlobalId*, memory_space> id;   // global, stable, used to sort output
  Kokkos::View<int*, memory_space> body;      // index of the body in the deck
  Kokkos::View<int*, memory_space> material;  // index of the material in the deck

  Vectors X;      // reference position X_p
  Vectors x;      // current position x_p
  Vectors u;      // displacement u_p (eq. 1.23 maps it from the grid)
  Vectors v;      // velocity
  Vectors a;      // acceleration
  Vectors force;  // external force on the particle (body force times its volume)

  Scalars mass;
  Scalars volume;   // current V_p
  Scalars volume0;  // reference V_p
  Scalars section;  // 1-D cross-section A(x_p); 2-D thickness

  Tensors F;         // deformation gradient
  Tensors stress;    // Cauchy stress (1-D: axial force per unit section)
  Scalars stressZZ;  // 2-D plane strain: out-of-plane Cauchy stress (output only)
  Tensors domain;    // particle domain: column k is the half-vector r_k (1-D: half length)
  Tensors domain0;   // reference particle domain

  Kokkos::View<double* [kMaxMaterialProps], memory_space> props;  // material parameters at X_p

  ParticleSet() = default;
  explicit ParticleSet(std::size_t n) { resize(n); }

  std::size_t size() const { return id.extent(0); }

  // Calls f(view) for every field, so that resizing, packing for migration and gathering
  // for output cannot forget one.
  template <class Fn>
  void forEachField(Fn&& f) {
    f(id), f(body), f(material), f(X), f(x), f(u), f(v), f(a), f(force), f(mass), f(volume),
        f(volume0), f(section), f(F), f(stress), f(stressZZ), f(domain), f(domain0), f(props);
  }

  // Keeps existing entries; new entries are zero.
  void resize(std::size_t n) {
    forEachField([n](auto& view) {
      using V = std::decay_t<decltype(view)>;
      if (view.data() == nullptr)
        view = V("particle field", n);
      else
        Kokkos::resize(view, n);
    });
  }
};

}  // namespace impm
