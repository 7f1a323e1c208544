#pragma once
// The MPI communicator under a Teuchos one, for the few calls Teuchos does not wrap
// (all-to-all exchanges, MPI-IO).  A serial Teuchos communicator gives MPI_COMM_SELF.

#include <mpi.h>

#include "core/TpetraTypes.hpp"

namespace impm {

MPI_Comm rawComm(const Comm& comm);

}  // namespace impm
