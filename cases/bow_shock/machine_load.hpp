// Whether other processes keep this machine's CPUs busy at the start of a run
// (docs/benchmarks.md, "A busy machine"). A threaded step beside them waits at every
// barrier for a descheduled thread; the backend switch finds that out from measured rates
// after half a second, which a short run pays in full, and the calibrations before the
// time loop have no switch. Read from the runnable tasks of the other processes
// (/proc/PID/task/TID/stat) against the CPUs this process may run on (sched_getaffinity).
// Tasks at a low priority count too: a build at nice 15 beside an otherwise idle 2-core
// machine still took time slices long enough for the threads' barriers to wait on, and
// two threads ran slower than one (measured in docs/benchmarks.md, "A busy machine").
#pragma once

#include <optional>
#include <string>

namespace granshock {

struct MachineLoad {
  int others_running = 0;  // runnable tasks of other processes
  int cpus = 1;            // CPUs this process may run on
};

// A task's scheduling state ('R' runnable, 'S' sleeping, ...) from the text of its /proc
// stat file; nullopt where the text is not one.
std::optional<char> task_state(const std::string& stat);

// The runnable tasks of every process under `proc` (the /proc tree) other than `self`;
// nullopt where `proc` cannot be listed.
std::optional<int> others_running(const std::string& proc, long self);

// The fewest runnable tasks of other processes over `samples` readings `gap_ms` apart (a
// process that runs for a moment is no load), or nullopt where /proc cannot be read.
std::optional<MachineLoad> measure_machine_load(int samples = 3, int gap_ms = 5);

// Whether `threads` threads would share the CPUs with the others' tasks: then one thread
// runs faster than the threads would.
inline bool threads_would_wait(const MachineLoad& load, int threads) {
  return load.others_running + threads > load.cpus;
}

// The load measured now where it leaves `threads` threads no room; nullopt where they
// have room or /proc cannot tell.
inline std::optional<MachineLoad> load_leaving_no_room(int threads) {
  const std::optional<MachineLoad> load = measure_machine_load();
  if (load && threads_would_wait(*load, threads)) return load;
  return std::nullopt;
}

}  // namespace granshock
