#pragma once
// A 2-D axis-aligned rectangle (Lower Corner, Upper Corner); filled on sub-cells, which tile
// it exactly when its edges are on grid lines.

#include <Teuchos_ParameterList.hpp>

#include "app/shapes/Shape.hpp"

namespace impm {

class Rectangle : public SubCellShape {
 public:
  static void declareParameters(Teuchos::ParameterList& valid);
  Rectangle(const Teuchos::ParameterList& params, const std::string& path);

  bool contains(const double* x) const override {
    return x[0] >= lower_[0] && x[0] <= upper_[0] && x[1] >= lower_[1] && x[1] <= upper_[1];
  }
  std::string placement() const override { return "Lower Corner"; }
};

}  // namespace impm
