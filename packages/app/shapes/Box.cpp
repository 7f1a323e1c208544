#include "app/shapes/Box.hpp"

#include "core/Errors.hpp"
#include "core/Parameters.hpp"

namespace impm {

template <int Dim>
void Box<Dim>::declareParameters(Teuchos::ParameterList& valid) {
  const std::vector<double> lower(Dim, 0.0), upper(Dim, 1.0);
  const std::string coordinates = Dim == 2 ? "(x, y)" : "(x, y, z)";
  declareDoubleArray(valid, "Lower Corner", lower, {Dim}, "lowest corner " + coordinates,
                     Bounds::any(), true);
  declareDoubleArray(valid, "Upper Corner", upper, {Dim}, "highest corner " + coordinates,
                     Bounds::any(), true);
}

template <int Dim>
Box<Dim>::Box(const Teuchos::ParameterList& params, const std::string& path) {
  const auto& lo = params.get<Teuchos::Array<double>>("Lower Corner");
  const auto& hi = params.get<Teuchos::Array<double>>("Upper Corner");
  for (int d = 0; d < Dim; ++d) {
    this->lower_[d] = lo[d], this->upper_[d] = hi[d];
    if (!(lo[d] < hi[d]))
      throw InputError(path + "/Upper Corner", "must lie above Lower Corner along every direction");
  }
}

template class Box<2>;
template class Box<3>;

}  // namespace impm
