// GoogleTest entry point: Kokkos is initialised once for the whole test program.
#include <gtest/gtest.h>

#include "io/hdf5_runtime.hpp"
#include "kernels/device/kokkos_runtime.hpp"

int main(int argc, char** argv) {
  // As granshock's main(): a test of a full disk leaves a file whose close failed, which
  // HDF5 would crash on flushing at exit.
  granshock::h5::keep_exit_free_of_hdf5();
  ::testing::InitGoogleTest(&argc, argv);
  // Listing the tests (ctest's discovery) starts no backend, so that a CUDA build's test
  // programs list their tests on a machine without a GPU (docs/cuda.md, "Test discovery").
  if (GTEST_FLAG_GET(list_tests)) return RUN_ALL_TESTS();
  granshock::KokkosRuntime kokkos(argc, argv);
  return RUN_ALL_TESTS();
}
