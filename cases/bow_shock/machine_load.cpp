#include "cases/bow_shock/machine_load.hpp"

#include <sched.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <thread>

namespace granshock {

std::optional<char> task_state(const std::string& stat) {
  // "pid (comm) state ppid ...": the command name may hold spaces and parentheses, so the
  // state is the first field after its last closing parenthesis.
  const std::size_t close = stat.rfind(')');
  if (close == std::string::npos) return std::nullopt;
  std::istringstream fields(stat.substr(close + 1));
  char state = 0;
  if (!(fields >> state)) return std::nullopt;
  return state;
}

namespace {

int allowed_cpus() {
  cpu_set_t set;
  CPU_ZERO(&set);
  if (sched_getaffinity(0, sizeof(set), &set) != 0) return 0;
  return CPU_COUNT(&set);
}

bool is_number(const std::string& name) {
  return !name.empty() &&
         std::all_of(name.begin(), name.end(), [](char c) { return c >= '0' && c <= '9'; });
}

}  // namespace

std::optional<int> others_running(const std::string& proc, long self) {
  std::error_code ec;
  std::filesystem::directory_iterator procs(proc, ec);
  if (ec) return std::nullopt;
  int running = 0;
  for (const auto& entry : procs) {
    const std::string pid = entry.path().filename().string();
    if (!is_number(pid) || std::stol(pid) == self) continue;
    std::error_code task_ec;  // a process may end while it is read
    for (const auto& task : std::filesystem::directory_iterator(entry.path() / "task", task_ec)) {
      std::ifstream in(task.path() / "stat");
      std::string line;
      if (!std::getline(in, line)) continue;
      if (task_state(line) == 'R') ++running;
    }
  }
  return running;
}

std::optional<MachineLoad> measure_machine_load(int samples, int gap_ms) {
  const int cpus = allowed_cpus();
  if (cpus <= 0) return std::nullopt;
  std::optional<int> fewest;
  for (int k = 0; k < samples; ++k) {
    if (k > 0) std::this_thread::sleep_for(std::chrono::milliseconds(gap_ms));
    const std::optional<int> now = others_running("/proc", long(getpid()));
    if (!now) return std::nullopt;
    fewest = fewest ? std::min(*fewest, *now) : *now;
  }
  return MachineLoad{*fewest, cpus};
}

}  // namespace granshock
