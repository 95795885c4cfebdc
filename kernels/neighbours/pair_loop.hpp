// The one loop over a particle's contacts (docs/design.md, "The pair loop"): for particle
// i, each partner j in its Verlet list whose centre is closer than r_i + r_j, in list
// order. The force kernel, the contact virial of field sampling, the elastic energy and
// the contact count all run through it, so the contact criterion and the minimum image
// are written once. Full lists: each touching pair is visited from both sides.
// Positions are Position (double) in every variant: a pair's separation and its periodic
// image are formed in double and only then rounded to Real (device/position.hpp).
#pragma once

#include <Kokkos_Core.hpp>

#include "kernels/device/box_geometry.hpp"
#include "kernels/device/position.hpp"
#include "kernels/device/row_element.hpp"
#include "kernels/device/vec.hpp"

namespace granshock {

template <int Dim, class Real, class MemSpace>
struct PairLoop {
  Kokkos::View<int*, MemSpace> offsets;     // n + 1
  Kokkos::View<int*, MemSpace> neighbours;  // partners of i: [offsets(i), offsets(i + 1))
  Kokkos::View<Position* [Dim], MemSpace> x;
  Kokkos::View<int*, MemSpace> species;
  Kokkos::View<Real*, MemSpace> radius;  // per species
  BoxGeometry<Dim, Position> box;
  Real max_radius;  // of all species: partners beyond 2 max_radius are not looked up

  KOKKOS_FORCEINLINE_FUNCTION Vec<Dim, Position> position(int i) const {
    Vec<Dim, Position> r;
    for (int d = 0; d < Dim; ++d) r[d] = row_element(x, i, d);
    return r;
  }

  // Calls touching(j, sj, dx, r2, rsum) for each partner j of particle i (at xi) in
  // contact: dx = x_i - x_j (minimum image, formed in Position, then rounded to Real), r2 =
  // |dx|^2 < rsum^2, rsum = r_i + r_j. Images false: i is known to have no partner across
  // a periodic face (solver/run_marks.hpp), where the image changes nothing.
  template <bool Images = true, class F>
  KOKKOS_FORCEINLINE_FUNCTION void for_each_contact(int i, const Vec<Dim, Position>& xi,
                                                    F&& touching) const {
    // Most list partners are not touching: they are rejected on the distance alone, against
    // twice the largest radius, before any radius is read (i's, then the partner's species
    // and radius). Every contact passes that test, and rsum decides, so the contacts are
    // those of r_i + r_j whatever the radii; read per particle, i's radius and species took
    // two loads and two registers from the partner loop (docs/benchmarks.md, "The closing
    // pass, and the radius read per contact").
    const Real reach = max_radius + max_radius;
    const Real reach2 = reach * reach;
    for (int k = offsets(i); k < offsets(i + 1); ++k) {
      const int j = neighbours(k);
      Vec<Dim, Position> separation = xi - position(j);
      if constexpr (Images) separation = box.nearby_image(separation);
      const Vec<Dim, Real> dx = to_real<Real>(separation);
      const Real r2 = norm2(dx);
      if (r2 >= reach2) continue;
      const int sj = species(j);
      const Real rsum = radius(species(i)) + radius(sj);
      if (r2 >= rsum * rsum) continue;
      touching(j, sj, dx, r2, rsum);
    }
  }
};

}  // namespace granshock
