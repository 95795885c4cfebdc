// How many host threads granshock lets Kokkos start (docs/stability.md, "Limits"). Kokkos
// 3.4's OpenMP backend keeps its per-thread data in a fixed table of 512 entries
// (OpenMPExec::MAX_THREAD_COUNT) and writes past it when started with more threads, which
// crashes every command at start-up; and more threads than a few per available CPU only
// make each parallel region wait for threads that are not running. So a request above
// thread_cap() is lowered to it, with a note on stderr, before Kokkos starts.
#pragma once

#include <optional>
#include <string>

namespace granshock {

inline constexpr int kMaxHostThreads = 512;  // Kokkos 3.4's OpenMP thread table
inline constexpr int kThreadsPerCpu = 4;     // oversubscription still allowed, for tests

// The most threads on `cpus` available CPUs: kThreadsPerCpu per CPU, at most
// kMaxHostThreads.
int thread_cap(int cpus);

// The CPUs this process may run on (its affinity mask), at least 1.
int available_cpus();

// A thread count given as text (an environment variable, a --kokkos-threads value) lowered
// to `cap`: the capped count as text, or nothing when it is not a number above the cap
// (Kokkos itself then answers it).
std::optional<std::string> capped_count(const std::string& text, int cap);

// Lowers every thread request above thread_cap(available_cpus()) before Kokkos starts:
// the OpenMP runtime's (OMP_NUM_THREADS), KOKKOS_NUM_THREADS and the arguments
// --kokkos-threads=N / --kokkos-num-threads=N (rewritten in argv). Says so on stderr, one
// line per request lowered.
void cap_host_threads(int argc, char** argv);

}  // namespace granshock
