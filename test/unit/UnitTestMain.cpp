// One main for every unit-test executable: initialises MPI and Kokkos through Tpetra,
// prints from rank 0 only, and fails on every rank if a test failed on any rank.

#include <gtest/gtest.h>

#include <Tpetra_Core.hpp>

#include <mpi.h>

int main(int argc, char** argv) {
  Tpetra::ScopeGuard scope(&argc, &argv);
  ::testing::InitGoogleTest(&argc, argv);
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  if (rank != 0) {
    auto& listeners = ::testing::UnitTest::GetInstance()->listeners();
    delete listeners.Release(listeners.default_result_printer());
  }
  const int local = RUN_ALL_TESTS();
  int global = 0;
  MPI_Allreduce(&local, &global, 1, MPI_INT, MPI_MAX, MPI_COMM_WORLD);
  if (rank == 0 && global != local)
    std::printf("[  FAILED  ] on another rank\n");
  return global;
}
