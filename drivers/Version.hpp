#pragma once
// What `impm --version` prints: impm's version and commit, the build type, and the versions
// of the libraries it was built with (Trilinos, Kokkos and its execution space) and runs with
// (MPI, netCDF): what a bug report or a paper's methods section needs.

#include <string>

namespace impm {

std::string versionText();

}  // namespace impm
