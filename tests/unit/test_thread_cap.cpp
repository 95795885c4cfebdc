// The host thread cap (kernels/device/thread_cap.hpp): Kokkos 3.4's OpenMP backend crashed
// at start-up with more than 512 threads, in every command; requests above the cap are
// lowered before Kokkos starts.
#include <gtest/gtest.h>

#include "kernels/device/thread_cap.hpp"

using namespace granshock;

TEST(ThreadCap, IsAFewThreadsPerCpuAndNeverPastKokkosTable) {
  EXPECT_EQ(thread_cap(1), kThreadsPerCpu);
  EXPECT_EQ(thread_cap(2), 2 * kThreadsPerCpu);
  EXPECT_EQ(thread_cap(0), kThreadsPerCpu);  // an affinity mask read as empty
  EXPECT_EQ(thread_cap(100000), kMaxHostThreads);
  EXPECT_LE(kMaxHostThreads, 512);
  EXPECT_GE(available_cpus(), 1);
}

TEST(ThreadCap, LowersOnlyCountsAboveTheCap) {
  EXPECT_EQ(capped_count("1000", 8), "8");
  EXPECT_EQ(capped_count("100000000000000000000", 8), "8");  // past long long
  EXPECT_FALSE(capped_count("8", 8));
  EXPECT_FALSE(capped_count("1", 8));
  EXPECT_FALSE(capped_count("-5", 8));  // Kokkos answers what is not a count
  EXPECT_FALSE(capped_count("many", 8));
  EXPECT_FALSE(capped_count("12x", 8));
  EXPECT_FALSE(capped_count("", 8));
}
