#pragma once
// Failures that one rank detects alone (a formula out of range at one of its particles, a
// particle leaving the grid) must stop every rank, or the others would wait forever in
// the next collective call.  collectively() runs a phase on every rank and, if it threw
// anywhere, throws the same error (the lowest failing rank's) on every rank.

#include <functional>

#include "core/TpetraTypes.hpp"

namespace impm {

void collectively(const Comm& comm, const std::function<void()>& phase);

}  // namespace impm
