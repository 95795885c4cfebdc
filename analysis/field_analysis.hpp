// Everything `granshock fields` derives from a run's bin sums (docs/fields.md): the fields,
// the upstream state and Ma_inf, the sonic line, the shock front and its angle, the
// detachment length with its uncertainty, the equation-of-state check and the inflow
// against its target. A number that cannot be determined is NaN with a reason next to it.
// Formulas and rules: docs/fields.md.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "analysis/bin_fields.hpp"
#include "analysis/detachment.hpp"
#include "analysis/detachment_convergence.hpp"
#include "analysis/eos_check.hpp"
#include "analysis/field_physics.hpp"
#include "analysis/flow_features.hpp"
#include "analysis/front_crossing.hpp"
#include "analysis/inflow_check.hpp"
#include "analysis/polyline.hpp"
#include "analysis/shock_front.hpp"
#include "analysis/steadiness.hpp"
#include "analysis/upstream_state.hpp"
#include "core/bin_sums.hpp"

namespace granshock {

struct Scene;

struct FieldAnalysisOptions {
  MaskRule mask;
  ThresholdRule threshold;
  EosCut eos;
  InflowTolerance inflow;
  double strip_width_d = 4;  // the stagnation-line strip delta is measured on, in d
  int bootstrap_resamples = 200;
};

struct FieldAnalysis {
  FieldPhysics physics;
  FieldAnalysisOptions options;
  BinSums grid;
  BinFields fields;
  BinSums profile_all;  // the stagnation-line profile as sampled (every column)
  BinSums profile;      // its strip on the axis (or the grid column on the axis)
  bool profile_from_grid = false;
  double strip_width = 0;  // of `profile`, m
  BinFields profile_fields;
  UpstreamState upstream_inlet;       // first two rows (the paper)
  UpstreamState upstream_downstream;  // two rows from one bin beyond the strip
  int reference_row = 0;  // where front searches start (= upstream_downstream.row_begin)
  double phi_up = 0;      // upstream phi of the threshold rule (NaN: not measured)
  double phi_up_err = 0;  // block standard error of phi_up (NaN with < 2 blocks)
  std::string phi_up_err_reason;
  std::vector<Polyline> sonic_lines;  // Ma = 1 (scene's mass definition)
  ShockFront front;
  Detachment detachment;    // by the primary definition (kPrimaryFront)
  Detachments detachments;  // by every definition, in the order of kFrontDefinitions
  DetachmentConvergence convergence;
  EosCheck eos;
  double phi_peak = 0;  // max phi over unmasked grid bins (NaN: all masked)
  std::string phi_peak_reason;
  double ma_target = 0;  // the run's target Ma_inf (set_target_mach), NaN: none
  std::string ma_target_reason;
  InflowCheck inflow;     // measured upstream state against the targets
  FlowFeatures features;  // the paper's qualitative claims as numbers
  RunSeries series;       // run.h5 /observables (empty for sums without a run file)
  Steadiness steadiness;  // whether the window is steady (docs/fields.md, section 12)
};

FieldAnalysis analyse_fields(const Scene& scene, BinSums grid, std::optional<BinSums> profile,
                             const FieldAnalysisOptions& options = {});
// Reads DIR/run.h5 (its resolved scene, field sums and time series) and analyses it.
FieldAnalysis analyse_run_file(const std::filesystem::path& run_h5,
                               const FieldAnalysisOptions& options = {});

// Replaces the target Ma_inf (analyse_fields takes the inflow's nominal one; a run's
// summary.json may name its own) and redoes the inflow check with it. `at_inlet`: the
// target is meant over the two inlet rows (inflow.mach_at = "inlet_bins"), so the Mach
// deviation compares those rows; otherwise the rows beyond the strip (docs/fields.md).
void set_target_mach(FieldAnalysis& analysis, double target, bool at_inlet = false);

}  // namespace granshock
