#pragma once
// Static load stepping: the loads (body forces, tractions, Robin gamma, prescribed
// displacements) are scaled by a load factor lambda(s), a function of the pseudo-time s that
// runs from 0 to 1 in Time Integration/Load Steps equal increments (Load Path; lambda = s by
// default, a ramp; a path that rises and falls loads and unloads a plastic body); each
// increment is a Newton solve of the grid system.  A failed
// increment is halved and retried, down to Minimum Load Increment, after which the run stops
// with the Newton history.  Formulas are evaluated at t = Final Time.

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

 private:
  double time_;
  Formula loadPath_;  // lambda(s)
};

}  // namespace impm
