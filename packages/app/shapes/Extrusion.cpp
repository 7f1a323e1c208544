#include "app/shapes/Extrusion.hpp"

namespace impm {

Extrusion::Extrusion(std::shared_ptr<const Shape<2>> base, double z0, double z1)
    : base_(std::move(base)) {
  for (int d = 0; d < 2; ++d)
    lower_[d] = base_->lower()[d], upper_[d] = base_->upper()[d];
  lower_[2] = z0, upper_[2] = z1;
}

}  // namespace impm
