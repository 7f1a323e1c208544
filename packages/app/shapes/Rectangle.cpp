#include "app/shapes/Rectangle.hpp"

#include "core/Errors.hpp"
#include "core/Parameters.hpp"

namespace impm {

void Rectangle::declareParameters(Teuchos::ParameterList& valid) {
  declareDoubleArray(valid, "Lower Corner", {0.0, 0.0}, {2}, "2-D: lower-left corner (x, y)",
                     Bounds::any(), true);
  declareDoubleArray(valid, "Upper Corner", {1.0, 1.0}, {2}, "2-D: upper-right corner (x, y)",
                     Bounds::any(), true);
}

Rectangle::Rectangle(const Teuchos::ParameterList& params, const std::string& path) {
  const auto& lo = params.get<Teuchos::Array<double>>("Lower Corner");
  const auto& hi = params.get<Teuchos::Array<double>>("Upper Corner");
  for (int d = 0; d < 2; ++d) {
    lower_[d] = lo[d], upper_[d] = hi[d];
    if (!(lo[d] < hi[d]))
      throw InputError(path + "/Upper Corner", "must lie above and right of Lower Corner");
  }
}

}  // namespace impm
