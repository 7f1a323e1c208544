#include "core/Shape.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "core/Errors.hpp"
#include "core/Parameters.hpp"

namespace impm {

void declareShapeParameters(Teuchos::ParameterList& valid) {
  declareChoice(valid, "Shape", "interval", {"interval", "rectangle", "disk", "polygon"},
                "Geometry of the body in the reference configuration: interval (1-D); "
                "rectangle, disk or polygon (2-D)");
  declareDoubleArray(valid.sublist("[Shape=interval]"), "Extent", {0.0, 1.0}, {2},
                     "1-D: the body occupies [Extent[0], Extent[1]]", Bounds::any(), true);
  auto& rectangle = valid.sublist("[Shape=rectangle]");
  declareDoubleArray(rectangle, "Lower Corner", {0.0, 0.0}, {2}, "2-D: lower-left corner (x, y)",
                     Bounds::any(), true);
  declareDoubleArray(rectangle, "Upper Corner", {1.0, 1.0}, {2}, "2-D: upper-right corner (x, y)",
                     Bounds::any(), true);
  auto& disk = valid.sublist("[Shape=disk]");
  declareDoubleArray(disk, "Center", {0.0, 0.0}, {2}, "2-D: centre (x, y) of the disk",
                     Bounds::any(), true);
  declareDouble(disk, "Radius", 1.0, "2-D: radius of the disk", Bounds::positive(), true);
  declareDoubleArray(valid.sublist("[Shape=polygon]"), "Vertices", {0.0, 0.0, 1.0, 0.0, 0.0, 1.0},
                     {}, "2-D: the polygon's vertices x0, y0, x1, y1, ... in order (at least 3)",
                     Bounds::any(), true);
}

Shape::Shape(const Teuchos::ParameterList& params, const std::string& path, int dim) : dim_(dim) {
  const auto& shape = params.get<std::string>("Shape");
  const int needs = shape == "interval" ? 1 : 2;
  if (needs != dim)
    throw InputError(path + "/Shape", "shape '" + shape + "' is " + std::to_string(needs) +
                                          "-D but the grid is " + std::to_string(dim) + "-D");
  if (shape == "interval") {
    kind_ = Kind::interval;
    const auto& e = params.get<Teuchos::Array<double>>("Extent");
    lower_[0] = e[0], upper_[0] = e[1];
    if (!(e[0] < e[1]))
      throw InputError(path + "/Extent", "the lower end must be below the upper end");
  } else if (shape == "rectangle") {
    kind_ = Kind::rectangle;
    const auto& lo = params.get<Teuchos::Array<double>>("Lower Corner");
    const auto& hi = params.get<Teuchos::Array<double>>("Upper Corner");
    for (int d = 0; d < 2; ++d) {
      lower_[d] = lo[d], upper_[d] = hi[d];
      if (!(lo[d] < hi[d]))
        throw InputError(path + "/Upper Corner", "must lie above and right of Lower Corner");
    }
  } else if (shape == "disk") {
    kind_ = Kind::disk;
    const auto& c = params.get<Teuchos::Array<double>>("Center");
    radius_ = params.get<double>("Radius");
    for (int d = 0; d < 2; ++d)
      center_[d] = c[d], lower_[d] = c[d] - radius_, upper_[d] = c[d] + radius_;
  } else {
    kind_ = Kind::polygon;
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
}

bool Shape::contains(const double* x) const {
  switch (kind_) {
    case Kind::interval:
      return x[0] >= lower_[0] && x[0] <= upper_[0];
    case Kind::rectangle:
      return x[0] >= lower_[0] && x[0] <= upper_[0] && x[1] >= lower_[1] && x[1] <= upper_[1];
    case Kind::disk: {
      const double dx = x[0] - center_[0], dy = x[1] - center_[1];
      return dx * dx + dy * dy <= radius_ * radius_;
    }
    case Kind::polygon: {
      // On an edge (up to round-off): inside, as for the other shapes.
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
  }
  return false;
}

double Shape::boxDistance(const double* x) const {
  double s = 0.0;
  for (int d = 0; d < dim_; ++d) {
    const double out = std::max({lower_[d] - x[d], x[d] - upper_[d], 0.0});
    s += out * out;
  }
  return std::sqrt(s);
}

}  // namespace impm
