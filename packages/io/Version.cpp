#include "io/Version.hpp"

#include <mpi.h>
#include <netcdf.h>

#include <Trilinos_version.h>
#include <exodusII.h>
#include <Kokkos_Core.hpp>
#include <sstream>

#include "impm/GeneratedVersion.hpp"

namespace impm {

std::string versionLine() {
  return std::string("impm ") + IMPM_VERSION + " (commit " + IMPM_COMMIT + ", " +
         (std::string(IMPM_BUILD_TYPE).empty() ? "default" : IMPM_BUILD_TYPE) + " build)";
}

std::string versionText() {
  char mpi[MPI_MAX_LIBRARY_VERSION_STRING] = {};
  int length = 0;
  MPI_Get_library_version(mpi, &length);
  std::string mpiName(mpi, static_cast<std::size_t>(length));
  mpiName = mpiName.substr(0, mpiName.find_first_of(",\n"));  // the first clause only
  const std::string netcdf = nc_inq_libvers();                // "4.9.0 of <date> $"
  std::ostringstream s;
  s << versionLine() << "\n"
    << "  Trilinos " << TRILINOS_VERSION_STRING << ", Kokkos " << KOKKOS_VERSION / 10000 << "."
    << KOKKOS_VERSION / 100 % 100 << "." << KOKKOS_VERSION % 100 << " ("
    << Kokkos::DefaultExecutionSpace::name() << " execution space)\n"
    << "  " << mpiName << "\n"
    << "  exodusII " << EX_API_VERS << ", netCDF " << netcdf.substr(0, netcdf.find(' ')) << "\n";
  return s.str();
}

}  // namespace impm
