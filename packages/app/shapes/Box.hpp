#pragma once
// An axis-aligned box (Lower Corner, Upper Corner): the 2-D "rectangle" and the 3-D "box";
// filled on sub-cells, which tile it exactly when its faces are on grid lines.

#include <Teuchos_ParameterList.hpp>

#include "app/shapes/Shape.hpp"

namespace impm {

template <int Dim>
class Box : public SubCellShape<Dim> {
 public:
  static void declareParameters(Teuchos::ParameterList& valid);
  Box(const Teuchos::ParameterList& params, const std::string& path);

  bool contains(const double* x) const override {
    for (int d = 0; d < Dim; ++d)
      if (x[d] < this->lower_[d] || x[d] > this->upper_[d])
        return false;
    return true;
  }
  std::string placement() const override { return "Lower Corner"; }
};

}  // namespace impm
