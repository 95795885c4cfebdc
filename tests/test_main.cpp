// GoogleTest entry point: Kokkos is initialised once for the whole test program.
#include <gtest/gtest.h>

#include "device/kokkos_runtime.hpp"

int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  granshock::KokkosRuntime kokkos(argc, argv);
  return RUN_ALL_TESTS();
}
