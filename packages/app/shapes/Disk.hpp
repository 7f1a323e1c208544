#pragma once
// A 2-D disk (Center, Radius); filled on sub-cells: its boundary becomes a staircase.

#include <Teuchos_ParameterList.hpp>

#include "app/shapes/Shape.hpp"

namespace impm {

class Disk : public SubCellShape {
 public:
  static void declareParameters(Teuchos::ParameterList& valid);
  Disk(const Teuchos::ParameterList& params, const std::string& path);

  bool contains(const double* x) const override {
    const double dx = x[0] - center_[0], dy = x[1] - center_[1];
    return dx * dx + dy * dy <= radius_ * radius_;
  }
  std::string placement() const override { return "Center"; }

 private:
  std::array<double, 2> center_{};
  double radius_ = 0.0;
};

}  // namespace impm
