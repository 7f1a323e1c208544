#pragma once
// A ball (Center, Radius): the 2-D "disk" and the 3-D "sphere"; filled on sub-cells, so its
// boundary becomes a staircase.

#include <Teuchos_ParameterList.hpp>

#include "app/shapes/Shape.hpp"

namespace impm {

template <int Dim>
class Ball : public SubCellShape<Dim> {
 public:
  static void declareParameters(Teuchos::ParameterList& valid);
  Ball(const Teuchos::ParameterList& params, const std::string& path);

  bool contains(const double* x) const override {
    double r2 = 0.0;
    for (int d = 0; d < Dim; ++d)
      r2 += (x[d] - center_[d]) * (x[d] - center_[d]);
    return r2 <= radius_ * radius_;
  }
  std::string placement() const override { return "Center"; }

 private:
  std::array<double, Dim> center_{};
  double radius_ = 0.0;
};

}  // namespace impm
