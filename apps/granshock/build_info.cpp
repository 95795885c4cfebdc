#include "build_info.hpp"

#include <Kokkos_Core.hpp>
#include <nlohmann/json.hpp>

#include "build_description.hpp"
#include "mpi_runtime.hpp"

namespace granshock {

std::string build_info_json(int processes) {
  nlohmann::json j = build_description();
  // The key `info` has always had for the version.
  j["granshock"] = j["version"];
  j["threads"] = Kokkos::DefaultHostExecutionSpace().concurrency();
  // MPI: linked always (parallel HDF5); started only under a launcher (docs/parallel.md).
  j["mpi"] = {{"library", MpiRuntime::library_version()},
              {"launched", MpiRuntime::launched_by_mpi()},
              {"processes", processes}};
  return j.dump(2);
}

}  // namespace granshock
