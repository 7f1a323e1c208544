#include "basis/Method.hpp"

#include "basis/BuildMap.hpp"
#include "basis/CornerWeights.hpp"
#include "basis/CpdiWeights.hpp"
#include "basis/GimpWeights.hpp"
#include "basis/PointWeights.hpp"
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

template <int Dim, class Space>
ParticleGridMap<Dim, Space> buildParticleGridMap(Method method, const GridGeometry<Dim>& grid,
                                                 const ParticleSet<Dim, Space>& particles) {
  switch (method) {
    case Method::fem:
    case Method::mpm:
      return buildParticleGridMap(PointWeights<Dim, Space>(grid, particles), particles);
    case Method::gimp:
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

}  // namespace impm
