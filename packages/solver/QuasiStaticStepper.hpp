#pragma once
// Static load stepping: the loads (body forces, tractions, Robin gamma, prescribed
// displacements) are scaled by a load factor lambda(s), a function of the pseudo-time s that
// runs from 0 to 1 in Time Integration/Load Steps equal increments (Load Path; lambda = s by
// default, a ramp; a path that rises and falls loads and unloads a plastic body); each
// increment is a Newton solve of the grid system.  A failed
// increment is halved and retried, down to Minimum Load Increment, after which the run stops
// with the Newton history.  Formulas are evaluated at t = Final Time.
//
// Newton's guess (Predictor): with "extrapolate", the last accepted increment per unit load
// factor times this step's load factor increment, on the nodes the two steps share (zero on
// the others), the prescribed increments imposed over it.  Near a limit load the zero guess
// puts the whole step's motion on the prescribed nodes, and the first Newton iterations
// then distort the cells beside them (line-search cuts, cut-back steps); the extrapolated
// one starts from the mechanism of the last step.  Checkpoints keep it (StepperState), so a
// restarted run takes the same guesses.

#include <Teuchos_ParameterList.hpp>

#include "core/Formula.hpp"
#include "solver/Stepper.hpp"

namespace impm {

template <int Dim>
class QuasiStaticStepper : public Stepper<Dim> {
 public:
  QuasiStaticStepper(const Teuchos::ParameterList& timeIntegration, StepperSetup<Dim> setup);

  // Runs the load steps left (all of them, or those after a restored state); calls onStep
  // after each accepted one.  Throws NumericalError when an increment fails at the smallest
  // size.
  void run(const StepCallback<Dim>& onStep) override;
  bool finished() const override;
  // The accepted state with the predictor's increment per unit load factor (nodalDofs,
  // nodalU).
  StepperState checkpointState() const override;

 private:
  // Newton's guess for a step of load factor increment dLambda on `system`.  Collective.
  Teuchos::RCP<Vector> guess(GridSystem<Dim>& system, double dLambda);
  // Keeps du / dLambda of the accepted step for the next guess.
  void keepRate(const GridSystem<Dim>& system, const Vector& du, double dLambda);

  double time_;
  Formula loadPath_;  // lambda(s)
  bool extrapolate_;
  // The last accepted increment per unit load factor on that step's unknowns (null: none,
  // or a step of no load factor increment), and the unknowns it leaves out of checkpoints.
  Teuchos::RCP<Vector> rate_;
  std::vector<GO> ratePadding_;
};

}  // namespace impm
