// Large blocks kept for reuse (core/large_blocks.hpp): once set, a block above glibc's own
// 32 MB limit that is freed and allocated again reuses the pages the process has, with no
// page fault; before, every such allocation faulted once per page (a checkpoint of a paper
// case copied its 42 MB of field sums into fresh pages three times: 0.4 s per checkpoint).
#include <gtest/gtest.h>
#include <sys/resource.h>

#include <cstring>
#include <memory>

#include "core/large_blocks.hpp"

using namespace granshock;

namespace {

long minor_faults() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return u.ru_minflt;
}

// Faults while a fresh block of `bytes` is allocated, written through and freed.
long faults_of_a_block(std::size_t bytes) {
  const long before = minor_faults();
  {
    std::unique_ptr<char[]> block(new char[bytes]);
    std::memset(block.get(), 1, bytes);
    // Read back, so that the writes cannot be dropped.
    EXPECT_EQ(block[bytes - 1], 1);
  }
  return minor_faults() - before;
}

}  // namespace

TEST(LargeBlocks, AFreedBlockOfFortyEightMegabytesIsReusedWithoutPageFaults) {
#if !defined(__GLIBC__)
  GTEST_SKIP() << "only glibc's malloc is tuned";
#else
  ASSERT_TRUE(keep_large_blocks());
  const std::size_t bytes = std::size_t(48) << 20;
  const long pages = long(bytes / 4096);
  const long first = faults_of_a_block(bytes);
  const long second = faults_of_a_block(bytes);
  const long third = faults_of_a_block(bytes);
  // The first may fault on every page (the heap grows); the later ones reuse them. A few
  // faults may come from elsewhere in the process (gtest's output).
  EXPECT_LT(second, pages / 100) << "first " << first << " of " << pages << " pages";
  EXPECT_LT(third, pages / 100);
#endif
}
