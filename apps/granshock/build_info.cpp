#include "apps/granshock/build_info.hpp"

#include <Kokkos_Core.hpp>
#include <nlohmann/json.hpp>

#include "cases/build_info/build_description.hpp"
#include "core/choice_names.hpp"
#include "device/backends.hpp"
#include "parallel/mpi_runtime.hpp"

namespace granshock {

std::string build_info_json(int processes) {
  nlohmann::json j = build_description();
  // The key `info` has always had for the version.
  j["granshock"] = j["version"];
  j["threads"] = Kokkos::DefaultHostExecutionSpace().concurrency();
  // Which branches the kernels take (docs/cuda.md, "Branch points"), and whether Kokkos
  // checks every View index (cmake/install_kokkos_debug.sh).
  j["kernel_paths"] = uses_host_paths<Kokkos::DefaultExecutionSpace>() ? "host" : "device";
#ifdef KOKKOS_ENABLE_DEBUG_BOUNDS_CHECK
  j["bounds_check"] = true;
#else
  j["bounds_check"] = false;
#endif
  // MPI: linked always (parallel HDF5); started only under a launcher (docs/parallel.md).
  j["mpi"] = {{"library", MpiRuntime::library_version()},
              {"launched", MpiRuntime::launched_by_mpi()},
              {"processes", processes}};
  // The names every choice takes (core/choice_names.hpp), among them the contact laws this
  // build compiles (each has a law in kernels/models/models.hpp).
  nlohmann::json choices;
  for_each_choice([&](auto value) {
    using Enum = decltype(value);
    choices[Choices<Enum>::what] = choice_names<Enum>();
  });
  j["choices"] = choices;
  return j.dump(2);
}

}  // namespace granshock
