#pragma once
// The four discretisations of the primer, selected by Discretization/Method.  They differ
// only in where the integration points are (Gauss points of the grid cells, or material
// points) and in how phi_ip and G_ip are computed.

#include <string>
#include <vector>

#include "basis/ParticleGridMap.hpp"
#include "core/Grid.hpp"
#include "core/ParticleSet.hpp"

namespace impm {

enum class Method {
  fem,   // Gauss points of the grid cells, fixed; point weights (eq. 1.22)
  mpm,   // material points, single-point weights (eq. 1.29)
  gimp,  // material points, exact tent average over the domain (eq. 1.33-1.35)
  cpdi,  // material points, CPDI alternative basis (eq. 1.36-1.38)
};

const std::vector<std::string>& methodNames();
Method parseMethod(const std::string& name);
std::string methodName(Method m);
// True when integration points are material points that carry mass and move.
inline bool isParticleMethod(Method m) {
  return m != Method::fem;
}

// Builds Y, phi_ip and G_ip for the given method (cpdi: CPDI2 where the particles carry
// corners, the field kCornersField).  Throws NumericalError naming the first
// particle whose integration domain is outside the grid.
template <int Dim, class Space = DefaultExecSpace>
ParticleGridMap<Dim, Space> buildParticleGridMap(Method method, const GridGeometry<Dim>& grid,
                                                 const ParticleSet<Dim, Space>& particles);

}  // namespace impm
