#include "cases/build_info/build_description.hpp"

#include <fmt/format.h>

#include <Kokkos_Core.hpp>

#include "version.hpp"

namespace granshock {

nlohmann::json build_description() {
  nlohmann::json j;
  j["version"] = GRANSHOCK_VERSION_STRING;
  j["commit"] = build_commit();
  j["build_type"] = GRANSHOCK_BUILD_TYPE;
  j["compiler"] = GRANSHOCK_COMPILER;
  j["march"] = build_march();
  j["kokkos"] = std::to_string(KOKKOS_VERSION / 10000) + "." +
                std::to_string(KOKKOS_VERSION / 100 % 100) + "." +
                std::to_string(KOKKOS_VERSION % 100);
  nlohmann::json backends = nlohmann::json::array();
#ifdef KOKKOS_ENABLE_SERIAL
  backends.push_back("Serial");
#endif
#ifdef KOKKOS_ENABLE_OPENMP
  backends.push_back("OpenMP");
#endif
#ifdef KOKKOS_ENABLE_CUDA
  backends.push_back("Cuda");
#endif
#ifdef KOKKOS_ENABLE_HIP
  backends.push_back("HIP");
#endif
  j["backends"] = backends;
  j["default_execution_space"] = Kokkos::DefaultExecutionSpace::name();
  return j;
}

std::string version_line() {
  const nlohmann::json b = build_description();
  return fmt::format(
      "granshock {} (commit {}, {}, {}, Kokkos {} {}, -march {})", b["version"].get<std::string>(),
      b["commit"].get<std::string>(), b["compiler"].get<std::string>(),
      b["build_type"].get<std::string>(), b["kokkos"].get<std::string>(),
      b["default_execution_space"].get<std::string>(), b["march"].get<std::string>());
}

}  // namespace granshock
