// A steady clock that a kernel written for either side may call: nanoseconds on the host,
// 0 in device code (where nothing calls it: the multi-step pass that times its threads'
// shares runs on host backends only, kernels/solver/fused_steps.hpp).
#pragma once

#include <Kokkos_Core.hpp>
#include <chrono>
#include <cstdint>

namespace granshock {

KOKKOS_INLINE_FUNCTION std::int64_t host_nanoseconds() {
#if defined(__CUDA_ARCH__) || defined(__HIP_DEVICE_COMPILE__) || defined(__SYCL_DEVICE_ONLY__)
  return 0;
#else
  return std::chrono::duration_cast<std::chrono::nanoseconds>(
             std::chrono::steady_clock::now().time_since_epoch())
      .count();
#endif
}

}  // namespace granshock
