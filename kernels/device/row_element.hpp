// Element (i, d) of a View<T*[N]> (a vector per particle), for the hot loops. On
// LayoutRight, the host's layout, it is data()[i * N + d] with N known at compile time;
// Kokkos' operator() multiplies i by the view's stride, a runtime value it keeps for
// padded views, which granshock never allocates (no Kokkos::AllowPadding): one
// multiplication per access and one register per view in the fused step's loops
// (docs/benchmarks.md, "Instructions per particle-step"). Any other layout (LayoutLeft
// on a GPU) goes through operator().
#pragma once

#include <Kokkos_Core.hpp>
#include <cstddef>
#include <type_traits>

namespace granshock {

// Under Kokkos' bounds checking (CI's checking builds) every access goes through
// operator(), so that the hot loops' indices are checked too.
#ifdef KOKKOS_ENABLE_DEBUG_BOUNDS_CHECK
inline constexpr bool row_element_unchecked = false;
#else
inline constexpr bool row_element_unchecked = true;
#endif

template <class View>
KOKKOS_FORCEINLINE_FUNCTION typename View::reference_type row_element(const View& view, int i,
                                                                      int d) {
  if constexpr (row_element_unchecked &&
                std::is_same_v<typename View::array_layout, Kokkos::LayoutRight> &&
                View::rank == 2 && View::static_extent(1) > 0) {
    return (view.data() + std::size_t(i) * View::static_extent(1))[d];
  } else {
    return view(i, d);
  }
}

}  // namespace granshock
