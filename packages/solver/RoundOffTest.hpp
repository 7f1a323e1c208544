#pragma once
// Newton's test for a residual at its round-off floor.
//
// The unknowns x are doubles: rounding each x_j by a relative eps moves R(x) by up to
// eps (|K| |x|)_i in row i, K = dR/dx.  A residual below eps || |K| |x| || is as small as any
// floating-point x can make it (its backward error is round-off): further Newton iterations
// do not reduce it, and move x by at most about cond(K) times round-off (the 1-D column
// of 250000 cells: 5e-10 of |x|, below the default Update Tolerance).  On tall grids this
// floor lies above a relative
// tolerance of 1e-10 (the strain sum_i G_ip u_i cancels terms of size |u|/h); without this
// test the step takes one more Newton iteration, a full linear solve, to pass the update test.

#include <NOX_StatusTest_Generic.H>

#include "core/TpetraTypes.hpp"
#include "solver/ResidualModel.hpp"

namespace impm {

// || |K| |x| ||_2, the absolute values taken entry by entry.  Collective.
double absoluteProductNorm(const CrsMatrix& K, const Vector& x);

// Converged when ||R(x_k)|| <= factor * eps * (|| |K| |x_k| || + model.roundOffScale()), K the
// Jacobian of the last Newton iteration (the solver's group holds it as a Tpetra CrsMatrix):
// the rounding of the unknowns and that of the model's own inputs (the stress of a stiff law
// at a small strain, where F - I has lost the digits).  Never on the initial guess; not
// evaluated when an earlier test of a minimal check has already decided.
class RoundOffResidual : public NOX::StatusTest::Generic {
 public:
  RoundOffResidual(double factor, const ResidualModel& model) : factor_(factor), model_(model) {}
  NOX::StatusTest::StatusType checkStatus(const NOX::Solver::Generic& solver,
                                          NOX::StatusTest::CheckType type) override;
  NOX::StatusTest::StatusType getStatus() const override { return status_; }
  std::ostream& print(std::ostream& out, int indent = 0) const override;

 private:
  double factor_, norm_ = 0.0, floor_ = 0.0;
  const ResidualModel& model_;
  NOX::StatusTest::StatusType status_ = NOX::StatusTest::Unevaluated;
};

}  // namespace impm
