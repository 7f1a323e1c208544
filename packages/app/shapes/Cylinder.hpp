#pragma once
// A 3-D circular cylinder: Center (the middle of its axis), Axis (x, y or z), Radius and
// Length along the axis; filled on sub-cells.

#include <Teuchos_ParameterList.hpp>

#include "app/shapes/Shape.hpp"

namespace impm {

class Cylinder : public SubCellShape<3> {
 public:
  static void declareParameters(Teuchos::ParameterList& valid);
  Cylinder(const Teuchos::ParameterList& params, const std::string& path);

  bool contains(const double* x) const override {
    double r2 = 0.0;
    for (int d = 0; d < 3; ++d)
      if (d != axis_)
        r2 += (x[d] - center_[d]) * (x[d] - center_[d]);
    return r2 <= radius_ * radius_ && x[axis_] >= lower_[axis_] && x[axis_] <= upper_[axis_];
  }
  std::string placement() const override { return "Center"; }

 private:
  std::array<double, 3> center_{};
  int axis_ = 2;
  double radius_ = 0.0;
};

}  // namespace impm
