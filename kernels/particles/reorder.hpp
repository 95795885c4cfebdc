// Moving particle rows: a permutation (dst(k) = src(order(k)) for k < n, after a cell
// sort so that particles close in space are close in memory) and a prefix copy (growing
// an array keeps its first n rows).
#pragma once

#include <Kokkos_Core.hpp>
#include <utility>

#include "kernels/device/device_lambda.hpp"
#include "kernels/device/space_alloc.hpp"

namespace granshock {

// Gathers `view` through `order` into `scratch`, then swaps the two handles, so that
// `view` holds the reordered data and `scratch` the old buffer (reused next time).
template <class ExecSpace, class View, class OrderView>
void gather_in_place(View& view, View& scratch, const OrderView& order, int n) {
  if (view.extent(0) == 0) return;
  if (scratch.extent(0) != view.extent(0) ||
      (View::rank > 1 && scratch.extent(1) != view.extent(1)))
    scratch = View(alloc_uninitialised_on<ExecSpace>(view.label() + "_scratch"), view.layout());
  auto src = view;
  auto dst = scratch;
  Kokkos::parallel_for(
      "reorder::gather", Kokkos::RangePolicy<ExecSpace>(0, n), KOKKOS_LAMBDA(const int k) {
        capture_before_if_constexpr(src, dst);
        const int from = order(k);
        if constexpr (View::rank == 1) {
          dst(k) = src(from);
        } else {
          for (int c = 0; c < int(src.extent(1)); ++c) dst(k, c) = src(from, c);
        }
      });
  std::swap(view, scratch);
}

// dst(i) = src(i) for i < n (dst may be longer).
template <class ExecSpace, class View>
void copy_prefix(const View& dst, const View& src, int n) {
  if (src.extent(0) == 0 || n == 0) return;
  Kokkos::parallel_for(
      "reorder::copy_prefix", Kokkos::RangePolicy<ExecSpace>(0, n), KOKKOS_LAMBDA(const int i) {
        capture_before_if_constexpr(dst, src);
        if constexpr (View::rank == 1) {
          dst(i) = src(i);
        } else {
          for (int c = 0; c < int(src.extent(1)); ++c) dst(i, c) = src(i, c);
        }
      });
}

}  // namespace granshock
