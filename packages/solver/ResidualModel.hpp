#pragma once
// A discrete nonlinear system R(x) = 0 over Tpetra, as the Newton solver sees it: a map of
// unknowns, a Jacobian with a fixed graph, and an evaluation of R and/or dR/dx.

#include "core/TpetraTypes.hpp"

namespace impm {

class ResidualModel {
 public:
  virtual ~ResidualModel() = default;
  // Distribution of the unknowns (and of the residual).
  virtual Teuchos::RCP<const Map> unknownMap() const = 0;
  // A matrix with the Jacobian's graph, to be filled by evaluate().
  virtual Teuchos::RCP<CrsMatrix> createJacobian() const = 0;
  // Fills the residual and/or the Jacobian at x; either pointer may be null.  Collective.
  virtual void evaluate(const Vector& x, Vector* residual, CrsMatrix* jacobian) = 0;
  // True when R is affine in x: one Newton step with a converged linear solve solves it.
  virtual bool isLinear() const { return false; }
  // The near-null space of the Jacobian's stiffness on unknownMap() (rigid-body modes, for
  // multigrid), or null when the model has none to offer.
  virtual Teuchos::RCP<MultiVector> nearNullSpace() const { return Teuchos::null; }
  // The 2-norm of how far R moves, per unit relative rounding, when its nonlinear terms are
  // evaluated at inputs rounded to doubles, at the last evaluation (0: nothing beyond the
  // rounding of x).  Newton's round-off test adds it times eps to eps || |K| |x| ||.
  // Collective.
  virtual double roundOffScale() const { return 0.0; }
};

}  // namespace impm
