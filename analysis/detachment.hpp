// The detachment (stand-off) length delta on the stagnation line (docs/fields.md, section
// 6; the paper's Fig. 1 and Fig. 6): the distance from the shock front to the cylinder's
// upstream surface y_c - R, found on one strip of the stagnation-line profile by one of
// four definitions of "the front" (stagnation_line.hpp): the half-rise of the temperature
// (the primary one), the density half-way threshold, the steepest density rise, the
// sonic point, and the centres of tanh steps fitted to T and to phi (with their thickness). Its
// statistical uncertainty comes from the blocks of the production window three ways
// (docs/fields.md, "Error bars"): the standard error of the blocks' own deltas, the same over pairs
// of neighbouring blocks merged (which grows when neighbouring blocks are correlated), and a
// bootstrap over blocks (resampled with replacement and pooled). The reported error is the larger
// of the merged pairs' (the single blocks' when fewer than two pairs show a front) and the
// bootstrap's. When a number cannot be determined it is NaN and a reason says why (docs/fields.md,
// "When a number cannot be determined").
#pragma once

#include <array>
#include <limits>
#include <string>
#include <vector>

#include "analysis/bin_fields.hpp"
#include "analysis/field_physics.hpp"
#include "analysis/front_crossing.hpp"
#include "analysis/stagnation_line.hpp"
#include "core/bin_sums.hpp"

namespace granshock {

struct Detachment {
  FrontDefinition definition = FrontDefinition::density_threshold;
  bool found = false;
  double y_shock = 0;       // front position on the axis (pooled profile), m
  double surface = 0;       // y_c - R, m
  double delta = 0;         // surface - y_shock, m
  double delta_over_d = 0;  // delta / D
  double delta_err = 0;     // the reported error (see above), m
  double delta_over_d_err = 0;
  // The three estimates of the error (NaN where they cannot be formed), m.
  double err_blocks = 0, err_merged_pairs = 0, err_bootstrap = 0;
  int bootstrap_found = 0, bootstrap_resamples = 0;  // resamples that showed a front
  double peak = 0, threshold = 0;                    // of the definition's quantity
  // The fitted fronts (temperature_fit, density_fit; NaN for the others): the thickness w
  // with its error (the same three estimates as delta's), the fitted level upstream and the
  // cut (the downstream edge of the last bin fitted), m.
  double width = 0, width_err = 0, low = 0, fit_end = 0;
  std::vector<double> delta_blocks;  // per block with samples; NaN where no front was found
  int blocks_used = 0;               // blocks whose delta entered err_blocks
  std::string reason;                // why delta is NaN (empty when found)
  std::string err_reason;            // why delta_err is NaN (empty when it is a number)
};

struct DetachmentSearch {
  // The search starts at the first profile bin whose centre is at or beyond y_begin (the
  // upstream reference row of the grid, beyond the insertion strip) and ends at the last bin
  // whose centre lies upstream of the surface.
  double y_begin = 0;
  // The upper edge of the grid rows that measured the upstream state: a front upstream of
  // it lies in those rows, so they are not the state ahead of the shock and delta is
  // undeterminable.
  double y_upstream_end = -std::numeric_limits<double>::infinity();
  ThresholdRule rule;
  MaskRule mask;  // masked profile bins (too few particle samples) hold no phi, T or Ma
  int bootstrap_resamples = 200;  // 0: no bootstrap
};

// profile: one column (a strip of the stagnation-line profile, strip_of()); upstream: the
// measured state ahead of the shock (phi, T; NaN when not measured). Not found (NaN, with a
// reason) without an obstacle or when the pooled profile shows no front. One result per
// definition, in the order of kFrontDefinitions (each profile's fields are computed once).
using Detachments = std::array<Detachment, kFrontDefinitions.size()>;
Detachments measure_detachments(const BinSums& profile, const FieldPhysics& physics,
                                const UpstreamValues& upstream, const DetachmentSearch& search);
Detachment measure_detachment(const BinSums& profile, const FieldPhysics& physics,
                              const UpstreamValues& upstream, const DetachmentSearch& search,
                              FrontDefinition definition);
// The entry of `all` for one definition.
const Detachment& of(const Detachments& all, FrontDefinition definition);
// The density threshold with phi_up alone (tests and the first versions of the analysis).
Detachment measure_detachment(const BinSums& profile, const FieldPhysics& physics, double phi_up,
                              double y_search_begin, const ThresholdRule& rule = {});

}  // namespace granshock
