#pragma once
// The deck's Solver/NOX list, checked with the deck, before anything is written.  impm's model
// evaluator gives NOX residuals and an assembled Jacobian with its linear solver: a Newton
// direction and a line search along it.  The NOX choices that need more crash or fail deep in
// a run: the Jacobian's transpose (the Steepest Descent and NonlinearCG directions, the trust
// regions' Cauchy steps), a tensor model (Tensor, Tensor Based), directional derivatives of a
// Jacobian NOX has not computed (More'-Thuente), or objects a deck cannot give (Safeguarded
// Step's update limits, User Defined).  They are refused by name; the supported ones are then
// built and run on a one-unknown system, so that a wrong entry anywhere in the list (a bad
// value in a sublist) is an error of the deck too.

#include <string>
#include <vector>

#include <Teuchos_ParameterList.hpp>

#include "core/TpetraTypes.hpp"

namespace impm {

// The supported values of NOX's choices, by their paths in the list.
struct NoxChoice {
  std::string path;  // "Direction/Method"
  std::vector<std::string> supported;
};
const std::vector<NoxChoice>& supportedNoxChoices();

// Throws InputError("Solver/NOX/<path>", ...) for an unsupported choice, and
// InputError("Solver/NOX", NOX's reason) when NOX rejects the list.  Collective.
void checkNoxList(const Teuchos::ParameterList& nox, const Teuchos::RCP<const Comm>& comm);

}  // namespace impm
