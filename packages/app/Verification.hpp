#pragma once
// Checks of a run against known answers, written in the deck (Verification sublist): the
// particle RMS displacement error against an exact solution,
//   e = sqrt(sum_p |u_p - u(X_p)|^2 / N_p)   (u_p from eq. 1.23),
// and the boundary forces F(0), F(L).  A failed check makes the driver exit non-zero, so a
// deck with a deliberately wrong expectation proves that the check can fail.

#include <Teuchos_ParameterList.hpp>

#include <string>
#include <vector>

#include "core/Formula.hpp"
#include "core/ParticleSet.hpp"
#include "core/TpetraTypes.hpp"

namespace impm {

Teuchos::ParameterList verificationValidParameters();

struct VerificationResult {
  bool hasExact = false;
  double rmsError = 0.0, maxError = 0.0;
  GlobalId points = 0;
  std::vector<std::string> failures;  // one line per failed check
  std::vector<std::string> report;    // one line per check
};

class Verification {
 public:
  // Throws InputError for a malformed exact solution.
  explicit Verification(const Teuchos::ParameterList& params);

  // Collective.
  template <int Dim>
  VerificationResult check(const ParticleSet<Dim>& particles, const Teuchos::RCP<const Comm>& comm,
                           double time, double F0, double FL) const;

 private:
  bool hasExact_;
  std::vector<Formula> exact_;  // per component
  double maxRms_, expectedF0_, expectedFL_, reactionTolerance_;
};

}  // namespace impm
