#include "material/MaterialPropertyFill.hpp"

#include <sstream>

#include "core/Errors.hpp"

namespace impm {

template <int Dim>
void fillPropertyFromFormula(const typename Material<Dim>::Evaluation& at,
                             const typename Material<Dim>::Table& values, const Formula& f,
                             const std::string& path, Bounds bounds) {
  auto X = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), at.particles.X);
  auto members = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), at.members);
  auto host = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), values);
  std::vector<double> position(Dim);
  for (std::size_t i = 0; i < members.extent(0); ++i) {
    const int p = members(i);
    for (int d = 0; d < Dim; ++d)
      position[d] = X(p, d);
    const double value = f(position);
    if (!std::isfinite(value) || !bounds.contains(value)) {
      std::ostringstream msg;
      msg << "must be " << bounds.describe() << ", but is " << value << " at x = " << position[0];
      if (Dim > 1)
        msg << ", y = " << position[1];
      throw InputError(path, msg.str());
    }
    host(p, 0) = value;
  }
  Kokkos::deep_copy(values, host);
}

template <int Dim>
double maxProperty(const typename Material<Dim>::Evaluation& at,
                   const typename Material<Dim>::Table& values) {
  const auto members = at.members;
  double result = 0.0;
  Kokkos::parallel_reduce(
      "impm::maxProperty",
      RangePolicy<typename Material<Dim>::ExecutionSpace>(0, members.extent(0)),
      KOKKOS_LAMBDA(const int i, double& m) {
        const double value = values(members(i), 0);
        if (value > m)
          m = value;
      },
      Kokkos::Max<double>(result));
  return members.extent(0) ? result : 0.0;
}

template void fillPropertyFromFormula<1>(const Material<1>::Evaluation&, const Material<1>::Table&,
                                         const Formula&, const std::string&, Bounds);
template void fillPropertyFromFormula<2>(const Material<2>::Evaluation&, const Material<2>::Table&,
                                         const Formula&, const std::string&, Bounds);
template void fillPropertyFromFormula<3>(const Material<3>::Evaluation&, const Material<3>::Table&,
                                         const Formula&, const std::string&, Bounds);
template double maxProperty<1>(const Material<1>::Evaluation&, const Material<1>::Table&);
template double maxProperty<2>(const Material<2>::Evaluation&, const Material<2>::Table&);
template double maxProperty<3>(const Material<3>::Evaluation&, const Material<3>::Table&);

}  // namespace impm
