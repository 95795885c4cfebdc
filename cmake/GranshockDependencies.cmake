# Finds granshock's dependencies and reports what it builds for.
find_package(Kokkos 3.4 REQUIRED)

set(GRANSHOCK_BACKENDS "")
foreach(backend SERIAL OPENMP CUDA HIP THREADS SYCL)
  if(Kokkos_ENABLE_${backend})
    list(APPEND GRANSHOCK_BACKENDS ${backend})
  endif()
endforeach()
if(GRANSHOCK_REQUIRE_OPENMP AND NOT Kokkos_ENABLE_OPENMP)
  message(FATAL_ERROR
    "The Kokkos found at ${Kokkos_DIR} has no OpenMP backend (it has: ${GRANSHOCK_BACKENDS}). "
    "Run cmake/install_deps.sh to build one, point Kokkos_ROOT to another, or configure "
    "with -DGRANSHOCK_REQUIRE_OPENMP=OFF to accept it.")
endif()
message(STATUS "granshock: Kokkos ${Kokkos_VERSION} from ${Kokkos_DIR}")
message(STATUS "granshock: building for Kokkos backends: ${GRANSHOCK_BACKENDS}")

find_package(fmt REQUIRED)
find_package(CLI11 QUIET CONFIG)
if(NOT CLI11_FOUND)
  find_path(CLI11_INCLUDE_DIR CLI/CLI.hpp REQUIRED)
  add_library(CLI11::CLI11 INTERFACE IMPORTED)
  target_include_directories(CLI11::CLI11 INTERFACE ${CLI11_INCLUDE_DIR})
endif()
find_package(nlohmann_json 3 REQUIRED)
find_package(tomlplusplus REQUIRED)
