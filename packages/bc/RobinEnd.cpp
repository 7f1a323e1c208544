#include "bc/RobinEnd.hpp"

#include <Teuchos_CommHelpers.hpp>

#include "basis/BuildMap.hpp"
#include "basis/Tent.hpp"
#include "core/Errors.hpp"
#include "core/Parameters.hpp"

namespace impm {

Teuchos::ParameterList RobinEnd::validParameters() {
  Teuchos::ParameterList valid;
  declareString(valid, "Body", "bar", "The body whose end this condition holds", true);
  declareChoice(valid, "End", "left", {"left", "right"}, "Which end of the body", true);
  declareDouble(valid, "alpha", 0.0, "Coefficient of the end force F in alpha F + beta u = gamma");
  declareDouble(valid, "beta", 1.0,
                "Coefficient of the end displacement u (minus the spring stiffness for a spring)");
  declareFormula(valid, "gamma", "0", {"t"},
                 "Right-hand side gamma(t); ramped with the load factor in static load steps");
  return valid;
}

RobinEnd::RobinEnd(const std::string& name, const Teuchos::ParameterList& params,
                   double referenceEnd, Kinematics kinematics)
    : name_(name),
      body_(params.get<std::string>("Body")),
      left_(params.get<std::string>("End") == "left"),
      alpha_(params.get<double>("alpha")),
      beta_(params.get<double>("beta")),
      gamma_(formulaText(params, "gamma"), {"t"}),
      kinematics_(kinematics),
      position_(referenceEnd) {
  if (alpha_ == 0.0 && beta_ == 0.0)
    throw InputError("Boundary Conditions/" + name + "/alpha",
                     "alpha and beta are both zero: the condition alpha F + beta u = gamma "
                     "constrains nothing");
}

void RobinEnd::prepare(const NodeOwnership<1>& ownership, std::vector<ExtraDof>& extras,
                       std::vector<GlobalId>& touched) {
  const auto& grid = ownership.grid();
  const double g = grid.gridCoord(0, position_);  // round-off may put a fixed end at -1e-17
  if (!(g >= -kGridTolerance && g <= grid.cells[0] + kGridTolerance))
    throw NumericalError("the " + std::string(left_ ? "left" : "right") + " end of body '" + body_ +
                         "' (boundary condition '" + name_ +
                         "') at x = " + std::to_string(position_) + " has left the grid");
  const int cell = grid.cellAlong(0, position_);
  const double s = grid.gridCoord(0, position_) - cell;
  support_ = Support();
  for (int k = 0; k < 2; ++k) {
    const double w = tent(s - k);
    if (w <= kNegligibleWeight)
      continue;
    support_.node[support_.count] = cell + k;
    support_.weight[support_.count] = w;
    ++support_.count;
  }
  const GlobalId anchor = support_.node[support_.count - 1];
  extras.push_back(ExtraDof{anchor});
  owner_ = ownership.ownerOfNode(anchor) == ownership.comm()->getRank();
  if (owner_)
    for (int k = 0; k < support_.count; ++k)
      touched.push_back(support_.node[k]);
}

void RobinEnd::couplings(const ContributionContext<1>& ctx,
                         std::vector<std::pair<GO, GO>>& out) const {
  if (!owner_)
    return;
  const GO F = ctx.dofs.extraDof(ctx.firstExtra);
  out.emplace_back(F, F);
  for (int k = 0; k < support_.count; ++k) {
    const GO u = ctx.dofs.nodeDof(support_.node[k], 0);
    out.emplace_back(F, u);
    out.emplace_back(u, F);
  }
}

void RobinEnd::initialGuess(const ContributionContext<1>& ctx, Vector& x) const {
  if (owner_)
    x.replaceGlobalValue(ctx.dofs.extraDof(ctx.firstExtra), force_);
}

double RobinEnd::gamma(const ContributionContext<1>& ctx) const {
  return ctx.loadFactor * gamma_(ctx.time);
}

void RobinEnd::addResidual(const ContributionContext<1>& ctx, const HostValues& x,
                           const HostValuesMutable& f) const {
  if (!owner_)
    return;
  const auto& overlap = *ctx.dofs.overlapMap();
  const LO F = overlap.getLocalElement(ctx.dofs.extraDof(ctx.firstExtra));
  double uEnd = displacement_;
  for (int k = 0; k < support_.count; ++k) {
    const LO u = overlap.getLocalElement(ctx.dofs.nodeDof(support_.node[k], 0));
    uEnd += support_.weight[k] * x(u, 0);
    f(u, 0) -= support_.weight[k] * x(F, 0);  // boundary-force array, eq. 1.12
  }
  f(F, 0) += alpha_ * x(F, 0) + beta_ * uEnd - gamma(ctx);  // eq. 1.19
}

void RobinEnd::addJacobian(const ContributionContext<1>& ctx, const HostValues& /*x*/,
                           FECrsMatrix& J) const {
  if (!owner_)
    return;
  const GO F = ctx.dofs.extraDof(ctx.firstExtra);
  J.sumIntoGlobalValues(F, 1, &alpha_, &F);
  for (int k = 0; k < support_.count; ++k) {
    const GO u = ctx.dofs.nodeDof(support_.node[k], 0);
    const double dFdu = beta_ * support_.weight[k], dudF = -support_.weight[k];
    J.sumIntoGlobalValues(F, 1, &dFdu, &u);
    J.sumIntoGlobalValues(u, 1, &dudF, &F);
  }
}

void RobinEnd::commit(const ContributionContext<1>& ctx, const HostValues& x) {
  // The owner knows the end force and the end's displacement increment; share them.
  double local[2] = {0.0, 0.0}, global[2];
  if (owner_) {
    const auto& overlap = *ctx.dofs.overlapMap();
    local[0] = x(overlap.getLocalElement(ctx.dofs.extraDof(ctx.firstExtra)), 0);
    for (int k = 0; k < support_.count; ++k)
      local[1] +=
          support_.weight[k] * x(overlap.getLocalElement(ctx.dofs.nodeDof(support_.node[k], 0)), 0);
  }
  Teuchos::reduceAll(*ctx.dofs.ownedMap()->getComm(), Teuchos::REDUCE_SUM, 2, local, global);
  work_ += 0.5 * (force_ + global[0]) * global[1];
  force_ = global[0];
  displacement_ += global[1];
  if (kinematics_ == Kinematics::updatedLagrangian)
    position_ += global[1];
}

void RobinEnd::restore(const std::vector<double>& s) {
  if (s.size() != 4)
    throw std::invalid_argument("a Robin end's state has 4 values, not " +
                                std::to_string(s.size()));
  position_ = s[0], displacement_ = s[1], force_ = s[2], work_ = s[3];
}

}  // namespace impm
