// Help for KOKKOS_LAMBDA, which is an extended __host__ __device__ lambda under CUDA.
// nvcc (since CUDA 11.6) rejects such a lambda when it captures a variable for the
// first time inside an `if constexpr` body ("cannot first-capture variable in
// constexpr-if context"): the set of captures must not depend on the instantiation.
// Naming those variables in capture_before_if_constexpr(...) at the top of the lambda
// captures them there; the call generates no code.
#pragma once

#include <Kokkos_Core.hpp>

namespace granshock {

template <class... T>
KOKKOS_FORCEINLINE_FUNCTION void capture_before_if_constexpr(const T&...) {}

}  // namespace granshock
