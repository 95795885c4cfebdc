#include "analysis/field_analysis.hpp"

#include <cmath>
#include <cstdio>
#include <limits>

#include "analysis/block_error.hpp"
#include "analysis/field_sampling_check.hpp"
#include "analysis/iso_lines.hpp"
#include "core/scene.hpp"
#include "core/user_error.hpp"
#include "io/field_sums_file.hpp"
#include "io/run_file.hpp"
#include "io/scene_file.hpp"

namespace granshock {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// The grid column whose centre is nearest the obstacle's axis (the domain's centre line
// without an obstacle).
int axis_column(const BinSums& grid, const FieldPhysics& phys) {
  int best = 0;
  for (int ix = 1; ix < grid.nx; ++ix)
    if (std::abs(phys.dx_from_axis(grid.x_centre(ix))) <
        std::abs(phys.dx_from_axis(grid.x_centre(best))))
      best = ix;
  return best;
}

// Why the stand-in for a missing profile, the grid column on the axis, cannot give delta
// (empty when it can): it must be narrow against the obstacle (docs/fields.md, section 6).
std::string axis_column_reason(const BinSums& grid, const FieldPhysics& phys) {
  if (!phys.obstacle) return "";
  const double across = phys.obstacle->width / grid.dx;
  if (across >= FieldSamplingLimits::bins_across_obstacle) return "";
  char text[200];
  std::snprintf(text, sizeof text,
                "run.h5 has no stagnation-line profile and the grid has only %.3g bins across "
                "the obstacle (the axis column stands in for the profile with %.0f or more)",
                across, FieldSamplingLimits::bins_across_obstacle);
  return text;
}

std::string ma_target_reason(const FieldPhysics& phys) {
  return phys.inflow_sigma > 0 ? "the target Ma_inf is not a finite number"
                               : "the scene gives no inflow.mach and its inflow has no velocity "
                                 "fluctuation (sigma = 0): Ma_inf is infinite";
}

}  // namespace

void set_target_mach(FieldAnalysis& a, double target, bool at_inlet) {
  a.ma_target = target;
  a.ma_target_reason = std::isfinite(target) ? "" : ma_target_reason(a.physics);
  a.inflow = check_inflow(a.upstream_downstream, a.phi_up_err, a.phi_up_err_reason,
                          a.physics.inflow_phi, a.ma_target, a.ma_target_reason, a.options.inflow);
  a.inflow.ma_rows = at_inlet ? "inlet" : "beyond_strip";
  if (!at_inlet || !std::isfinite(target) || !(target > 0)) return;
  a.inflow.ma_measured = a.upstream_inlet.mach;
  a.inflow.ma_deviation = a.upstream_inlet.mach / target - 1;
  a.inflow.ma_deviation_reason = a.upstream_inlet.determined()
                                     ? ""
                                     : "no upstream state at the inlet: " + a.upstream_inlet.reason;
}

