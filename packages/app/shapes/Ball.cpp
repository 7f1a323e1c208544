#include "app/shapes/Ball.hpp"

#include "core/Parameters.hpp"

namespace impm {

template <int Dim>
void Ball<Dim>::declareParameters(Teuchos::ParameterList& valid) {
  const char* what = Dim == 2 ? "disk" : "sphere";
  declareDoubleArray(
      valid, "Center", std::vector<double>(Dim, 0.0), {Dim},
      std::string("centre ") + (Dim == 2 ? "(x, y)" : "(x, y, z)") + " of the " + what,
      Bounds::any(), true);
  declareDouble(valid, "Radius", 1.0, std::string("radius of the ") + what, Bounds::positive(),
                true);
}

template <int Dim>
Ball<Dim>::Ball(const Teuchos::ParameterList& params, const std::string& /*path*/) {
  const auto& c = params.get<Teuchos::Array<double>>("Center");
  radius_ = params.get<double>("Radius");
  for (int d = 0; d < Dim; ++d)
    center_[d] = c[d], this->lower_[d] = c[d] - radius_, this->upper_[d] = c[d] + radius_;
}

template class Ball<2>;
template class Ball<3>;

}  // namespace impm
