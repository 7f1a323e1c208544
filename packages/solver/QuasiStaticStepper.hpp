#pragma once
// Static load stepping: the loads (body forces and Robin gamma) are ramped by a load factor
// from 0 to 1 in Time Integration/Load Steps equal increments; each increment is a Newton
// solve of the grid system.  A failed increment is halved and retried, down to
// Minimum Load Increment, after which the run stops with the Newton history.  Formulas
// are evaluated at t = Final Time.

#include <Teuchos_ParameterList.hpp>

#include "solver/GridSystem.hpp"
#include "solver/StepperContext.hpp"

namespace impm {

template <int Dim>
class QuasiStaticStepper {
 public:
  QuasiStaticStepper(const Teuchos::ParameterList& timeIntegration, StepperContext<Dim> context);

  // Runs every load step; calls onStep after each accepted one.  Throws NumericalError when
  // an increment fails at the smallest size.
  void run(const StepCallback<Dim>& onStep);

 private:
  StepperContext<Dim> ctx_;
  int steps_;
  double minIncrement_, time_;
  double bodyWork_ = 0.0;
  std::ostream* log_;
};

}  // namespace impm
