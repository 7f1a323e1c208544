#pragma once
// A 1-D body [a, b] (Bodies/<name>/Extent).  Its material points are equal particles filling
// [a, b], about n per grid cell; its Gauss points are two per cell on the part of each cell
// inside [a, b] (the cut part of the cell that an end crosses, so that FEM integrates over
// the body exactly).

#include <Teuchos_ParameterList.hpp>

#include "app/shapes/Shape.hpp"

namespace impm {

class Interval : public Shape<1> {
 public:
  static void declareParameters(Teuchos::ParameterList& valid);
  Interval(const Teuchos::ParameterList& params, const std::string& path);

  bool contains(const double* x) const override { return x[0] >= lower_[0] && x[0] <= upper_[0]; }
  std::string placement() const override { return "Extent"; }
  std::vector<Seed<1>> fill(const GridGeometry<1>& grid, int perCell, bool gauss) const override;
};

}  // namespace impm
