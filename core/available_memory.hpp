// The memory this process may still take, for refusing work that would need more before
// it is allocated (docs/stability.md, "Limits"): a run's scene (cases/bow_shock/
// run_memory.hpp) and a dump's frame (io/particle_dump.hpp).
#pragma once

#include <optional>

namespace granshock {

// MemAvailable of /proc/meminfo in bytes, lowered to what the address-space limit
// (ulimit -v) leaves this process when one is set; nothing where neither can be read.
std::optional<double> available_memory_bytes();

}  // namespace granshock
