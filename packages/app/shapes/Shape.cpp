#include "app/shapes/Shape.hpp"

#include <algorithm>
#include <cmath>

namespace impm {

template <int Dim>
double Shape<Dim>::boxDistance(const double* x) const {
  double s = 0.0;
  for (int d = 0; d < Dim; ++d) {
    const double out = std::max({lower_[d] - x[d], x[d] - upper_[d], 0.0});
    s += out * out;
  }
  return std::sqrt(s);
}

namespace {

// Calls f(idx) for every index with lo[d] <= idx[d] < hi[d], x fastest (a rank-independent
// order).
template <int Dim, class Fn>
void forEachIndex(const int lo[Dim], const int hi[Dim], Fn&& f) {
  for (int d = 0; d < Dim; ++d)
    if (lo[d] >= hi[d])
      return;
  int idx[Dim];
  std::copy(lo, lo + Dim, idx);
  while (true) {
    f(idx);
    int d = 0;
    while (d < Dim && ++idx[d] == hi[d])
      idx[d] = lo[d], ++d;
    if (d == Dim)
      return;
  }
}

}  // namespace

template <int Dim>
std::vector<Seed<Dim>> subCellFill(const Shape<Dim>& shape, const GridGeometry<Dim>& g, int perCell,
                                   bool gauss) {
  const auto& lower = shape.lower();
  const auto& upper = shape.upper();
  const int n = gauss ? 2 : perCell;
  int lo[Dim], hi[Dim], first[Dim] = {}, last[Dim];
  double volume = 1.0;
  for (int d = 0; d < Dim; ++d) {
    lo[d] = std::max(0, static_cast<int>(std::floor(g.gridCoord(d, lower[d]))));
    hi[d] = std::min(g.cells[d], static_cast<int>(std::ceil(g.gridCoord(d, upper[d]))));
    last[d] = n;
    volume *= g.spacing[d] / n;
  }
  const double off = 0.5 / std::sqrt(3.0);  // Gauss points at +-1/sqrt(3) of the half-cell
  std::vector<Seed<Dim>> seeds;
  forEachIndex<Dim>(lo, hi, [&](const int* cell) {
    double centre[Dim];
    for (int d = 0; d < Dim; ++d)
      centre[d] = g.nodeCoord(d, cell[d]) + 0.5 * g.spacing[d];
    if (gauss && !shape.contains(centre))
      return;
    forEachIndex<Dim>(first, last, [&](const int* sub) {
      Seed<Dim> seed{};
      for (int d = 0; d < Dim; ++d) {
        const double h = g.spacing[d];
        seed.x[d] = gauss ? centre[d] + (sub[d] ? off : -off) * h
                          : g.nodeCoord(d, cell[d]) + (sub[d] + 0.5) * h / n;
        seed.half[d][d] = h / (2 * n);
      }
      if (!gauss && !shape.contains(seed.x))
        return;
      seed.volume = volume;
      seeds.push_back(seed);
    });
  });
  return seeds;
}

template std::vector<Seed<2>> subCellFill<2>(const Shape<2>&, const GridGeometry<2>&, int, bool);
template std::vector<Seed<3>> subCellFill<3>(const Shape<3>&, const GridGeometry<3>&, int, bool);
template class Shape<1>;
template class Shape<2>;
template class Shape<3>;

}  // namespace impm
