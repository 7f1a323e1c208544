#pragma once
// A 1-D law written in the deck: sigma = xi(eps, x) as a muparser formula of the strain eps
// (= F - 1) and the reference position x (primer eq. 1.54: the black box).  Its tangent is
// a second formula, or else a central difference of the first with step
// delta = eps_machine^(1/3) max(|eps|, 1e-3), which balances truncation (delta^2) against
// round-off (eps_machine / delta) for laws that bend on the scale of the strain (doc/theory.md
// gives the error).  Evaluated on the host.

#include <Teuchos_ParameterList.hpp>

#include "core/Formula.hpp"
#include "material/Material.hpp"

namespace impm {

class FormulaLaw1D : public Material<1> {
 public:
  static const char* model() { return "formula"; }
  static Teuchos::ParameterList validParameters();

  FormulaLaw1D(const std::string& name, const Teuchos::ParameterList& params);
  void initialize(const Evaluation& at) const override;
  void firstPiola(const Evaluation& at, Tensors& P, Tangents& A) const override;
  void energyDensity(const Evaluation& at, Scalars& W) const override;
  double maxModulus(const Evaluation& at) const override;

  // sigma and dsigma/deps at strain e and position x.
  double stress(double e, double x) const { return stress_(e, x); }
  double tangent(double e, double x) const;

 private:
  Formula stress_, tangent_;
  bool analyticTangent_;
};

}  // namespace impm
