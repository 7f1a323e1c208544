#pragma once
// Builds the ragged particle-grid map (eq. 1.39-1.40) from any weights.  A weights type says
// which box of grid nodes a particle may touch (nodeBox, which also fills the type's
// Particle: what every node's weights read of the particle, its domain's ends or corners,
// computed once per particle) and the weights for one node (evaluate); entries whose weights
// vanish are left out, so Y lists exactly the nodes whose basis function is non-zero
// somewhere on the particle's integration domain.

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

namespace detail {

// NumericalError naming the first particle whose integration domain left the grid.
template <int Dim, class Space>
void throwLeftTheGrid(const GridGeometry<Dim>& grid, const ParticleSet<Dim, Space>& particles,
                      int p) {
  std::ostringstream msg;
  msg << particleLabel(particles, p) << " has left the grid [";
  for (int d = 0; d < Dim; ++d)
    msg << (d ? " x [" : "") << grid.origin[d] << ", " << grid.upper(d) << "]";
  throw NumericalError(msg.str() + " (its integration domain reaches outside it)");
}

// rowPtr(p) becomes the sum of rowPtr(0 .. p-1) (the counts are at p + 1); returns the total.
template <class Exec, class View>
std::size_t exclusiveSum(const View& rowPtr, int n) {
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
  return total;
}

// The map whose particle p has counts(p + 1) entries at the start of its row of `box`: the
// same entries with the rows next to one another.
template <int Dim, class Space>
ParticleGridMap<Dim, Space> compacted(
    const ParticleGridMap<Dim, Space>& box,
    const Kokkos::View<std::size_t*, typename Space::memory_space>& counts, std::size_t total) {
  using Exec = typename Space::execution_space;
  using Memory = typename Space::memory_space;
  const int n = static_cast<int>(box.numParticles());
  exclusiveSum<Exec>(counts, n);
  ParticleGridMap<Dim, Space> map;
  map.rowPtr = counts;
  map.node =
      Kokkos::View<GlobalId*, Memory>(Kokkos::ViewAllocateWithoutInitializing("Y node"), total);
  map.phi = Kokkos::View<double*, Memory>(Kokkos::ViewAllocateWithoutInitializing("Y phi"), total);
  map.grad =
      Kokkos::View<double* [Dim], Memory>(Kokkos::ViewAllocateWithoutInitializing("Y grad"), total);
  Kokkos::parallel_for(
      "impm::compactMapEntries", Kokkos::RangePolicy<Exec>(0, n), KOKKOS_LAMBDA(const int p) {
        for (std::size_t k = map.rowPtr(p), from = box.rowPtr(p); k < map.rowPtr(p + 1);
             ++k, ++from) {
          map.node(k) = box.node(from);
          map.phi(k) = box.phi(from);
          for (int d = 0; d < Dim; ++d)
            map.grad(k, d) = box.grad(from, d);
        }
      });
  return map;
}

}  // namespace detail

// The weights are evaluated once: each particle's entries are written at the place its
// node box reserves (the box's node count, an upper bound), and only when some weight was
// negligible are the entries moved together (rare: a domain end on a node up to round-off,
// a CPDI domain whose corners miss a corner of their box).
template <int Dim, class Space, class Weights>
ParticleGridMap<Dim, Space> buildParticleGridMap(const Weights& weights,
                                                 const ParticleSet<Dim, Space>& particles) {
  using Exec = typename Space::execution_space;
  using Memory = typename Space::memory_space;
  const GridGeometry<Dim> grid = weights.grid;
  const int n = static_cast<int>(particles.size());

  // The nodes of each particle's box, and the first particle whose domain left the grid.
  Kokkos::View<std::size_t*, Memory> boxPtr("Y box rowPtr", n + 1);
  int firstOutside = n;
  Kokkos::parallel_reduce(
      "impm::countBoxNodes", Kokkos::RangePolicy<Exec>(0, n),
      KOKKOS_LAMBDA(const int p, int& outside) {
        int lo[Dim] = {}, hi[Dim] = {};
        typename Weights::Particle at{};
        if (!weights.nodeBox(p, at, lo, hi, kGridTolerance)) {
          if (p < outside)
            outside = p;
          boxPtr(p + 1) = 0;
          return;
        }
        std::size_t count = 1;
        for (int d = 0; d < Dim; ++d)
          count *= static_cast<std::size_t>(hi[d] - lo[d] + 1);
        boxPtr(p + 1) = count;
      },
      Kokkos::Min<int>(firstOutside));
  if (firstOutside < n)
    detail::throwLeftTheGrid(grid, particles, firstOutside);
  const std::size_t capacity = detail::exclusiveSum<Exec>(boxPtr, n);

  // The entries, at their boxes' places; counts(p + 1): how many particle p has.
  ParticleGridMap<Dim, Space> box;
  box.rowPtr = boxPtr;
  box.node =
      Kokkos::View<GlobalId*, Memory>(Kokkos::ViewAllocateWithoutInitializing("Y node"), capacity);
  box.phi =
      Kokkos::View<double*, Memory>(Kokkos::ViewAllocateWithoutInitializing("Y phi"), capacity);
  box.grad = Kokkos::View<double* [Dim], Memory>(Kokkos::ViewAllocateWithoutInitializing("Y grad"),
                                                 capacity);
  Kokkos::View<std::size_t*, Memory> counts("Y rowPtr", n + 1);
  auto node = box.node;
  auto phiView = box.phi;
  auto gradView = box.grad;
  std::size_t total = 0;
  Kokkos::parallel_reduce(
      "impm::fillMapEntries", Kokkos::RangePolicy<Exec>(0, n),
      KOKKOS_LAMBDA(const int p, std::size_t& sum) {
        int lo[Dim] = {}, hi[Dim] = {};
        typename Weights::Particle at{};
        weights.nodeBox(p, at, lo, hi, kGridTolerance);
        std::size_t k = boxPtr(p);
        detail::forEachNodeInBox<Dim>(grid, lo, hi, [&](const int* idx, GlobalId id) {
          double phi = 0.0, grad[Dim] = {};
          weights.evaluate(at, lo, idx, phi, grad);
          if (detail::negligible<Dim>(grid, phi, grad))
            return;
          node(k) = id;
          phiView(k) = phi;
          for (int d = 0; d < Dim; ++d)
            gradView(k, d) = grad[d];
          ++k;
        });
        counts(p + 1) = k - boxPtr(p);
        sum += k - boxPtr(p);
      },
      total);
  if (total == capacity)
    return box;
  return detail::compacted(box, counts, total);
}

}  // namespace impm
