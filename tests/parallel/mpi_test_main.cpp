// GoogleTest entry point for the tests that run under an MPI launcher (ctest starts them
// with mpirun): MPI, then Kokkos, started once for the program, as granshock's main does.
#include <gtest/gtest.h>

#include "device/kokkos_runtime.hpp"
#include "mpi_runtime.hpp"

int main(int argc, char** argv) {
  granshock::MpiRuntime mpi(argc, argv);
  ::testing::InitGoogleTest(&argc, argv);
  granshock::KokkosRuntime kokkos(argc, argv);
  // Only rank 0 prints GoogleTest's report; a failure on any rank still fails the run
  // through its exit code.
  if (mpi.rank() != 0) {
    auto& listeners = ::testing::UnitTest::GetInstance()->listeners();
    delete listeners.Release(listeners.default_result_printer());
  }
  return RUN_ALL_TESTS();
}
