// The type particle positions are stored, moved and differenced in, in every precision
// variant (docs/design.md, "Particles"). Why double even in the single-precision variant:
// a float coordinate near 0.5 m (the paper's 500 d box, d = 1 mm) is spaced by 3e-8 m,
// while a contact's overlap is about 1e-6 m, so storing positions in float would err by
// a few % in every contact, more in a larger box. Positions stay double, and a pair's
// separation (with its periodic image), a particle's distance to the obstacle, the drift
// and the skin displacement are formed in double and only then rounded to the variant's
// Real, in which everything else (velocities, forces, spins, springs, the contact law)
// is computed. In the double variant Position and Real are the same type, so the
// conversions are the identity and the arithmetic is unchanged.
#pragma once

#include <Kokkos_Core.hpp>

#include "kernels/device/vec.hpp"

namespace granshock {

using Position = double;

// A position-precision vector (a separation, a displacement) rounded to Real.
template <class Real, int Dim, class From>
KOKKOS_FORCEINLINE_FUNCTION Vec<Dim, Real> to_real(const Vec<Dim, From>& a) {
  Vec<Dim, Real> r;
  for (int d = 0; d < Dim; ++d) r.c[d] = Real(a.c[d]);
  return r;
}

}  // namespace granshock
