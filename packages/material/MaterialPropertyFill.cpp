#include "material/MaterialPropertyFill.hpp"

#include <sstream>

#include "core/Errors.hpp"

namespace impm {

template <int Dim>
void fillPropertyFromFormula(ParticleSet<Dim>& particles, int index, int slot, const Formula& f,
                             const std::string& path, Bounds bounds) {
  auto X = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), particles.X);
  auto material = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), particles.material);
  auto props = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), particles.props);
  std::vector<double> at(Dim);
  for (std::size_t p = 0; p < particles.size(); ++p) {
    if (material(p) != index)
      continue;
    for (int d = 0; d < Dim; ++d)
      at[d] = X(p, d);
    const double value = f(at);
    if (!std::isfinite(value) || !bounds.contains(value)) {
      std::ostringstream msg;
      msg << "must be " << bounds.describe() << ", but is " << value << " at x = " << at[0];
      if (Dim > 1)
        msg << ", y = " << at[1];
      throw InputError(path, msg.str());
    }
    props(p, slot) = value;
  }
  Kokkos::deep_copy(particles.props, props);
}

template <int Dim>
double maxProperty(const ParticleSet<Dim>& particles, int index, int slot) {
  auto material = particles.material;
  auto props = particles.props;
  double result = 0.0;
  Kokkos::parallel_reduce(
      "impm::maxProperty", RangePolicy<DefaultExecSpace>(0, particles.size()),
      KOKKOS_LAMBDA(const int p, double& m) {
        if (material(p) == index && props(p, slot) > m)
          m = props(p, slot);
      },
      Kokkos::Max<double>(result));
  return result;
}

template void fillPropertyFromFormula<1>(ParticleSet<1>&, int, int, const Formula&,
                                         const std::string&, Bounds);
template void fillPropertyFromFormula<2>(ParticleSet<2>&, int, int, const Formula&,
                                         const std::string&, Bounds);
template double maxProperty<1>(const ParticleSet<1>&, int, int);
template double maxProperty<2>(const ParticleSet<2>&, int, int);

}  // namespace impm
