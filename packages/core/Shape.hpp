#pragma once
// The region a body occupies in the reference configuration: an interval (1-D), or a
// rectangle, disk or polygon (2-D).  Bodies are filled by testing points against it.

#include <Teuchos_ParameterList.hpp>

#include <array>
#include <string>
#include <vector>

namespace impm {

class Shape {
 public:
  enum class Kind { interval, rectangle, disk, polygon };

  // The shape's parameters of Bodies/<name> (valid list: shapeValidParameters); throws
  // InputError naming `path` + "/<parameter>" when the shape is degenerate or does not fit
  // a `dim`-D grid.
  Shape(const Teuchos::ParameterList& params, const std::string& path, int dim);
  Shape() = default;

  Kind kind() const { return kind_; }
  // True when x lies in the shape (closed: a point on the boundary is inside).
  bool contains(const double* x) const;
  // Distance from x to the shape's bounding box (0 inside it).
  double boxDistance(const double* x) const;
  // Bounding box: lower()[d] <= x[d] <= upper()[d].
  const std::array<double, 2>& lower() const { return lower_; }
  const std::array<double, 2>& upper() const { return upper_; }

 private:
  Kind kind_ = Kind::interval;
  int dim_ = 1;
  std::array<double, 2> lower_{}, upper_{};
  std::array<double, 2> center_{};
  double radius_ = 0.0;
  std::vector<std::array<double, 2>> vertices_;
};

// Shape, and the parameters of each shape in "[Shape=...]" sublists.
void declareShapeParameters(Teuchos::ParameterList& valid);

}  // namespace impm
