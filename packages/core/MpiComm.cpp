#include "core/MpiComm.hpp"

#include <Teuchos_DefaultMpiComm.hpp>

namespace impm {

MPI_Comm rawComm(const Comm& comm) {
  const auto* mpi = dynamic_cast<const Teuchos::MpiComm<int>*>(&comm);
  return mpi ? (*mpi->getRawMpiComm())() : MPI_COMM_SELF;
}

}  // namespace impm
