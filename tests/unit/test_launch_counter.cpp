// The launch counter (kernels/device/launch_counter.hpp) against a known sequence of
// kernels, fences and copies: what it counts per step of a run is what summary.json and
// docs/cuda.md ("Launches per step") report. The kernels here are Kokkos' own fills
// (deep_copy of a value is one kernel launch): tests hold no device code (.ci/run).
#include <gtest/gtest.h>

#include <Kokkos_Core.hpp>
#include <type_traits>

#include "kernels/device/launch_counter.hpp"

using namespace granshock;

namespace {

// 3 fills (one kernel and one deep_copy each), 4 copies between small Views (no kernel),
// and `fences` fences.
LaunchCounts run_sequence(int fences) {
  Kokkos::View<double*> a("a", 8), b("b", 8);
  Kokkos::fence();
  LaunchCounter counter;
  EXPECT_TRUE(counter.start());
  for (int k = 0; k < 3; ++k) Kokkos::deep_copy(a, 1.5 + k);
  for (int k = 0; k < 4; ++k) Kokkos::deep_copy(k % 2 ? a : b, k % 2 ? b : a);
  for (int k = 0; k < fences; ++k) Kokkos::fence();
  return counter.stop();
}

}  // namespace

TEST(LaunchCounter, CountsAKnownSequence) {
  const LaunchCounts without = run_sequence(0), with = run_sequence(2);
  EXPECT_EQ(without.kernels, 3u);
  EXPECT_EQ(with.kernels, 3u);
  EXPECT_EQ(without.deep_copies, 7u);
  EXPECT_EQ(with.deep_copies, 7u);
  // Kokkos may fence inside a copy itself: the two explicit ones come on top, where this
  // Kokkos reports fences at all (3.4 does not, and none is counted).
  if (with.fences_reported)
    EXPECT_EQ(with.fences - without.fences, 2u);
  else
    EXPECT_EQ(with.fences, 0u);
  // One memory space on a host build; a GPU build's copies here stay on the device too.
  EXPECT_EQ(without.device_to_host_copies, 0u);
}

TEST(LaunchCounter, CountsNothingOnceStoppedAndOneAtATime) {
  Kokkos::View<double*> a("a", 4);
  LaunchCounter first, second;
  ASSERT_TRUE(first.start());
  EXPECT_FALSE(second.start()) << "two counters would share the hooks";
  Kokkos::deep_copy(a, 2.0);
  const LaunchCounts at_stop = first.stop();
  Kokkos::deep_copy(a, 3.0);
  EXPECT_EQ(at_stop.kernels, 1u);
  EXPECT_EQ(at_stop.reductions, 0u);
  EXPECT_EQ(first.counts().kernels, 1u);
  EXPECT_TRUE(second.start()) << "free again once the first stopped";
  second.stop();
}

// A copy into host memory from a device's: the device-to-host read a GPU step avoids.
TEST(LaunchCounter, ACopyToTheHostFromAnotherSpaceIsADeviceToHostRead) {
  Kokkos::View<double*> device("device", 8);
  auto host = Kokkos::create_mirror(device);  // a host copy even where the spaces agree
  LaunchCounter counter;
  ASSERT_TRUE(counter.start());
  Kokkos::deep_copy(host, device);
  const LaunchCounts c = counter.stop();
  EXPECT_EQ(c.deep_copies, 1u);
  constexpr bool same =
      std::is_same_v<Kokkos::DefaultExecutionSpace::memory_space, Kokkos::HostSpace>;
  EXPECT_EQ(c.device_to_host_copies, same ? 0u : 1u);
}

// What makes the host wait (host_reads): a copy into a host value, or into a mirror, as
// device paths read device Views on any build; not a fill, nor a copy between two Views
// of the device. (Reductions into a device View, named "...->device", are checked with
// the solver's kernels: ChainedSteps.TwoLaunchesPerStepAndOneHostReadPerChain.)
TEST(LaunchCounter, HostReadsAreCopiesIntoHostValuesAndMirrors) {
  Kokkos::View<double*> device("device", 8), other("other", 8);
  Kokkos::View<double> scalar("scalar");
  auto mirror = Kokkos::create_mirror(device);
  LaunchCounter counter;
  ASSERT_TRUE(counter.start());
  Kokkos::deep_copy(device, 1.0);     // a fill
  Kokkos::deep_copy(other, device);   // within the device's memory
  Kokkos::deep_copy(device, mirror);  // host to device: a write
  const LaunchCounts writes = counter.counts();
  double value = 0;
  Kokkos::deep_copy(value, scalar);   // a host value
  Kokkos::deep_copy(mirror, device);  // a mirror
  const LaunchCounts c = counter.stop();
  EXPECT_EQ(writes.host_reads, 0u);
  EXPECT_EQ(c.host_reads, 2u);
  EXPECT_EQ(c.deep_copies, 5u);
}
