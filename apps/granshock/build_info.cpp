#include "build_info.hpp"

#include <Kokkos_Core.hpp>
#include <nlohmann/json.hpp>

#include "device/backends.hpp"
#include "mpi_runtime.hpp"

#include "version.hpp"

namespace granshock {

std::string build_info_json(int processes) {
  nlohmann::json j;
  j["granshock"] = GRANSHOCK_VERSION_STRING;
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
  j["build_type"] = GRANSHOCK_BUILD_TYPE;
  j["compiler"] = GRANSHOCK_COMPILER;
  return j.dump(2);
}

}  // namespace granshock
