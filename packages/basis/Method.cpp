#include "basis/Method.hpp"

#include <sstream>

#include "basis/BuildMap.hpp"
#include "basis/CornerWeights.hpp"
#include "basis/CpdiWeights.hpp"
#include "basis/GimpWeights.hpp"
#include "basis/PointWeights.hpp"
#include "core/Diagnostics.hpp"
#include "core/Errors.hpp"

namespace impm {

const std::vector<std::string>& methodNames() {
  static const std::vector<std::string> names = {"fem", "mpm", "gimp", "cpdi"};
  return names;
}

Method parseMethod(const std::string& name) {
  const auto& names = methodNames();
  for (std::size_t k = 0; k < names.size(); ++k)
    if (names[k] == name)
      return static_cast<Method>(k);
  throw InputError("", "unknown method '" + name + "'");
}

std::string methodName(Method m) {
  return methodNames()[static_cast<int>(m)];
}

namespace {

// NumericalError naming the first particle whose GIMP box has a half-width that is not
// positive.  The half-widths are the diagonal of the domain tensor F r0: a stretch F_dd that
// changed sign (large shear or rotation) turns the box inside out, and the weights of an
// inverted box are meaningless, not a smaller particle.
template <int Dim, class Space>
void requireUprightBoxes(const ParticleSet<Dim, Space>& particles) {
  const auto domain = particles.domain;
  int first = static_cast<int>(particles.size());
  Kokkos::parallel_reduce(
      "impm::insideOutBoxes", RangePolicy<typename Space::execution_space>(0, first),
      KOKKOS_LAMBDA(const int p, int& found) {
        for (int d = 0; d < Dim; ++d)
          if (!(domain(p, d, d) > 0.0) && p < found)
            found = p;
      },
      Kokkos::Min<int>(first));
  if (first >= static_cast<int>(particles.size()))  // Min's identity is the largest int
    return;
  auto r = Kokkos::create_mirror_view_and_copy(
      Kokkos::HostSpace(),
      Kokkos::subview(domain, Kokkos::make_pair(first, first + 1), Kokkos::ALL(), Kokkos::ALL()));
  std::ostringstream msg;
  msg << particleLabel(particles, first) << " has its GIMP box turned inside out: half-widths (";
  for (int d = 0; d < Dim; ++d)
    msg << (d ? ", " : "") << r(0, d, d);
  msg << "), the diagonal of F times its initial box (a stretch F_dd that changed sign under "
         "large shear or rotation); cpdi's domains follow the whole of F";
  throw NumericalError(msg.str());
}

}  // namespace

template <int Dim, class Space>
ParticleGridMap<Dim, Space> buildParticleGridMap(Method method, const GridGeometry<Dim>& grid,
                                                 const ParticleSet<Dim, Space>& particles) {
  switch (method) {
    case Method::fem:
    case Method::mpm:
      return buildParticleGridMap(PointWeights<Dim, Space>(grid, particles), particles);
    case Method::gimp:
      requireUprightBoxes(particles);
      return buildParticleGridMap(GimpWeights<Dim, Space>(grid, particles), particles);
    case Method::cpdi:
      if (particles.has(kCornersField))  // tracked corners: CPDI2 and CPTI
        return buildParticleGridMap(
            CornerWeights<Dim, Space>(grid, particles, particles.values(kCornersField)), particles);
      return buildParticleGridMap(CpdiWeights<Dim, Space>(grid, particles), particles);
  }
  throw std::logic_error("unhandled method");
}

template ParticleGridMap<1> buildParticleGridMap(Method, const GridGeometry<1>&,
                                                 const ParticleSet<1>&);
template ParticleGridMap<2> buildParticleGridMap(Method, const GridGeometry<2>&,
                                                 const ParticleSet<2>&);
template ParticleGridMap<3> buildParticleGridMap(Method, const GridGeometry<3>&,
                                                 const ParticleSet<3>&);

}  // namespace impm
