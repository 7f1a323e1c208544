#include "app/AppParameters.hpp"

#include "app/Bodies.hpp"
#include "app/BoundaryConditions.hpp"
#include "app/LoadBalance.hpp"
#include "app/Output.hpp"
#include "app/TimeIntegration.hpp"
#include "app/Verification.hpp"
#include "basis/Method.hpp"
#include "core/Parameters.hpp"
#include "material/MaterialFactory.hpp"
#include "solver/NewtonSolver.hpp"

namespace impm {

namespace {

Teuchos::ParameterList discretizationParameters() {
  Teuchos::ParameterList valid;
  declareChoice(valid, "Method", "gimp", methodNames(),
                "fem: Gauss points of the grid cells (2 per cell and direction); mpm: classic "
                "MPM, single-point weights at particle centres; gimp: exact average of the "
                "tent functions over each particle; cpdi: convected particle domain "
                "interpolation",
                true);
  declareChoice(valid, "Kinematics", "auto", {"auto", "total Lagrangian", "updated Lagrangian"},
                "total Lagrangian: integration points stay at their reference positions (FEM; "
                "the primer's small-deformation bar); updated Lagrangian: particles move "
                "through the grid (MPM).  auto: total for fem, updated otherwise");
  declareChoice(valid, "F-bar", "none", {"none", "cell"},
                "cell: the laws see each particle's F with its determinant replaced by the "
                "volume-weighted average over the particles of its grid cell (the F-bar method "
                "against volumetric locking; doc/theory.md); none: the particles' own F");
  declareDouble(
      valid, "Ghost Penalty", 1e-3,
      "gamma of the ghost penalty: gamma E h int [[d_n "
      "du]] . [[d_n dv]] on the faces between two active grid cells of which one is "
      "on the body's boundary, with E the largest Young's modulus of the laws.  It gives the "
      "nodes that a body reaches by a sliver the stiffness of their neighbours, "
      "and vanishes for increments linear across the face (doc/theory.md).  0: none",
      Bounds::nonNegative());
  return valid;
}

Teuchos::ParameterList gridParameters() {
  Teuchos::ParameterList valid;
  declareIntArray(valid, "Cells", {16}, {1, 2, 3},
                  "Number of cells along each direction; its length sets the dimension",
                  Bounds::atLeast(1), true);
  declareDoubleArray(valid, "Length", {1.0}, {1, 2, 3}, "Size of the grid along each direction",
                     Bounds::positive(), true);
  declareDoubleArray(valid, "Origin", {}, {0, 1, 2, 3},
                     "Position of the grid's lower corner (empty: the origin)");
  return valid;
}

}  // namespace

Teuchos::ParameterList deckValidParameters() {
  Teuchos::ParameterList valid("impm");
  valid.sublist("Discretization", false, "How the weak form is integrated") =
      discretizationParameters();
  valid.sublist("Grid", false, "The background grid") = gridParameters();
  valid.sublist("Materials", false, "Constitutive models, one sublist each").sublist("<name>") =
      materialValidParameters();
  valid.sublist("Bodies", false, "Bodies, one sublist each").sublist("<name>") =
      bodyValidParameters();
  valid.sublist("Boundary Conditions", false, "Boundary conditions, one sublist each")
      .sublist("<name>") = boundaryConditionValidParameters();
  valid.sublist("Time Integration", false, "Static load stepping or time stepping") =
      timeIntegrationValidParameters();
  valid.sublist("Solver", false, "Newton and linear solvers") = NewtonSolver::validParameters();
  valid.sublist("Load Balance", false, "The ranks' shares of the grid as the particles move") =
      loadBalanceValidParameters();
  valid.sublist("Output") = outputValidParameters();
  valid.sublist("Verification", false, "Checks against known answers") =
      verificationValidParameters();
  return valid;
}

}  // namespace impm
