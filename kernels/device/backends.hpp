// Which execution spaces granshock instantiates kernels for: always Kokkos' default,
// plus Serial when it is enabled and is not already the default (for tests that
// compare backends). And which of two ways a kernel takes where it is written one way
// for host backends and another for a GPU (docs/cuda.md, "Branch points").
#pragma once

#include <Kokkos_Core.hpp>

// GRANSHOCK_NO_SERIAL_VARIANTS (the CMake option GRANSHOCK_SERIAL_VARIANTS=OFF) builds as
// if Kokkos had no Serial.
#if defined(KOKKOS_ENABLE_SERIAL) && !defined(GRANSHOCK_NO_SERIAL_VARIANTS) && \
    (defined(KOKKOS_ENABLE_OPENMP) || defined(KOKKOS_ENABLE_CUDA) ||           \
     defined(KOKKOS_ENABLE_THREADS) || defined(KOKKOS_ENABLE_HIP))
#define GRANSHOCK_SEPARATE_SERIAL 1
#else
#define GRANSHOCK_SEPARATE_SERIAL 0
#endif

// Set to 1 by the CMake option GRANSHOCK_DEVICE_PATHS: host backends then take every
// device branch, so that the code a GPU runs is run and tested on the host.
#ifndef GRANSHOCK_DEVICE_PATHS
#define GRANSHOCK_DEVICE_PATHS 0
#endif

namespace granshock {

// Whether the host can read the memory of ExecSpace's kernels (OpenMP, Serial: yes;
// Cuda: no). Host paths are only possible there.
template <class ExecSpace>
constexpr bool host_accessible() {
  return Kokkos::SpaceAccessibility<Kokkos::HostSpace,
                                    typename ExecSpace::memory_space>::accessible;
}

// The one predicate every host-or-device choice of the kernels asks, through the
// KernelPaths tag below: host paths on host backends, unless the build asks for the
// device paths everywhere.
template <class ExecSpace>
constexpr bool uses_host_paths() {
  return host_accessible<ExecSpace>() && !GRANSHOCK_DEVICE_PATHS;
}

// A host path's seldom taken branch kept out of its caller, so that the caller's hot loops
// get the registers to themselves (solver/fused_step.hpp). nvcc's passes inline it as
// they choose.
#if defined(__CUDACC__)
#define GRANSHOCK_HOST_NOINLINE
#else
#define GRANSHOCK_HOST_NOINLINE __attribute__((noinline))
#endif

// The choice as a type, a template argument of the kernels that branch (defaulted to
// DefaultPaths), so that a test can build both ways into one program and compare them.
// Each branch reads `Paths::host`; docs/cuda.md lists every one (checked by
// tests/cli/device_branches_listed.sh).
template <bool Host>
struct KernelPaths {
  static constexpr bool host = Host;
};
using HostPaths = KernelPaths<true>;
using DevicePaths = KernelPaths<false>;
template <class ExecSpace>
using DefaultPaths = KernelPaths<uses_host_paths<ExecSpace>()>;

// Host paths read device memory from the host: only where the host can.
template <class ExecSpace, class Paths>
constexpr bool paths_possible() {
  return host_accessible<ExecSpace>() || !Paths::host;
}

}  // namespace granshock
