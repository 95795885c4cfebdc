#include "kernels/device/thread_cap.hpp"

#include <sched.h>

#include <Kokkos_Core.hpp>
#include <algorithm>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <deque>
#include <iostream>
#include <thread>
#if defined(KOKKOS_ENABLE_OPENMP)
#include <omp.h>
#endif

#include "core/quoted_input.hpp"

namespace granshock {

namespace {

void say_capped(const std::string& what, const std::string& asked, int cap) {
  std::cerr << "granshock: note: " << what << " asks for " << asked << " threads; capped at " << cap
            << " (" << kThreadsPerCpu << " per available CPU, at most " << kMaxHostThreads << ")\n";
}

}  // namespace

int thread_cap(int cpus) {
  return int(std::clamp(long(kThreadsPerCpu) * std::max(cpus, 1), 1L, long(kMaxHostThreads)));
}

int available_cpus() {
  cpu_set_t set;
  CPU_ZERO(&set);
  if (sched_getaffinity(0, sizeof set, &set) == 0 && CPU_COUNT(&set) > 0) return CPU_COUNT(&set);
  return int(std::max(1u, std::thread::hardware_concurrency()));
}

std::optional<std::string> capped_count(const std::string& text, int cap) {
  errno = 0;
  char* end = nullptr;
  const long long n = std::strtoll(text.c_str(), &end, 10);
  const bool number = !text.empty() && end && *end == '\0';
  if (!number || (errno == ERANGE && n < 0) || (errno != ERANGE && n <= cap)) return std::nullopt;
  return std::to_string(cap);
}

void cap_host_threads(int argc, char** argv) {
  const int cap = thread_cap(available_cpus());
#if defined(KOKKOS_ENABLE_OPENMP)
  // OMP_NUM_THREADS as the OpenMP runtime read it (also "8,2" lists), or all CPUs.
  // The variable's own text as well as the runtime's count: a number past int wraps in the
  // runtime (99999999999 reads as 1215752191 threads, 4294967297 as 1).
  const char* omp_env = std::getenv("OMP_NUM_THREADS");
  const bool env_past_cap = omp_env && capped_count(omp_env, cap);
  if (const int asked = omp_get_max_threads(); asked > cap || env_past_cap) {
    say_capped(omp_env ? "OMP_NUM_THREADS" : "the OpenMP runtime",
               omp_env ? printable_line(omp_env, 64) : std::to_string(asked), cap);
    omp_set_num_threads(cap);
  }
#endif
  if (const char* env = std::getenv("KOKKOS_NUM_THREADS")) {
    if (const auto capped = capped_count(env, cap)) {
      say_capped("KOKKOS_NUM_THREADS", printable_line(env, 64), cap);
      setenv("KOKKOS_NUM_THREADS", capped->c_str(), 1);
    }
  }
  // The rewritten arguments must outlive Kokkos' reading of argv.
  static std::deque<std::string> rewritten;
  for (int k = 1; k < argc; ++k) {
    for (const char* flag : {"--kokkos-threads=", "--kokkos-num-threads="}) {
      const std::size_t length = std::strlen(flag);
      if (std::strncmp(argv[k], flag, length) != 0) continue;
      if (const auto capped = capped_count(argv[k] + length, cap)) {
        say_capped(std::string(flag, length - 1), printable_line(argv[k] + length, 64), cap);
        rewritten.push_back(flag + *capped);
        argv[k] = rewritten.back().data();
      }
    }
  }
}

}  // namespace granshock
