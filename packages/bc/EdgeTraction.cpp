#include "bc/EdgeTraction.hpp"

#include <cmath>
#include <sstream>

#include "basis/Tent.hpp"
#include "core/Errors.hpp"
#include "core/Parameters.hpp"

namespace impm {

Teuchos::ParameterList EdgeTraction::validParameters() {
  Teuchos::ParameterList valid;
  declareDoubleArray(valid, "Region", {0.0, 1.0, 1.0, 1.0}, {4},
                     "2-D: xmin, xmax, ymin, ymax of the box holding the loaded part of the "
                     "boundary, in the reference configuration (edges included)",
                     Bounds::any(), true);
  for (const char* c : {"x", "y"})
    declareFormula(valid, std::string("Traction ") + c, "0", {"x", "y", "t"},
                   std::string("2-D: ") + c +
                       " component of the traction, force per unit "
                       "reference length (a dead load), a formula of the reference position x, y "
                       "and time t; ramped with the load factor in static load steps");
  return valid;
}

EdgeTraction::EdgeTraction(const std::string& name, const Teuchos::ParameterList& params, int body,
                           std::function<bool(const double*)> inside, Kinematics kinematics)
    : name_(name), body_(body), inside_(std::move(inside)), kinematics_(kinematics) {
  const std::string path = "Boundary Conditions/" + name + "/";
  const auto& region = params.get<Teuchos::Array<double>>("Region");
  for (int k = 0; k < 4; ++k)
    box_[k] = region[k];
  if (!(box_[0] <= box_[1] && box_[2] <= box_[3]))
    throw InputError(path + "Region", "needs xmin <= xmax and ymin <= ymax");
  const char* components[2] = {"x", "y"};
  for (int a = 0; a < 2; ++a) {
    const std::string p = std::string("Traction ") + components[a];
    try {
      traction_[a] = Formula(formulaText(params, p), {"x", "y", "t"});
    } catch (const InputError& e) {
      throw InputError(path + p, e.what());
    }
  }
}

void EdgeTraction::addResidual(const ContributionContext<2>& ctx, const HostValues& /*x*/,
                               const HostValuesMutable& f) const {
  const auto host = ctx.particles.mirror(Kokkos::DefaultHostExecutionSpace());
  const auto& body = host.body;
  const auto& id = host.id;
  const auto& X = host.X;
  const auto& r0 = host.domain0;
  const bool total = kinematics_ == Kinematics::totalLagrangian;
  const auto& xs = total ? host.X : host.x;  // where the faces are during the step
  const auto& rs = total ? host.domain0 : host.domain;
  const auto& grid = ctx.grid;
  const auto& overlap = *ctx.dofs.overlapMap();
  const double tol = 1e-9;
  for (std::size_t p = 0; p < host.size(); ++p) {
    if (body(p) != body_)
      continue;
    for (int k = 0; k < 2; ++k)  // faces +-r_k; the other half-vector spans the face
      for (const double s : {-1.0, 1.0}) {
        const int o = 1 - k;
        double mid[2], beyond[2];
        for (int d = 0; d < 2; ++d) {
          mid[d] = X(p, d) + s * r0(p, d, k);
          beyond[d] = mid[d] + 1e-6 * s * r0(p, d, k);
        }
        if (mid[0] < box_[0] - tol || mid[0] > box_[1] + tol || mid[1] < box_[2] - tol ||
            mid[1] > box_[3] + tol || inside_(beyond))
          continue;
        const double length = 2.0 * std::hypot(r0(p, 0, o), r0(p, 1, o));
        double t[2];
        for (int a = 0; a < 2; ++a)
          t[a] = ctx.loadFactor * traction_[a](mid[0], mid[1], ctx.time);
        for (const double c : {-1.0, 1.0}) {  // the face's two corners, now
          double g[2];
          for (int d = 0; d < 2; ++d)
            g[d] = clipToGrid(grid, d,
                              grid.gridCoord(d, xs(p, d) + s * rs(p, d, k) + c * rs(p, d, o)));
          int cell[2];
          for (int d = 0; d < 2; ++d)
            cell[d] = std::min(grid.cells[d] - 1, std::max(0, static_cast<int>(std::floor(g[d]))));
          for (int j = 0; j <= 1; ++j)
            for (int i = 0; i <= 1; ++i) {
              const int node[2] = {cell[0] + i, cell[1] + j};
              const double N = tent(g[0] - node[0]) * tent(g[1] - node[1]);
              if (N == 0.0)
                continue;
              const GlobalId nodeId = grid.nodeId(node);
              for (int a = 0; a < 2; ++a) {
                const LO lid = overlap.getLocalElement(ctx.dofs.nodeDof(nodeId, a));
                if (lid == Teuchos::OrdinalTraits<LO>::invalid()) {
                  std::ostringstream msg;
                  msg << "Boundary Conditions/" << name_ << ": a loaded face of particle " << id(p)
                      << " reaches grid node " << nodeId
                      << ", which no integration point reaches (use gimp or cpdi)";
                  throw NumericalError(msg.str());
                }
                f(lid, 0) -= t[a] * length * 0.5 * N;
              }
            }
        }
      }
  }
}

}  // namespace impm
