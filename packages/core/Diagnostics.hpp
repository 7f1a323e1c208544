#pragma once
// What numerical-failure messages need: the first particle or unknown whose values are not
// finite, and how to name a particle or a grid node to a user ("particle 12 at x = (0.5,
// 0.25)", "grid node 7 at x = (1, 0.5)").

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <sstream>
#include <string>

#include "core/Grid.hpp"
#include "core/ParticleSet.hpp"

namespace impm {

// True for NaN and +-inf.  (x - x is 0 for every finite x and NaN otherwise; unlike
// std::isfinite it is available in device kernels.)
KOKKOS_INLINE_FUNCTION bool notFinite(double x) {
  return !(x - x == 0.0);
}

// 1 for NaN and +-inf, 0 otherwise, from the exponent's bits: all ones, 2047, exactly when
// 2047 + 1 reaches bit 11.  Shifts, masks and adds on 64-bit integers, which a loop over many
// values vectorizes (with SSE2 alone), where a comparison of doubles does not.
KOKKOS_INLINE_FUNCTION std::uint64_t nonFiniteCount(double x) {
  std::uint64_t bits;
  memcpy(&bits, &x, sizeof bits);
  return (((bits >> 52) & 0x7ff) + 1) >> 11;
}

// The smallest row index below `rows` of a rank 1, 2, 3 or 5 view (scalars, vectors, tensors,
// tangents per particle) with an entry that is NaN or infinite, or -1 when there is none.
//
// Checked every step on every particle, so the common case is a branch-free count over the
// view's whole allocation (it vectorizes); the search by rows runs only when that count finds
// something, which may lie in the rows at or past `rows` that the view keeps in reserve.
template <class View>
long firstNonFiniteRow(const View& v, std::size_t rows) {
  using Exec = typename View::execution_space;
  static_assert(View::rank <= 3 || View::rank == 5, "firstNonFiniteRow: a view of rank 1-3 or 5");
  if (v.span_is_contiguous()) {
    const auto* data = v.data();
    std::uint64_t count = 0;
    Kokkos::parallel_reduce(
        "impm::countNonFinite", Kokkos::RangePolicy<Exec>(0, v.span()),
        KOKKOS_LAMBDA(const std::size_t i, std::uint64_t& n) { n += nonFiniteCount(data[i]); },
        count);
    if (count == 0)
      return -1;
  }
  long first = static_cast<long>(rows);
  Kokkos::parallel_reduce(
      "impm::firstNonFiniteRow", Kokkos::RangePolicy<Exec>(0, rows),
      KOKKOS_LAMBDA(const std::size_t p, long& m) {
        bool bad = false;
        if constexpr (View::rank == 1) {
          bad = notFinite(v(p));
        } else if constexpr (View::rank == 2) {
          for (std::size_t i = 0; i < v.extent(1); ++i)
            bad = bad || notFinite(v(p, i));
        } else if constexpr (View::rank == 3) {
          for (std::size_t i = 0; i < v.extent(1); ++i)
            for (std::size_t j = 0; j < v.extent(2); ++j)
              bad = bad || notFinite(v(p, i, j));
        } else {
          for (std::size_t i = 0; i < v.extent(1); ++i)
            for (std::size_t j = 0; j < v.extent(2); ++j)
              for (std::size_t k = 0; k < v.extent(3); ++k)
                for (std::size_t l = 0; l < v.extent(4); ++l)
                  bad = bad || notFinite(v(p, i, j, k, l));
        }
        if (bad && static_cast<long>(p) < m)
          m = static_cast<long>(p);
      },
      Kokkos::Min<long>(first));
  return first < static_cast<long>(rows) ? first : -1;
}

// "particle <id> at x = (x, y)": its id and current position (copied to the host: for
// messages, not for loops).
template <int Dim, class Space>
std::string particleLabel(const ParticleSet<Dim, Space>& particles, std::size_t p) {
  const auto rows = Kokkos::make_pair(p, p + 1);
  auto x = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(),
                                               Kokkos::subview(particles.x, rows, Kokkos::ALL()));
  auto id =
      Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), Kokkos::subview(particles.id, rows));
  std::ostringstream s;
  s << "particle " << id(0) << " at x = (";
  for (int d = 0; d < Dim; ++d)
    s << (d ? ", " : "") << x(0, d);
  s << ")";
  return s.str();
}

// "grid node <id> at x = (x, y)".
template <int Dim>
std::string nodeLabel(const GridGeometry<Dim>& grid, GlobalId node) {
  int idx[Dim];
  grid.nodeIndex(node, idx);
  std::ostringstream s;
  s << "grid node " << node << " at x = (";
  for (int d = 0; d < Dim; ++d)
    s << (d ? ", " : "") << grid.nodeCoord(d, idx[d]);
  s << ")";
  return s.str();
}

}  // namespace impm
