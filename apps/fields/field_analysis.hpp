// Everything `granshock fields` derives from a run's bin sums (DESIGN.md 2.3): the fields,
// the upstream state and Ma_inf, the sonic line, the shock front and its angle, the
// detachment length with its uncertainty and the equation-of-state check. Formulas and
// rules: docs/fields.md.
#pragma once

#include <filesystem>
#include <optional>
#include <vector>

#include "bin_fields.hpp"
#include "bin_sums.hpp"
#include "detachment.hpp"
#include "eos_check.hpp"
#include "field_physics.hpp"
#include "front_crossing.hpp"
#include "polyline.hpp"
#include "shock_front.hpp"
#include "upstream_state.hpp"

namespace granshock {

struct Scene;

struct FieldAnalysisOptions {
  MaskRule mask;
  ThresholdRule threshold;
  EosCut eos;
};

struct FieldAnalysis {
  FieldPhysics physics;
  BinSums grid;
  BinFields fields;
  BinSums profile;  // the stagnation-line profile (or the grid column on the axis)
  bool profile_from_grid = false;
  BinFields profile_fields;
  UpstreamState upstream_inlet;       // first two rows (the paper)
  UpstreamState upstream_downstream;  // two rows from one bin beyond the strip
  int reference_row = 0;  // where front searches start (= upstream_downstream.row_begin)
  double phi_up = 0;      // upstream phi of the threshold rule
  std::vector<Polyline> sonic_lines;  // Ma = 1 (scene's mass definition)
  ShockFront front;
  Detachment detachment;
  EosCheck eos;
  double phi_peak = 0;   // max phi over unmasked grid bins
  double ma_target = 0;  // the inflow's nominal Mach number (FieldPhysics::nominal_mach)
};

FieldAnalysis analyse_fields(const Scene& scene, BinSums grid, std::optional<BinSums> profile,
                             const FieldAnalysisOptions& options = {});
// Reads DIR/run.h5 (its resolved scene and field sums) and analyses it.
FieldAnalysis analyse_run_file(const std::filesystem::path& run_h5,
                               const FieldAnalysisOptions& options = {});

}  // namespace granshock
