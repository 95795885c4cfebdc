// What this granshock binary is: version, Kokkos and its backends, threads, options.
#pragma once

#include <string>

namespace granshock {

// `processes`: the MPI processes this one was started with (1 without a launcher).
std::string build_info_json(int processes);

}  // namespace granshock
