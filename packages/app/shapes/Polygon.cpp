#include "app/shapes/Polygon.hpp"

#include <algorithm>
#include <cmath>

#include "core/Errors.hpp"
#include "core/Parameters.hpp"

namespace impm {

void Polygon::declareParameters(Teuchos::ParameterList& valid) {
  declareDoubleArray(valid, "Vertices", {0.0, 0.0, 1.0, 0.0, 0.0, 1.0}, {},
                     "2-D: the polygon's vertices x0, y0, x1, y1, ... in order (at least 3)",
                     Bounds::any(), true);
}

Polygon::Polygon(const Teuchos::ParameterList& params, const std::string& path) {
  const auto& v = params.get<Teuchos::Array<double>>("Vertices");
  if (v.size() < 6 || v.size() % 2 != 0)
    throw InputError(path + "/Vertices",
                     "needs an even number of coordinates, at least 3 vertices, but has " +
                         std::to_string(v.size()) + " numbers");
  lower_ = {v[0], v[1]}, upper_ = {v[0], v[1]};
  double area = 0.0;
  const auto n = static_cast<std::size_t>(v.size());
  for (std::size_t k = 0; k < n; k += 2) {
    vertices_.push_back({v[k], v[k + 1]});
    const std::size_t next = (k + 2) % n;
    area += v[k] * v[next + 1] - v[next] * v[k + 1];
    for (int d = 0; d < 2; ++d)
      lower_[d] = std::min(lower_[d], v[k + d]), upper_[d] = std::max(upper_[d], v[k + d]);
  }
  if (!(std::abs(area) > 0))
    throw InputError(path + "/Vertices", "the polygon has zero area");
}

bool Polygon::contains(const double* x) const {
  for (std::size_t i = 0, j = vertices_.size() - 1; i < vertices_.size(); j = i++) {
    const auto &a = vertices_[i], &b = vertices_[j];
    const double ex = b[0] - a[0], ey = b[1] - a[1];
    const double px = x[0] - a[0], py = x[1] - a[1];
    const double length2 = ex * ex + ey * ey;
    const double along = px * ex + py * ey;
    if (std::abs(ex * py - ey * px) <= 1e-12 * length2 && along >= 0 && along <= length2)
      return true;
  }
  // Even-odd rule: count the edges that a ray towards +x crosses.
  bool inside = false;
  for (std::size_t i = 0, j = vertices_.size() - 1; i < vertices_.size(); j = i++) {
    const auto &a = vertices_[i], &b = vertices_[j];
    if ((a[1] > x[1]) != (b[1] > x[1]) &&
        x[0] < a[0] + (x[1] - a[1]) * (b[0] - a[0]) / (b[1] - a[1]))
      inside = !inside;
  }
  return inside;
}

}  // namespace impm
