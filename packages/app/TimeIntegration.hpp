#pragma once
// The deck's Time Integration sublist: static load stepping, implicit Newmark or explicit
// time stepping, and the settings each takes.

#include <Teuchos_ParameterList.hpp>

#include "solver/DynamicStepper.hpp"

namespace impm {

Teuchos::ParameterList timeIntegrationValidParameters();

bool isStatic(const Teuchos::ParameterList& timeIntegration);
DynamicSettings dynamicSettings(const Teuchos::ParameterList& timeIntegration);

}  // namespace impm
