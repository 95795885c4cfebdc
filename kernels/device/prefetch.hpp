// A hint that the cache line holding p is about to be written: the host fetches it while
// other work proceeds (GCC and Clang, x86 `prefetchw` where the CPU has it). On a GPU the
// hint compiles to nothing; its caches and occupancy hide latency instead.
#pragma once

#include <Kokkos_Core.hpp>

namespace granshock {

KOKKOS_FORCEINLINE_FUNCTION void prefetch_for_write(const void* p) {
#if defined(__GNUC__) && !defined(__CUDA_ARCH__) && !defined(__HIP_DEVICE_COMPILE__) && \
    !defined(__SYCL_DEVICE_ONLY__)
  __builtin_prefetch(p, 1, 3);
#else
  (void)p;
#endif
}

}  // namespace granshock
