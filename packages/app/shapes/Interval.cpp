#include "app/shapes/Interval.hpp"

#include <algorithm>
#include <cmath>

#include "core/Errors.hpp"
#include "core/Parameters.hpp"

namespace impm {

void Interval::declareParameters(Teuchos::ParameterList& valid) {
  declareDoubleArray(valid, "Extent", {0.0, 1.0}, {2},
                     "1-D: the body occupies [Extent[0], Extent[1]]", Bounds::any(), true);
}

Interval::Interval(const Teuchos::ParameterList& params, const std::string& path) {
  const auto& e = params.get<Teuchos::Array<double>>("Extent");
  lower_[0] = e[0], upper_[0] = e[1];
  if (!(e[0] < e[1]))
    throw InputError(path + "/Extent", "the lower end must be below the upper end");
}

std::vector<Seed<1>> Interval::fill(const GridGeometry<1>& g, int perCell, bool gauss) const {
  const double a = lower_[0], b = upper_[0], h = g.spacing[0];
  std::vector<Seed<1>> seeds;
  const auto add = [&](double x, double length) {
    Seed<1> s{};
    s.x[0] = x, s.half[0][0] = length / 2, s.volume = length;
    seeds.push_back(s);
  };
  if (!gauss) {
    const int n = std::max(1, static_cast<int>(std::lround(perCell * (b - a) / h)));
    const double length = (b - a) / n;
    for (int k = 0; k < n; ++k)
      add(a + (k + 0.5) * length, length);
    return seeds;
  }
  for (int c = 0; c < g.cells[0]; ++c) {
    const double lo = std::max(a, g.nodeCoord(0, c)), hi = std::min(b, g.nodeCoord(0, c + 1));
    if (hi - lo <= 1e-12 * h)
      continue;
    const double mid = 0.5 * (lo + hi), off = (hi - lo) / (2 * std::sqrt(3.0));
    add(mid - off, (hi - lo) / 2);
    add(mid + off, (hi - lo) / 2);
  }
  return seeds;
}

}  // namespace impm
