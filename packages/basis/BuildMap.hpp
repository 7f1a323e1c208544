#pragma once
// Builds the ragged particle-grid map (eq. 1.39-1.40) from any weights.  A weights type says
// which box of grid nodes a particle may touch (nodeBox) and the weights for one node
// (evaluate); entries whose weights vanish are left out, so Y lists exactly the nodes whose
// basis function is non-zero somewhere on the particle's integration domain.

#include <sstream>

#include "basis/ParticleGridMap.hpp"
#include "core/Diagnostics.hpp"
#include "core/Errors.hpp"
#include "core/ParticleSet.hpp"

namespace impm {

// Weights smaller than this (relative to 1 and to 1/h) are round-off, not overlap: a domain
// end that sits on a node up to round-off must not make the next node active.
constexpr double kNegligibleWeight = 1e-14;
// How far (in cells) an integration domain may poke out of the grid through round-off.
constexpr double kGridTolerance = 1e-9;

namespace detail {

// Calls f(node index, node id) for every node of the box [lo, hi] (inclusive).
template <int Dim, class Fn>
KOKKOS_INLINE_FUNCTION void forEachNodeInBox(const GridGeometry<Dim>& grid, const int lo[Dim],
                                             const int hi[Dim], Fn&& f) {
  int idx[Dim];
  for (int d = 0; d < Dim; ++d)
    idx[d] = lo[d];
  while (true) {
    f(idx, grid.nodeId(idx));
    int d = 0;
    while (d < Dim && ++idx[d] > hi[d])
      idx[d] = lo[d], ++d;
    if (d == Dim)
      return;
  }
}

template <int Dim>
KOKKOS_INLINE_FUNCTION bool negligible(const GridGeometry<Dim>& grid, double phi,
                                       const double grad[Dim]) {
  if (phi > kNegligibleWeight || phi < -kNegligibleWeight)
    return false;
  for (int d = 0; d < Dim; ++d) {
    const double g = grad[d] * grid.spacing[d];
    if (g > kNegligibleWeight || g < -kNegligibleWeight)
      return false;
  }
  return true;
}

}  // namespace detail

template <int Dim, class Space, class Weights>
ParticleGridMap<Dim, Space> buildParticleGridMap(const Weights& weights,
                                                 const ParticleSet<Dim, Space>& particles) {
  using Exec = typename Space::execution_space;
  const GridGeometry<Dim> grid = weights.grid;
  const int n = static_cast<int>(particles.size());
  ParticleGridMap<Dim, Space> map;
  map.rowPtr = Kokkos::View<std::size_t*, typename Space::memory_space>("Y rowPtr", n + 1);

  // Count, and find the first particle whose integration domain left the grid.
  auto rowPtr = map.rowPtr;
  int firstOutside = n;
  Kokkos::parallel_reduce(
      "impm::countMapEntries", Kokkos::RangePolicy<Exec>(0, n),
      KOKKOS_LAMBDA(const int p, int& outside) {
        int lo[Dim] = {}, hi[Dim] = {};
        if (!weights.nodeBox(p, lo, hi, kGridTolerance)) {
          if (p < outside)
            outside = p;
          rowPtr(p + 1) = 0;
          return;
        }
        std::size_t count = 0;
        detail::forEachNodeInBox<Dim>(grid, lo, hi, [&](const int* idx, GlobalId) {
          double phi, grad[Dim];
          weights.evaluate(p, lo, idx, phi, grad);
          if (!detail::negligible<Dim>(grid, phi, grad))
            ++count;
        });
        rowPtr(p + 1) = count;
      },
      Kokkos::Min<int>(firstOutside));
  if (firstOutside < n) {
    std::ostringstream msg;
    msg << particleLabel(particles, firstOutside) << " has left the grid [";
    for (int d = 0; d < Dim; ++d)
      msg << (d ? " x [" : "") << grid.origin[d] << ", " << grid.upper(d) << "]";
    throw NumericalError(msg.str() + " (its integration domain reaches outside it)");
  }

  std::size_t total = 0;
  Kokkos::parallel_scan(
      "impm::scanMapEntries", Kokkos::RangePolicy<Exec>(0, n + 1),
      KOKKOS_LAMBDA(const int p, std::size_t& sum, const bool final) {
        const std::size_t count = rowPtr(p);
        sum += count;
        if (final)
          rowPtr(p) = sum;
      },
      total);

  map.node = Kokkos::View<GlobalId*, typename Space::memory_space>("Y node", total);
  map.phi = Kokkos::View<double*, typename Space::memory_space>("Y phi", total);
  map.grad = Kokkos::View<double* [Dim], typename Space::memory_space>("Y grad", total);
  auto node = map.node;
  auto phiView = map.phi;
  auto gradView = map.grad;
  Kokkos::parallel_for(
      "impm::fillMapEntries", Kokkos::RangePolicy<Exec>(0, n), KOKKOS_LAMBDA(const int p) {
        int lo[Dim] = {}, hi[Dim] = {};
        weights.nodeBox(p, lo, hi, kGridTolerance);
        std::size_t k = rowPtr(p);
        detail::forEachNodeInBox<Dim>(grid, lo, hi, [&](const int* idx, GlobalId id) {
          double phi, grad[Dim];
          weights.evaluate(p, lo, idx, phi, grad);
          if (detail::negligible<Dim>(grid, phi, grad))
            return;
          node(k) = id;
          phiView(k) = phi;
          for (int d = 0; d < Dim; ++d)
            gradView(k, d) = grad[d];
          ++k;
        });
      });
  return map;
}

}  // namespace impm
