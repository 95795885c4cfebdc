// A Kokkos allocation that fails is a user error of one line (core/allocation_failure.hpp):
// 2.3e8 particles once ended as "internal error: Kokkos failed to allocate 3.4 G", exit 3.
#include <gtest/gtest.h>

#include <Kokkos_Core.hpp>
#include <stdexcept>
#include <string>

#include "core/allocation_failure.hpp"

using namespace granshock;

TEST(AllocationFailure, AFailedKokkosAllocationIsOneLineNamingWhatAndHowMuch) {
  std::string what;
  try {
    // 2^60 bytes: more than any machine has, refused by the allocator at once.
    Kokkos::View<char*> huge("verlet_neighbours", std::size_t(1) << 60);
    FAIL() << "2^60 bytes were allocated";
  } catch (const std::bad_alloc&) {
    GTEST_SKIP() << "this Kokkos reports the failure as std::bad_alloc (already exit 2)";
  } catch (const std::runtime_error& e) {
    what = e.what();
  }
  const auto line = allocation_failure(what);
  ASSERT_TRUE(line.has_value()) << what;
  EXPECT_EQ(line->find('\n'), std::string::npos) << *line;
  EXPECT_EQ(line->rfind("not enough memory: Kokkos could not allocate 'verlet_neighbours' (", 0),
            0u)
      << *line;
  EXPECT_NE(line->find("make the scene smaller"), std::string::npos);
}

TEST(AllocationFailure, OtherErrorsAreNotMistakenForIt) {
  EXPECT_FALSE(allocation_failure("Kokkos::View ERROR: out of bounds"));
  EXPECT_FALSE(allocation_failure(""));
  EXPECT_TRUE(allocation_failure(
      "Kokkos encountered an allocation failure, then another allocation failure while "
      "trying to create the error message."));
}
