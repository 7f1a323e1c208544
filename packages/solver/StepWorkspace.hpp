#pragma once
// The per-particle arrays of a step (trial F, P and A, and P, A relative to the start of the
// step), kept from one step to the next.  A and its push-forward An share one array (the
// push-forward is done in place: A is not needed after it), which is 128 bytes a particle in
// 2-D and 648 in 3-D; so do P and Pn when there is no push-forward (total Lagrangian).  They are
// allocated with room to spare and handed out at the step's particle count, so that a step
// allocates nothing the last one had: migration changes the count on a rank by a few particles per
// step.

#include "assembly/Kinematics.hpp"

namespace impm {

template <int Dim>
class StepWorkspace {
 public:
  using Tensors = typename ParticleSet<Dim>::Tensors;
  using Scalars = typename ParticleSet<Dim>::Scalars;

  struct Arrays {
    Tensors F, P, Pn;     // trial F, its first Piola stress, P relative to the step start
    Tangents<Dim> A, An;  // the same array
    // F-bar (assembly/FBar.hpp): g, theta and omega; empty without it.
    Tensors g;
    Scalars theta, omega;
  };

  // The arrays for n particles (their values are those the last step left).  With total-
  // Lagrangian kinematics P relative to the step start is P itself: Pn shares P's array.
  Arrays arrays(std::size_t n, Kinematics kinematics, bool fbar = false);

 private:
  Arrays buffers_;
};

// A view of the first n rows of `buffer`, which grows (by an eighth, so that growth is
// rare) when it holds fewer.  Values are kept only while it does not grow.
template <class View>
View firstRows(View& buffer, const std::string& label, std::size_t n) {
  if (buffer.extent(0) < n)
    buffer = allocateField(label, buffer, n + n / 8 + 16);
  const auto rows = Kokkos::make_pair(std::size_t(0), n);
  if constexpr (View::rank == 1)
    return Kokkos::subview(buffer, rows);
  else if constexpr (View::rank == 2)
    return Kokkos::subview(buffer, rows, Kokkos::ALL());
  else if constexpr (View::rank == 3)
    return Kokkos::subview(buffer, rows, Kokkos::ALL(), Kokkos::ALL());
  else if constexpr (View::rank == 5)
    return Kokkos::subview(buffer, rows, Kokkos::ALL(), Kokkos::ALL(), Kokkos::ALL(),
                           Kokkos::ALL());
  else
    static_assert(View::rank == 1, "firstRows: add the subview of this rank");
}

template <int Dim>
typename StepWorkspace<Dim>::Arrays StepWorkspace<Dim>::arrays(std::size_t n, Kinematics kinematics,
                                                               bool fbar) {
  const auto A = firstRows(buffers_.A, "A, then relative to step start", n);
  const auto P = firstRows(buffers_.P, "P", n);
  const auto Pn = kinematics == Kinematics::totalLagrangian
                      ? P
                      : firstRows(buffers_.Pn, "P relative to step start", n);
  Arrays out{firstRows(buffers_.F, "trial F", n), P, Pn, A, A, {}, {}, {}};
  if (fbar) {
    out.g = firstRows(buffers_.g, "F-bar g", n);
    out.theta = firstRows(buffers_.theta, "F-bar theta", n);
    out.omega = firstRows(buffers_.omega, "F-bar omega", n);
  }
  return out;
}

}  // namespace impm
