// What this granshock binary is: version, Kokkos and its backends, threads, options.
#pragma once

#include <string>

namespace granshock {

std::string build_info_json();

}  // namespace granshock
