// The upstream state and Ma_inf as the paper measures it (its section 2, after eq. 8):
// "the upstream sound-speed a_inf [is calculated] by using T and phi averaged over two
// bins from the inlet", and Ma_inf = U_inf / a_inf (eq. 5) with U_inf the inflow speed.
// The first bin row overlaps the insertion strip, where particles appear with the inflow's
// fluctuation and the area fraction builds up batch by batch, so the same average is also
// taken over the two rows that start one bin beyond the strip (docs/fields.md).
#pragma once

#include <string>
#include <vector>

#include "analysis/bin_fields.hpp"
#include "analysis/field_physics.hpp"
#include "core/bin_sums.hpp"

namespace granshock {

struct UpstreamState {
  int row_begin = 0, row_end = 0;  // rows [row_begin, row_end) of the grid
  int bins = 0;                    // unmasked bins averaged
  double phi = 0;                  // mean over the rows' bins
  double temperature = 0;          // particle-weighted mean of the bins' T
  double uy = 0;                   // particle-weighted mean streamwise velocity (measured)
  double sound_speed = 0;          // a(T, phi) with the scene's mass definition
  double mach = 0;                 // U / a, U the inflow speed (eq. 5)
  double mach_mixture_mean = 0, mach_paper_sum = 0;
  std::string reason;  // why the state is undeterminable (every number NaN); empty if it is not
  bool determined() const { return reason.empty(); }
};

// Averages rows [row_begin, row_end) of `grid`: phi over every sampled bin, T and u_y
// weighted with the particles counted in each unmasked bin, the number fractions of the
// mixture-mean mass from the pooled counts. Undeterminable (every number NaN, `reason`
// set) when a row lies outside the grid or the domain, when the rows reach the obstacle's
// upstream surface, or when fewer than half of their bins are unmasked (docs/fields.md).
UpstreamState measure_upstream(const BinFields& fields, const BinSums& grid,
                               const FieldPhysics& physics, int row_begin, int row_end);

// The mean phi of rows [row_begin, row_end) in each block that has samples, for the block
// error of phi_inf (block_error.hpp). Empty when the rows are not all in the grid.
std::vector<double> upstream_phi_by_block(const BinSums& grid, const FieldPhysics& physics,
                                          int row_begin, int row_end);

// The first row whose lower edge lies at least one bin beyond the insertion strip:
// y0 + row dy >= strip + dy.
int first_row_beyond_strip(const BinSums& grid, double strip);

}  // namespace granshock
