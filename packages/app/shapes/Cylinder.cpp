#include "app/shapes/Cylinder.hpp"

#include <algorithm>

#include "core/Axes.hpp"
#include "core/Parameters.hpp"

namespace impm {

void Cylinder::declareParameters(Teuchos::ParameterList& valid) {
  declareDoubleArray(valid, "Center", {0.0, 0.0, 0.0}, {3},
                     "centre (x, y, z) of the cylinder: the middle of its axis", Bounds::any(),
                     true);
  declareChoice(valid, "Axis", "z", axisNames<3>(), "direction of the cylinder's axis");
  declareDouble(valid, "Radius", 1.0, "radius of the cylinder", Bounds::positive(), true);
  declareDouble(valid, "Length", 1.0, "length of the cylinder along its axis", Bounds::positive(),
                true);
}

Cylinder::Cylinder(const Teuchos::ParameterList& params, const std::string& /*path*/) {
  const auto& c = params.get<Teuchos::Array<double>>("Center");
  const auto names = axisNames<3>();
  axis_ = static_cast<int>(std::find(names.begin(), names.end(), params.get<std::string>("Axis")) -
                           names.begin());
  radius_ = params.get<double>("Radius");
  const double half = 0.5 * params.get<double>("Length");
  for (int d = 0; d < 3; ++d) {
    const double extent = d == axis_ ? half : radius_;
    center_[d] = c[d], lower_[d] = c[d] - extent, upper_[d] = c[d] + extent;
  }
}

}  // namespace impm
