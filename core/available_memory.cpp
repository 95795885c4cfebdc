#include "core/available_memory.hpp"

#include <sys/resource.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>
#include <string>

namespace granshock {

std::optional<double> available_memory_bytes() {
  std::optional<double> available;
  std::ifstream in("/proc/meminfo");
  for (std::string line; std::getline(in, line);) {
    std::istringstream fields(line);
    std::string key, unit;
    double kib = 0;
    if (fields >> key >> kib >> unit && key == "MemAvailable:" && unit == "kB")
      available = kib * 1024;
  }
  rlimit limit{};
  if (getrlimit(RLIMIT_AS, &limit) == 0 && limit.rlim_cur != RLIM_INFINITY) {
    // The limit counts the address space already mapped (libraries, thread stacks).
    double mapped = 0;
    std::ifstream status("/proc/self/status");
    for (std::string line; std::getline(status, line);) {
      std::istringstream fields(line);
      std::string key;
      double kib = 0;
      if (fields >> key >> kib && key == "VmSize:") mapped = kib * 1024;
    }
    available =
        std::min(available.value_or(INFINITY), std::max(0.0, double(limit.rlim_cur) - mapped));
  }
  return available;
}

}  // namespace granshock
