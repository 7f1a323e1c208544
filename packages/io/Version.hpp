#pragma once
// Which impm made a result: its version and the commit it was built from, on the first line of
// every run's log, in the info records of every Exodus file, and with the libraries' versions
// (Trilinos, Kokkos and its execution space, MPI, exodusII, netCDF) in `impm --version`: what a
// bug report or a paper's methods section needs.  The commit is read at build time
// (cmake/Version.cmake): "+changes" marks a build from a work tree that differed from it,
// "unknown" one made outside a git clone.

#include <string>

namespace impm {

// "impm 0.1.0 (commit 0123456789ab, Release build)"
std::string versionLine();

// The version line, then the libraries', one per line.
std::string versionText();

}  // namespace impm
