// Which execution spaces granshock instantiates kernels for: always Kokkos' default,
// plus Serial when it is enabled and is not already the default (for tests that
// compare backends).
#pragma once

#include <Kokkos_Core.hpp>

#if defined(KOKKOS_ENABLE_SERIAL) &&                                 \
    (defined(KOKKOS_ENABLE_OPENMP) || defined(KOKKOS_ENABLE_CUDA) || \
     defined(KOKKOS_ENABLE_THREADS) || defined(KOKKOS_ENABLE_HIP))
#define GRANSHOCK_SEPARATE_SERIAL 1
#else
#define GRANSHOCK_SEPARATE_SERIAL 0
#endif
