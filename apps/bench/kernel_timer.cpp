// A Kokkos profiling tool that times every kernel by name: load it into any granshock
// program with
//   KOKKOS_PROFILE_LIBRARY=build/apps/bench/libgranshock_kernel_timer.so granshock run ...
// and it prints, when Kokkos finalises, each kernel's calls, total seconds, share of the
// wall time since Kokkos started and microseconds per call (stderr, largest first).
// Host backends run kernels synchronously, so the times are the kernels' wall times; on a
// GPU they are launch times unless the program fences (CUDA_LAUNCH_BLOCKING=1 makes them
// complete). What the time between kernels goes to (host work, I/O) is the remainder.
// The entry points are Kokkos' C profiling interface (Kokkos_Profiling_C_Interface.h).
#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <map>
#include <mutex>
#include <string>
#include <vector>

namespace {

using Clock = std::chrono::steady_clock;

struct KernelTime {
  long calls = 0;
  double seconds = 0;
};

struct Timer {
  Clock::time_point started = Clock::now();
  std::map<std::string, KernelTime> by_name;
  std::vector<std::pair<std::string, Clock::time_point>> open;  // by kernel id
  std::mutex lock;

  void begin(const char* name, uint64_t* id) {
    std::lock_guard<std::mutex> guard(lock);
    *id = open.size();
    open.emplace_back(name, Clock::now());
  }
  void end(uint64_t id) {
    const auto now = Clock::now();
    std::lock_guard<std::mutex> guard(lock);
    if (id >= open.size()) return;
    KernelTime& k = by_name[open[id].first];
    ++k.calls;
    k.seconds += std::chrono::duration<double>(now - open[id].second).count();
    if (id + 1 == open.size()) open.pop_back();
  }
  void report() const {
    const double wall = std::chrono::duration<double>(Clock::now() - started).count();
    std::vector<std::pair<std::string, KernelTime>> rows(by_name.begin(), by_name.end());
    std::sort(rows.begin(), rows.end(),
              [](const auto& a, const auto& b) { return a.second.seconds > b.second.seconds; });
    double kernels = 0;
    for (const auto& r : rows) kernels += r.second.seconds;
    std::fprintf(stderr, "\nkernel times (wall %.3f s, in kernels %.3f s = %.1f %%)\n", wall,
                 kernels, 100 * kernels / wall);
    std::fprintf(stderr, "%10s %12s %7s %10s  %s\n", "calls", "seconds", "% wall", "us/call",
                 "kernel");
    for (const auto& [name, k] : rows)
      std::fprintf(stderr, "%10ld %12.4f %7.2f %10.2f  %.100s\n", k.calls, k.seconds,
                   100 * k.seconds / wall, 1e6 * k.seconds / double(k.calls), name.c_str());
  }
};

Timer* timer = nullptr;

}  // namespace

extern "C" {

struct Kokkos_Profiling_KokkosPDeviceInfo;

void kokkosp_init_library(int, uint64_t, uint32_t, Kokkos_Profiling_KokkosPDeviceInfo*) {
  timer = new Timer;
}
void kokkosp_finalize_library() {
  if (!timer) return;
  timer->report();
  delete timer;
  timer = nullptr;
}
void kokkosp_begin_parallel_for(const char* name, uint32_t, uint64_t* id) {
  timer->begin(name, id);
}
void kokkosp_end_parallel_for(uint64_t id) {
  timer->end(id);
}
void kokkosp_begin_parallel_reduce(const char* name, uint32_t, uint64_t* id) {
  timer->begin(name, id);
}
void kokkosp_end_parallel_reduce(uint64_t id) {
  timer->end(id);
}
void kokkosp_begin_parallel_scan(const char* name, uint32_t, uint64_t* id) {
  timer->begin(name, id);
}
void kokkosp_end_parallel_scan(uint64_t id) {
  timer->end(id);
}
}
