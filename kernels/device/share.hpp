// Contiguous shares of a range, as a static schedule deals them out: share s of `shares`
// over [0, total) is [share_begin(total, s, shares), share_begin(total, s + 1, shares)).
// Kernels that hand each thread one share themselves (the one-visit list build, the row
// owners' bands) cut the range the same way; the multi-step pass starts from these cuts and
// moves them by time (solver/thread_shares.hpp).
#pragma once

#include <Kokkos_Core.hpp>

namespace granshock {

KOKKOS_INLINE_FUNCTION int share_begin(int total, int share, int shares) {
  return int(long(total) * share / shares);
}

}  // namespace granshock
