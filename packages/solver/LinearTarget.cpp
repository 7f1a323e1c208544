#include "solver/LinearTarget.hpp"

#include <NOX_Abstract_Group.H>
#include <NOX_Solver_Generic.H>

#include <algorithm>

namespace impm {

namespace {
// The fraction of Newton's target a solve aims at (the rest is left to the nonlinearity),
// and the loosest tolerance a solve is given.
constexpr double kMargin = 0.5;
constexpr double kLoosest = 0.1;
}  // namespace

Teuchos::ParameterList& linearSolveList(Teuchos::ParameterList& nox) {
  return nox.sublist("Direction").sublist("Newton").sublist("Linear Solver");
}

double LinearTarget::tolerance(double residual) const {
  if (!(residual > 0))
    return linearTolerance_;
  return std::min(kLoosest, std::max(linearTolerance_, kMargin * target_ / residual));
}

void LinearTarget::runPreIterate(const NOX::Solver::Generic& solver) {
  linearSolveList(nox_).set("Tolerance", tolerance(solver.getSolutionGroup().getNormF()));
}

}  // namespace impm
