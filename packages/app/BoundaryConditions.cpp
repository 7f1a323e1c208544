#include "app/BoundaryConditions.hpp"

#include "app/TimeIntegration.hpp"
#include "bc/DirichletNodes.hpp"
#include "bc/EdgeTraction.hpp"
#include "bc/RobinEnd.hpp"
#include "core/Errors.hpp"
#include "core/Parameters.hpp"

namespace impm {

Teuchos::ParameterList boundaryConditionValidParameters() {
  Teuchos::ParameterList valid;
  declareChoice(valid, "Type", "Robin", {"Robin", "Dirichlet", "Traction"},
                "Robin: alpha F + beta u = gamma at an end of a 1-D body (primer eq. 1.1); "
                "Dirichlet: a prescribed displacement component on grid nodes (rollers, "
                "clamps, platens); Traction: a dead load on part of a 2-D body's boundary",
                true);
  valid.sublist("[Type=Robin]").setParameters(RobinEnd::validParameters());
  valid.sublist("[Type=Dirichlet]").setParameters(DirichletNodes<2>::validParameters());
  auto& traction = valid.sublist("[Type=Traction]");
  declareString(traction, "Body", "block", "The body whose boundary is loaded", true);
  traction.setParameters(EdgeTraction::validParameters());
  return valid;
}

namespace {

// A Robin end of a 1-D body; each end takes one condition.
std::shared_ptr<Contribution<1>> robinEnd(const std::string& name, const Teuchos::ParameterList& p,
                                          const Bodies<1>& bodies, Kinematics kinematics,
                                          std::vector<std::string>& taken) {
  const std::string path = "Boundary Conditions/" + name;
  const int b = bodies.find(p.get<std::string>("Body"));
  if (b < 0)
    throw InputError(path + "/Body", "no body called '" + p.get<std::string>("Body") + "'");
  const std::string end = p.get<std::string>("Body") + "/" + p.get<std::string>("End");
  for (const auto& t : taken)
    if (t == end)
      throw InputError(path + "/End", "that end of body '" + p.get<std::string>("Body") +
                                          "' already has a boundary condition");
  taken.push_back(end);
  const auto& shape = *bodies.list()[b].shape;
  const double at = p.get<std::string>("End") == "left" ? shape.lower()[0] : shape.upper()[0];
  return std::make_shared<RobinEnd>(name, p, at, kinematics);
}

// The bit of Side Set in the face masks of the body's particles, or -1 when it is empty.
int sideSetBit(const Teuchos::ParameterList& p, const Shape<2>& shape, const std::string& path) {
  const auto& name = p.get<std::string>("Side Set");
  if (name.empty())
    return -1;
  const auto& sets = shape.sideSets();
  for (std::size_t k = 0; k < sets.size(); ++k)
    if (sets[k] == name) {
      if (shape.edgesOn(static_cast<int>(k)) == 0)
        throw InputError(path + "/Side Set", "side set '" + name + "' of " + shape.source() +
                                                 " names no edge of body '" +
                                                 p.get<std::string>("Body") + "'");
      return static_cast<int>(k);
    }
  throw InputError(path + "/Side Set", "body '" + p.get<std::string>("Body") + "' " +
                                           (shape.hasCorners() ? "(" + shape.source() + ") " : "") +
                                           "has no side set '" + name + "'");
}

}  // namespace

template <int Dim>
std::vector<std::shared_ptr<Contribution<Dim>>> createBoundaryConditions(
    const Teuchos::ParameterList& deck, const Bodies<Dim>& bodies, const GridGeometry<Dim>& grid,
    Method method, Kinematics kinematics) {
  std::vector<std::shared_ptr<Contribution<Dim>>> result;
  const auto& list = deck.sublist("Boundary Conditions");
  const double initialLoad = isStatic(deck.sublist("Time Integration")) ? 0.0 : 1.0;
  std::vector<std::string> taken;
  for (auto it = list.begin(); it != list.end(); ++it) {
    const std::string& name = list.name(it);
    const auto& p = list.sublist(name);
    if (p.get<std::string>("Type") == "Dirichlet") {
      result.push_back(std::make_shared<DirichletNodes<Dim>>(name, p, grid, initialLoad));
      continue;
    }
    const std::string path = "Boundary Conditions/" + name;
    if (p.get<std::string>("Type") == "Traction") {
      if constexpr (Dim == 2) {
        const int b = bodies.find(p.get<std::string>("Body"));
        if (b < 0)
          throw InputError(path + "/Body", "no body called '" + p.get<std::string>("Body") + "'");
        if (!isParticleMethod(method))
          throw InputError(path + "/Type",
                           "a traction acts on the faces of particle domains, which fem's Gauss "
                           "points do not have: use mpm, gimp or cpdi");
        const auto shape = bodies.list()[b].shape;
        result.push_back(std::make_shared<EdgeTraction>(
            name, p, b, [shape](const double* x) { return shape->contains(x); },
            sideSetBit(p, *shape, path), kinematics, initialLoad));
        continue;
      }
      throw InputError(path + "/Type",
                       Dim == 1 ? "tractions are for 2-D bodies; a 1-D end force is a Robin "
                                  "condition"
                                : "tractions on the faces of 3-D bodies are not written yet; "
                                  "a body force or a prescribed displacement can load a 3-D "
                                  "body");
    }
    if constexpr (Dim == 1)
      result.push_back(robinEnd(name, p, bodies, kinematics, taken));
    else
      throw InputError(path + "/Type", "Robin ends are for 1-D bars; use Dirichlet on a " +
                                           std::to_string(Dim) + "-D grid");
  }
  return result;
}

template std::vector<std::shared_ptr<Contribution<1>>> createBoundaryConditions<1>(
    const Teuchos::ParameterList&, const Bodies<1>&, const GridGeometry<1>&, Method, Kinematics);
template std::vector<std::shared_ptr<Contribution<2>>> createBoundaryConditions<2>(
    const Teuchos::ParameterList&, const Bodies<2>&, const GridGeometry<2>&, Method, Kinematics);
template std::vector<std::shared_ptr<Contribution<3>>> createBoundaryConditions<3>(
    const Teuchos::ParameterList&, const Bodies<3>&, const GridGeometry<3>&, Method, Kinematics);

}  // namespace impm
