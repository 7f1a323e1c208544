#pragma once
// Failures that one rank detects alone (a formula out of range at one of its particles, a
// particle leaving the grid) must stop every rank, or the others would wait forever in
// the next collective call.  collectively() runs a phase on every rank and, if it threw
// anywhere, throws the same error (the lowest failing rank's) on every rank.

#include <functional>
#include <vector>

#include "core/TpetraTypes.hpp"
#include "core/Types.hpp"

namespace impm {

void collectively(const Comm& comm, const std::function<void()>& phase);

// A map with every index 0..n-1 on rank 0 and none elsewhere: the target of an Import that
// gathers a distributed vector to the rank that writes a file.
Teuchos::RCP<const Map> rootMap(GlobalId n, const Teuchos::RCP<const Comm>& comm);

// Whether `mine` holds on every rank (a decision every rank must take alike).  Collective.
bool onEveryRank(bool mine, const Comm& comm);

// Every rank's values, concatenated in rank order, on every rank (counts may differ).
std::vector<double> gatherToAll(const Comm& comm, const std::vector<double>& local);

}  // namespace impm
