// The detachment (stand-off) length delta on the stagnation line (docs/fields.md; the
// paper's Fig. 1 and Fig. 6): the distance from the shock front, found on the fine
// stagnation-line profile with the threshold rule of front_crossing.hpp, to the cylinder's
// upstream surface y_c - R. Its statistical uncertainty comes from block averages: delta is
// found again in each block's profile alone, and the standard error of the mean over the
// blocks, s_B / sqrt(B), is reported (B blocks with samples, s_B their sample standard
// deviation). When a number cannot be determined it is NaN and a reason says why
// (docs/fields.md, "When a number cannot be determined").
#pragma once

#include <limits>
#include <string>
#include <vector>

#include "bin_fields.hpp"
#include "bin_sums.hpp"
#include "field_physics.hpp"
#include "front_crossing.hpp"

namespace granshock {

struct Detachment {
  bool found = false;
  double y_shock = 0;       // shock position on the axis (pooled profile), m
  double surface = 0;       // y_c - R, m
  double delta = 0;         // surface - y_shock, m
  double delta_over_d = 0;  // delta / D
  double delta_err = 0;     // standard error from the blocks, m (NaN with < 2 blocks)
  double delta_over_d_err = 0;
  double phi_peak = 0, threshold = 0;
  std::vector<double> delta_blocks;  // per block with samples; NaN where no front was found
  int blocks_used = 0;               // blocks whose delta entered the error
  std::string reason;                // why delta is NaN (empty when found)
  std::string err_reason;            // why delta_err is NaN (empty when it is a number)
};

struct DetachmentSearch {
  // The search starts at the first profile bin whose centre is at or beyond y_begin (the
  // upstream reference row of the grid, beyond the insertion strip) and ends at the last bin
  // whose centre lies upstream of the surface.
  double y_begin = 0;
  // The upper edge of the grid rows that measured phi_up: a front upstream of it lies in
  // those rows, so phi_up is not the state ahead of the shock and delta is undeterminable.
  double y_upstream_end = -std::numeric_limits<double>::infinity();
  ThresholdRule rule;
  MaskRule mask;  // masked profile bins (too few particle samples) hold no phi
};

// phi_up: the measured upstream phi (NaN when it could not be measured). Not found (NaN,
// with a reason) without an obstacle or when the pooled profile shows no front.
Detachment measure_detachment(const BinSums& profile, const FieldPhysics& physics, double phi_up,
                              const DetachmentSearch& search);
Detachment measure_detachment(const BinSums& profile, const FieldPhysics& physics, double phi_up,
                              double y_search_begin, const ThresholdRule& rule = {});

}  // namespace granshock
