#include "app/BoundaryConditions.hpp"

#include "bc/RobinEnd.hpp"
#include "core/Errors.hpp"
#include "core/Parameters.hpp"

namespace impm {

Teuchos::ParameterList boundaryConditionValidParameters() {
  Teuchos::ParameterList valid;
  declareChoice(valid, "Type", "Robin", {"Robin"},
                "Robin: alpha F + beta u = gamma at an end of a 1-D body (primer eq. 1.1)", true);
  valid.sublist("[Type=Robin]").setParameters(RobinEnd::validParameters());
  return valid;
}

template <>
std::vector<std::shared_ptr<Contribution<1>>> createBoundaryConditions<1>(
    const Teuchos::ParameterList& deck, const Bodies<1>& bodies, Kinematics kinematics) {
  std::vector<std::shared_ptr<Contribution<1>>> result;
  const auto& list = deck.sublist("Boundary Conditions");
  std::vector<std::string> taken;
  for (auto it = list.begin(); it != list.end(); ++it) {
    const std::string& name = list.name(it);
    const auto& p = list.sublist(name);
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
    const Body& body = bodies.list()[b];
    const double at = p.get<std::string>("End") == "left" ? body.lower : body.upper;
    result.push_back(std::make_shared<RobinEnd>(name, p, at, kinematics));
  }
  return result;
}

}  // namespace impm
