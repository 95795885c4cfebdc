// The band of bin rows that one thread owns in row-owner field sampling
// (sampling/row_owner_sampling.hpp; docs/fields.md, "Cost of sampling").
#pragma once

#include <Kokkos_Core.hpp>

#include "kernels/device/share.hpp"

namespace granshock {

// Owner t's band of rows [lo, hi) of a layout with `rows` rows, for n particles in the
// order row_of(i) gives their rows: from the row of the particle that starts the t-th of
// `owners` equal shares of the order to the row of the one that starts share t + 1. The
// boundaries are running maxima, so that the bands tile [0, rows) whatever the order
// (particles inserted since the last sort sit at the end, out of order).
template <class RowOf>
KOKKOS_INLINE_FUNCTION void owner_band(int t, int owners, int n, int rows, const RowOf& row_of,
                                       int& lo, int& hi) {
  lo = 0;
  hi = rows;
  int boundary = 0;
  for (int k = 1; k < owners; ++k) {
    const int r = n > 0 ? row_of(share_begin(n, k, owners)) : 0;
    boundary = r > boundary ? r : boundary;
    if (k == t) lo = boundary;
    if (k == t + 1) hi = boundary;
  }
}

}  // namespace granshock
