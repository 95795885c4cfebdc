// What a stretch of stepping costs the device beyond its arithmetic (docs/cuda.md, "Launches
// per step"): the kernels launched (parallel_for, parallel_reduce, parallel_scan), the
// fences, and the deep copies, counted through Kokkos' profiling hooks while a counter is
// running. `deep_copies` counts every Kokkos::deep_copy, fills of a value included. On a
// GPU build a copy into host memory from another space is a device-to-host read; on host
// builds no copy crosses spaces, and `deep_copies` shows the copies that a GPU build of
// the same paths would make (-DGRANSHOCK_DEVICE_PATHS=ON runs them). Fences are those
// Kokkos reports to its tools, where it reports them (LaunchCounts::fences_reported).
//
// `host_reads` counts what makes the host wait for the device's values, in every build, as
// a GPU build would: a parallel_reduce into a host value (a fence and a device-to-host read
// on a GPU), unless its name ends in result_on_device_suffix (the result stays in a device
// View); and a deep copy into host memory from another space, into a host scalar, or into
// a mirror (Kokkos labels create_mirror's Views "<label>_mirror"): the copies
// host_mirror.hpp's host_copy makes on device paths, which on a host build are copies
// within host memory.
//
// The hooks are Kokkos' tool interface: where a profiling tool is loaded (KOKKOS_TOOLS_LIBS)
// the counter stays off rather than replace the tool's callbacks.
#pragma once

#include <cstdint>
#include <string_view>

namespace granshock {

// The end of the name of a reduction whose result stays in device memory.
inline constexpr std::string_view result_on_device_suffix = "->device";

struct LaunchCounts {
  std::uint64_t kernels = 0;
  // Of them, parallel_reduce: on a GPU a reduction into a host value is also a fence and a
  // device-to-host read, which the deep-copy hook does not see.
  std::uint64_t reductions = 0;
  std::uint64_t fences = 0;
  std::uint64_t deep_copies = 0;
  std::uint64_t device_to_host_copies = 0;  // into host memory from another memory space
  std::uint64_t host_reads = 0;             // waits for device values (above)
  // Whether this Kokkos reports fences to its tools at all (Kokkos 3.4 does not: its
  // fence hook is never called; 4.x calls it for every fence).
  bool fences_reported = false;
};

// Counts from start() to stop() (or its end). One counter at a time in a process: a second
// start() while one runs leaves the first counting and this one off.
class LaunchCounter {
 public:
  LaunchCounter() = default;
  LaunchCounter(const LaunchCounter&) = delete;
  LaunchCounter& operator=(const LaunchCounter&) = delete;
  ~LaunchCounter() { stop(); }

  // False (and nothing counted) where a profiling tool is loaded or another counter runs.
  bool start();
  LaunchCounts stop();
  bool running() const { return running_; }
  // The counts so far (while running), or at stop().
  LaunchCounts counts() const;

 private:
  bool running_ = false;
  bool fences_reported_ = false;
  LaunchCounts final_;
};

}  // namespace granshock
