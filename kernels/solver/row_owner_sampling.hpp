// Field sampling by row owners (ScatterStrategy::rows; docs/fields.md, "Cost of
// sampling"): one pass for the grid and the stagnation-line profile together. Thread t of
// `owners` (a power of two) scans every particle and takes those whose bin lies in one of
// its rows (row & (owners - 1) == t); for each it computes the contact virial through the
// pair loop, as the separate virial kernel would, and adds moments and virial to the bin
// without atomics. Each bin's particles are added in particle order, so the sums are
// bitwise the same for any thread count, and the virial never goes through memory.
#pragma once

#include <Kokkos_Core.hpp>

#include "sampling/bin_accumulator.hpp"
#include "solver/contact_forces.hpp"

namespace granshock {

template <class V, class ExecSpace, class Part>
struct RowOwnerSamplePass {
  static constexpr int Dim = V::dim;
  using Real = typename V::real;
  using Sums = Kokkos::View<double*, typename ExecSpace::memory_space>;

  ContactForceKernel<V, ExecSpace, ForceMode::virial> contacts;
  Part grid, profile;  // SampleContribution<GridIndex, ...> of each layout
  Sums grid_sums, profile_sums;
  bool with_profile;
  int n, owner_mask;

  KOKKOS_INLINE_FUNCTION void operator()(const int t) const {
    PlainAdd<Sums> to_grid{grid_sums}, to_profile{profile_sums};
    for (int i = 0; i < n; ++i) {
      const double x = double(contacts.p.x(i, 0)), y = double(contacts.p.x(i, 1));
      int grid_row = 0, profile_row = 0;
      const int grid_bin = grid.where(x, y, grid_row);
      const int profile_bin = with_profile ? profile.where(x, y, profile_row) : -1;
      const bool in_grid = grid_bin >= 0 && (grid_row & owner_mask) == t;
      const bool in_profile = profile_bin >= 0 && (profile_row & owner_mask) == t;
      if (!in_grid && !in_profile) continue;
      Real w[Dim * Dim] = {};
      Vec<Dim, Real> force = Vec<Dim, Real>::zero();
      Real torque = 0;
      int used_slots = 0;
      contacts.sum_contacts(i, contacts.pairs.position(i), contacts.velocity(i), force, torque,
                            used_slots, w);
      const auto virial_of = [&](int k) { return w[k]; };
      if (in_grid) grid.add_to_bin(grid_bin, i, to_grid, virial_of);
      if (in_profile) profile.add_to_bin(profile_bin, i, to_profile, virial_of);
    }
  }
};

}  // namespace granshock
