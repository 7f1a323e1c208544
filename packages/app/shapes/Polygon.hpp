#pragma once
// A 2-D simple polygon (Vertices x0, y0, x1, y1, ...); filled on sub-cells.  A point on an
// edge (up to round-off) is inside, as for the other shapes; elsewhere the even-odd rule.

#include <Teuchos_ParameterList.hpp>

#include "app/shapes/Shape.hpp"

namespace impm {

class Polygon : public SubCellShape<2> {
 public:
  static void declareParameters(Teuchos::ParameterList& valid);
  Polygon(const Teuchos::ParameterList& params, const std::string& path);

  bool contains(const double* x) const override;
  std::string placement() const override { return "Vertices"; }

 private:
  std::vector<std::array<double, 2>> vertices_;
};

}  // namespace impm
