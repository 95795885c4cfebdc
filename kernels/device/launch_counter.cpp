#include "kernels/device/launch_counter.hpp"

#include <Kokkos_Core.hpp>
#include <atomic>
#include <cstring>

namespace granshock {

namespace {

// The hooks are plain functions: the counts of the one running counter.
std::atomic<bool> g_in_use{false};
std::atomic<std::uint64_t> g_kernels{0}, g_reductions{0}, g_fences{0}, g_copies{0},
    g_device_to_host{0};

void on_kernel(const char*, std::uint32_t, std::uint64_t* id) {
  *id = 0;
  ++g_kernels;
}

void on_reduction(const char* name, std::uint32_t device, std::uint64_t* id) {
  on_kernel(name, device, id);
  ++g_reductions;
}

void on_fence(const char*, std::uint32_t, std::uint64_t* id) {
  *id = 0;
  ++g_fences;
}

void on_deep_copy(Kokkos::Tools::SpaceHandle dst, const char*, const void*,
                  Kokkos::Tools::SpaceHandle src, const char*, const void*, std::uint64_t) {
  ++g_copies;
  if (std::strcmp(dst.name, "Host") == 0 && std::strcmp(src.name, "Host") != 0) ++g_device_to_host;
}

void set_hooks(bool on) {
  namespace tools = Kokkos::Tools::Experimental;
  tools::set_begin_parallel_for_callback(on ? on_kernel : nullptr);
  tools::set_begin_parallel_reduce_callback(on ? on_reduction : nullptr);
  tools::set_begin_parallel_scan_callback(on ? on_kernel : nullptr);
  tools::set_begin_fence_callback(on ? on_fence : nullptr);
  tools::set_begin_deep_copy_callback(on ? on_deep_copy : nullptr);
}

}  // namespace

bool LaunchCounter::start() {
  if (running_ || Kokkos::Tools::profileLibraryLoaded()) return false;
  bool expected = false;
  if (!g_in_use.compare_exchange_strong(expected, true)) return false;
  g_fences = 0;
  set_hooks(true);
  Kokkos::fence();  // whether this Kokkos reports a fence to its tools
  fences_reported_ = g_fences > 0;
  g_kernels = g_reductions = g_fences = g_copies = g_device_to_host = 0;
  running_ = true;
  return true;
}

LaunchCounts LaunchCounter::counts() const {
  if (!running_) return final_;
  return {g_kernels.load(), g_reductions.load(),     g_fences.load(),
          g_copies.load(),  g_device_to_host.load(), fences_reported_};
}

LaunchCounts LaunchCounter::stop() {
  if (!running_) return final_;
  set_hooks(false);
  final_ = {g_kernels.load(), g_reductions.load(),     g_fences.load(),
            g_copies.load(),  g_device_to_host.load(), fences_reported_};
  running_ = false;
  g_in_use = false;
  return final_;
}

}  // namespace granshock
