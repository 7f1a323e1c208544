#pragma once
// Execution and memory spaces, and the view types every package shares.
//
// Kernels are written as Kokkos parallel patterns over views whose execution space is a
// template parameter (defaulting to Kokkos' default space), so a device build of Trilinos
// needs no rewrite of the kernels.  Host-only work (formula evaluation with muparser,
// file output) is done on host mirrors.

#include <Kokkos_Core.hpp>

namespace impm {

using DefaultExecSpace = Kokkos::DefaultExecutionSpace;
using DefaultMemSpace = DefaultExecSpace::memory_space;

// Global identifiers follow Tpetra's global ordinal (long long in Debian's build).
using GlobalId = long long;

template <class Space>
using RangePolicy = Kokkos::RangePolicy<typename Space::execution_space>;

}  // namespace impm
