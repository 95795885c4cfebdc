// The paper's qualitative claims about the bow shock, each turned into a number one run can
// measure (docs/fields.md, "Flow features"):
//   - "phi is about 0.5 between shock and obstacle": the mean phi on the stagnation strip
//     between the primary front and the surface (its largest value is no measure: rows of
//     0.5 d against the wall hold whole layers of particle centres, phi up to pi/2);
//   - "the hot region behind the shock is subsonic and enveloped by the sonic line": of the
//     stagnation strip's bins between the primary front and the surface at or above its
//     threshold, the fraction with Ma < 1;
//   - "the local Ma upstream of the shock exceeds Ma_inf because the gas cools": the largest
//     Ma on the stagnation strip between the search start and the primary front, over the
//     measured Ma_inf at the inlet;
//   - "the wake is nearly empty": the mean phi behind the cylinder (|x - x_c| <= R, one
//     diameter downstream of it) over phi_up.
// A number that cannot be determined is NaN with a reason.
#pragma once

#include <string>

namespace granshock {

struct FieldAnalysis;

struct FlowFeatures {
  double shock_layer_phi_mean = 0;
  std::string shock_layer_reason;
  double hot_subsonic_fraction = 0;
  int hot_bins = 0;
  std::string hot_reason;
  double upstream_ma_peak = 0, upstream_ma_peak_over_inf = 0;
  std::string upstream_ma_reason;
  double wake_phi_over_phi_up = 0;
  std::string wake_reason;
};

// From an analysis whose fields, upstream state and detachment are filled in.
FlowFeatures measure_flow_features(const FieldAnalysis& analysis);

}  // namespace granshock
