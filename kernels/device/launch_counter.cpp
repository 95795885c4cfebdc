#include "kernels/device/launch_counter.hpp"

#include <Kokkos_Core.hpp>
#include <atomic>
#include <cstring>

namespace granshock {

namespace {

// The hooks are plain functions: the counts of the one running counter.
std::atomic<bool> g_in_use{false};
std::atomic<std::uint64_t> g_kernels{0}, g_reductions{0}, g_fences{0}, g_copies{0},
    g_device_to_host{0}, g_host_reads{0};

bool ends_with(std::string_view text, std::string_view end) {
  return text.size() >= end.size() && text.substr(text.size() - end.size()) == end;
}

void on_kernel(const char*, std::uint32_t, std::uint64_t* id) {
  *id = 0;
  ++g_kernels;
}

void on_reduction(const char* name, std::uint32_t device, std::uint64_t* id) {
  on_kernel(name, device, id);
  ++g_reductions;
  if (!ends_with(name, result_on_device_suffix)) ++g_host_reads;
}

void on_fence(const char*, std::uint32_t, std::uint64_t* id) {
  *id = 0;
  ++g_fences;
}

void on_deep_copy(Kokkos::Tools::SpaceHandle dst, const char* dst_label, const void*,
                  Kokkos::Tools::SpaceHandle src, const char*, const void*, std::uint64_t) {
  ++g_copies;
  const bool into_host = std::strcmp(dst.name, "Host") == 0;
  const bool across = into_host && std::strcmp(src.name, "Host") != 0;
  if (across) ++g_device_to_host;
  if (across ||
      (into_host && (std::string_view(dst_label) == "Scalar" || ends_with(dst_label, "_mirror"))))
    ++g_host_reads;
}

void set_hooks(bool on) {
  namespace tools = Kokkos::Tools::Experimental;
  tools::set_begin_parallel_for_callback(on ? on_kernel : nullptr);
  tools::set_begin_parallel_reduce_callback(on ? on_reduction : nullptr);
  tools::set_begin_parallel_scan_callback(on ? on_kernel : nullptr);
  tools::set_begin_fence_callback(on ? on_fence : nullptr);
  tools::set_begin_deep_copy_callback(on ? on_deep_copy : nullptr);
}

LaunchCounts current(bool fences_reported) {
  return {g_kernels,        g_reductions, g_fences,       g_copies,
          g_device_to_host, g_host_reads, fences_reported};
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
  g_kernels = g_reductions = g_fences = g_copies = g_device_to_host = g_host_reads = 0;
  running_ = true;
  return true;
}

LaunchCounts LaunchCounter::counts() const {
  if (!running_) return final_;
  return current(fences_reported_);
}

LaunchCounts LaunchCounter::stop() {
  if (!running_) return final_;
  set_hooks(false);
  final_ = current(fences_reported_);
  running_ = false;
  g_in_use = false;
  return final_;
}

}  // namespace granshock
