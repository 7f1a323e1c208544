#pragma once
// A 2-D shape (rectangle, disk, polygon, image, mesh) extruded along z in a 3-D deck: the
// points (x, y, z) with (x, y) in the 2-D shape and z in Extrusion = {z0, z1}; filled on
// sub-cells like the 3-D shapes (an image's pixels and a mesh's elements become stair-
// stepped prisms of sub-cells: their own 3-D forms are voxel stacks and 3-D meshes).

#include <memory>

#include "app/shapes/Shape.hpp"

namespace impm {

class Extrusion : public SubCellShape<3> {
 public:
  Extrusion(std::shared_ptr<const Shape<2>> base, double z0, double z1);

  bool contains(const double* x) const override {
    return x[2] >= lower_[2] && x[2] <= upper_[2] && base_->contains(x);
  }
  std::string placement() const override { return base_->placement(); }
  std::string source() const override { return base_->source(); }

 private:
  std::shared_ptr<const Shape<2>> base_;
};

}  // namespace impm