FieldAnalysis analyse_fields(const Scene& scene, BinSums grid, std::optional<BinSums> profile,
                             const FieldAnalysisOptions& o) {
  FieldAnalysis a;
  a.options = o;
  a.physics = field_physics_from_scene(scene);
  const FieldPhysics& phys = a.physics;
  if (static_cast<std::size_t>(grid.n_species) != phys.mass.size())
    throw UserError("the field sums hold " + std::to_string(grid.n_species) +
                    " species, the run's scene " + std::to_string(phys.mass.size()));
  a.grid = std::move(grid);
  a.fields = compute_bin_fields(a.grid, phys, o.mask);

  a.upstream_inlet = measure_upstream(a.fields, a.grid, phys, 0, 2);
  // No clamping to the grid: rows beyond it leave the upstream state undetermined.
  a.reference_row = first_row_beyond_strip(a.grid, phys.inflow_strip);
  const int upstream_end = a.reference_row + 2;
  a.upstream_downstream = measure_upstream(a.fields, a.grid, phys, a.reference_row, upstream_end);
  // The threshold rule needs the measured state ahead of the shock, never a stand-in.
  a.phi_up = a.upstream_downstream.phi;
  a.phi_up_err = kNaN;
  if (!a.upstream_downstream.determined()) {
    a.phi_up_err_reason = "no upstream state beyond the strip: " + a.upstream_downstream.reason;
  } else {
    const std::vector<double> blocks =
        upstream_phi_by_block(a.grid, phys, a.reference_row, upstream_end);
    a.phi_up_err = block_standard_error(blocks);
    if (!std::isfinite(a.phi_up_err))
      a.phi_up_err_reason = "only " + std::to_string(blocks.size()) +
                            " blocks with samples (the block error needs 2)";
  }
  const double y_upstream_end = a.grid.y0 + upstream_end * a.grid.dy;

  const NodeGrid centres{a.grid.nx,          a.grid.ny, a.grid.x_centre(0),
                         a.grid.y_centre(0), a.grid.dx, a.grid.dy};
  a.sonic_lines = iso_lines(a.fields.mach, centres, 1.0);
  a.front = find_shock_front(a.fields, a.grid, phys, a.phi_up, a.reference_row, o.threshold,
                             y_upstream_end);

  const int on_axis = axis_column(a.grid, phys);
  if (profile) {
    if (profile->n_species != a.grid.n_species)
      throw UserError("the stagnation-line profile holds " + std::to_string(profile->n_species) +
                      " species, the grid " + std::to_string(a.grid.n_species));
    a.profile_all = std::move(*profile);
  } else {
    a.profile_all = a.grid.column(on_axis);
    a.profile_from_grid = true;
  }
  const double x_axis = phys.obstacle ? phys.obstacle->xc : 0.5 * (phys.box_x_lo + phys.box_x_hi);
  a.profile = strip_of(a.profile_all, x_axis, o.strip_width_d * phys.d);
  a.strip_width = a.profile.dx;
  a.profile_fields = compute_bin_fields(a.profile, phys, o.mask);
  DetachmentSearch search;
  search.y_begin = a.grid.y0 + a.reference_row * a.grid.dy;
  search.y_upstream_end = y_upstream_end;
  search.rule = o.threshold;
  search.mask = o.mask;
  search.bootstrap_resamples = o.bootstrap_resamples;
  const UpstreamValues upstream{a.phi_up};
  a.detachments = measure_detachments(a.profile, phys, upstream, search);
  const std::string coarse_axis = a.profile_from_grid ? axis_column_reason(a.grid, phys) : "";
  if (!coarse_axis.empty()) {
    for (Detachment& d : a.detachments) {
      d.found = false;
      d.y_shock = d.delta = d.delta_over_d = d.delta_err = d.delta_over_d_err = d.threshold = kNaN;
      d.delta_blocks.assign(d.delta_blocks.size(), kNaN);
      d.blocks_used = 0;
      d.reason = d.err_reason = coarse_axis;
    }
  }
  if (phys.obstacle) {
    ConvergenceInput in;
    in.profile = &a.profile_all;
    in.grid = &a.grid;
    in.axis_column = on_axis;
    in.x_axis = x_axis;
    in.strip_width = a.strip_width;
    in.reference = &a.detachments;
    a.convergence = detachment_convergence(in, phys, upstream, search);
  }

  // Without a measured phi_up nothing that depends on the threshold rule is determined;
  // say why in terms of the upstream rows.
  if (!a.upstream_downstream.determined() && phys.obstacle) {
    const std::string why = "no upstream phi beyond the strip: " + a.upstream_downstream.reason;
    for (Detachment& d : a.detachments)
      if (!d.found) d.reason = d.err_reason = why;
    a.front.left.reason = a.front.right.reason = a.front.angle_reason = why;
  }
  a.detachment = of(a.detachments, kPrimaryFront);

  a.eos = check_equation_of_state(a.fields, o.eos);
  a.phi_peak = kNaN;
  for (std::size_t k = 0; k < a.fields.size(); ++k)
    if (!a.fields.masked[k] && (!std::isfinite(a.phi_peak) || a.fields.phi[k] > a.phi_peak))
      a.phi_peak = a.fields.phi[k];
  if (!std::isfinite(a.phi_peak))
    a.phi_peak_reason = "every one of the " + std::to_string(a.fields.size()) +
                        " bins is masked (too few particle samples)";
  set_target_mach(a, phys.nominal_mach(phys.mass_definition));
  a.features = measure_flow_features(a);
  a.steadiness = assess_steadiness(a.series, a.grid.production_start, a.grid.production_end, phys,
                                   a.convergence);
  return a;
}

FieldAnalysis analyse_run_file(const std::filesystem::path& run_h5, const FieldAnalysisOptions& o) {
  std::error_code ec;
  if (!std::filesystem::exists(run_h5, ec))
    throw UserError("cannot read '" + run_h5.string() +
                    "': no such file (is this a granshock run directory?)");
  const RunFile run = RunFile::open_read_only(run_h5);
  const LoadedScene scene =
      parse_scene(run.scene_resolved(), {}, run_h5.string() + ":/scene/resolved");
  BinSums grid = read_grid_sums(run);
  std::optional<BinSums> profile;
  if (has_profile_sums(run)) profile = read_profile_sums(run);
  FieldAnalysis a = analyse_fields(scene.scene, std::move(grid), std::move(profile), o);
  a.series.time = run.read_array("/observables/particles/time");
  a.series.particles = run.read_array("/observables/particles/value");
  a.series.kinetic_energy = run.read_array("/observables/kinetic_energy/value");
  a.steadiness = assess_steadiness(a.series, a.grid.production_start, a.grid.production_end,
                                   a.physics, a.convergence);
  return a;
}

}  // namespace granshock
