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

std::vector<Seed<2>> SubCellShape::fill(const GridGeometry<2>& g, int perCell, bool gauss) const {
  return subCellFill(*this, g, perCell, gauss);
}

std::vector<Seed<2>> subCellFill(const Shape<2>& shape, const GridGeometry<2>& g, int perCell,
                                 bool gauss) {
  const auto& lower = shape.lower();
  const auto& upper = shape.upper();
  const auto contains = [&](const double* x) { return shape.contains(x); };
  const int n = gauss ? 2 : perCell;
  int lo[2], hi[2];
  for (int d = 0; d < 2; ++d) {
    lo[d] = std::max(0, static_cast<int>(std::floor(g.gridCoord(d, lower[d]))));
    hi[d] = std::min(g.cells[d], static_cast<int>(std::ceil(g.gridCoord(d, upper[d]))));
  }
  const double hx = g.spacing[0], hy = g.spacing[1];
  const double off = 0.5 / std::sqrt(3.0);  // Gauss points at +-1/sqrt(3) of the half-cell
  std::vector<Seed<2>> seeds;
  for (int j = lo[1]; j < hi[1]; ++j)
    for (int i = lo[0]; i < hi[0]; ++i) {
      const double centre[2] = {g.nodeCoord(0, i) + hx / 2, g.nodeCoord(1, j) + hy / 2};
      if (gauss && !contains(centre))
        continue;
      for (int s = 0; s < n; ++s)
        for (int r = 0; r < n; ++r) {
          Seed<2> seed{};
          seed.x[0] =
              gauss ? centre[0] + (r ? off : -off) * hx : g.nodeCoord(0, i) + (r + 0.5) * hx / n;
          seed.x[1] =
              gauss ? centre[1] + (s ? off : -off) * hy : g.nodeCoord(1, j) + (s + 0.5) * hy / n;
          if (!gauss && !contains(seed.x))
            continue;
          seed.half[0][0] = hx / (2 * n), seed.half[1][1] = hy / (2 * n);
          seed.volume = hx * hy / (n * n);
          seeds.push_back(seed);
        }
    }
  return seeds;
}

template class Shape<1>;
template class Shape<2>;

}  // namespace impm
