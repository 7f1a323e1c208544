#pragma once
// The tolerance of each Newton iteration's linear solve: no tighter than Newton needs.
//
// A linear solve that stops at a relative residual eta leaves ||R_(k+1)|| about
// eta ||R_k|| plus the step's nonlinearity.  Newton stops at its target ||R|| <= tau
// (Relative Tolerance times ||R_0||, or Absolute Tolerance), so a solve from ||R_k|| near
// tau needs only eta = 0.5 tau / ||R_k|| to end the iteration (inexact Newton, Dembo,
// Eisenstat and Steihaug 1982).  Solved to Linear Tolerance instead, such an iteration costs
// a full solve: on the 64 x 512 column, where the first iteration of three load steps in ten
// stopped at 1.01 tau, the second took 24 Krylov iterations to move the unknowns by 1e-12 of
// themselves; at 0.5 tau / ||R_k|| it takes 3-4.  The last iteration of a nonlinear step
// (||R_k|| a few decades above tau, its Newton steps converging quadratically) likewise
// needs a few decades, not ten.  So
//   eta = min(0.1, max(Linear Tolerance, 0.5 tau / ||R_k||)):
// Linear Tolerance far from the target (the first iteration with the defaults, where
// 0.5 tau / ||R_0|| = 0.5 Relative Tolerance is below it), and at most 0.1, a tenfold
// reduction, close to it.  The step's result then meets the same target, ||R|| <= tau.

#include <NOX_Observer.hpp>
#include <Teuchos_ParameterList.hpp>

namespace impm {

// The list NOX's Newton direction hands to each linear solve, within the solver's list
// `nox`.  Looked up at each use: a sublist lives in its parent's array of entries, and NOX
// adds entries (defaults) after the solver is built, which may copy it elsewhere.
Teuchos::ParameterList& linearSolveList(Teuchos::ParameterList& nox);

class LinearTarget : public NOX::Observer {
 public:
  // `nox`: the solver's list, whose linear solve "Tolerance" is set before every iteration
  // (it must outlive this observer); `target`: tau, the ||R|| Newton stops at.
  LinearTarget(Teuchos::ParameterList& nox, double linearTolerance, double target)
      : nox_(nox), linearTolerance_(linearTolerance), target_(target) {}

  void runPreIterate(const NOX::Solver::Generic& solver) override;

  // eta for a Newton iteration from a residual of norm `residual`.
  double tolerance(double residual) const;

 private:
  Teuchos::ParameterList& nox_;
  double linearTolerance_, target_;
};

}  // namespace impm
