#include "app/shapes/Disk.hpp"

#include "core/Parameters.hpp"

namespace impm {

void Disk::declareParameters(Teuchos::ParameterList& valid) {
  declareDoubleArray(valid, "Center", {0.0, 0.0}, {2}, "2-D: centre (x, y) of the disk",
                     Bounds::any(), true);
  declareDouble(valid, "Radius", 1.0, "2-D: radius of the disk", Bounds::positive(), true);
}

Disk::Disk(const Teuchos::ParameterList& params, const std::string& /*path*/) {
  const auto& c = params.get<Teuchos::Array<double>>("Center");
  radius_ = params.get<double>("Radius");
  for (int d = 0; d < 2; ++d)
    center_[d] = c[d], lower_[d] = c[d] - radius_, upper_[d] = c[d] + radius_;
}

}  // namespace impm
