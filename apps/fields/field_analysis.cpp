#include "field_analysis.hpp"

#include <cmath>
#include <limits>

#include "iso_lines.hpp"
#include "run_file.hpp"
#include "scene.hpp"
#include "scene_file.hpp"
#include "user_error.hpp"

namespace granshock {

namespace {

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

}  // namespace

FieldAnalysis analyse_fields(const Scene& scene, BinSums grid, std::optional<BinSums> profile,
                             const FieldAnalysisOptions& o) {
  FieldAnalysis a;
  a.physics = field_physics_from_scene(scene);
  const FieldPhysics& phys = a.physics;
  if (static_cast<std::size_t>(grid.n_species) != phys.mass.size())
    throw UserError("the field sums hold " + std::to_string(grid.n_species) +
                    " species, the run's scene " + std::to_string(phys.mass.size()));
  a.grid = std::move(grid);
  a.fields = compute_bin_fields(a.grid, phys, o.mask);

  a.upstream_inlet = measure_upstream(a.fields, phys, 0, 2);
  a.reference_row =
      std::min(first_row_beyond_strip(a.grid, phys.inflow_strip), std::max(a.grid.ny - 2, 0));
  a.upstream_downstream = measure_upstream(a.fields, phys, a.reference_row, a.reference_row + 2);
  a.phi_up = std::isfinite(a.upstream_downstream.phi) ? a.upstream_downstream.phi
             : std::isfinite(a.upstream_inlet.phi)    ? a.upstream_inlet.phi
                                                      : phys.inflow_phi;

  const NodeGrid centres{a.grid.nx,          a.grid.ny, a.grid.x_centre(0),
                         a.grid.y_centre(0), a.grid.dx, a.grid.dy};
  a.sonic_lines = iso_lines(a.fields.mach, centres, 1.0);
  a.front = find_shock_front(a.fields, a.grid, phys, a.phi_up, a.reference_row, o.threshold);

  if (profile) {
    if (profile->n_species != a.grid.n_species)
      throw UserError("the stagnation-line profile holds " + std::to_string(profile->n_species) +
                      " species, the grid " + std::to_string(a.grid.n_species));
    a.profile = std::move(*profile);
  } else {
    a.profile = a.grid.column(axis_column(a.grid, phys));
    a.profile_from_grid = true;
  }
  a.profile_fields = compute_bin_fields(a.profile, phys, o.mask);
  const double search_from = a.grid.y0 + a.reference_row * a.grid.dy;
  a.detachment = measure_detachment(a.profile, phys, a.phi_up, search_from, o.threshold);

  a.eos = check_equation_of_state(a.fields, o.eos);
  a.phi_peak = std::numeric_limits<double>::quiet_NaN();
  for (std::size_t k = 0; k < a.fields.size(); ++k)
    if (!a.fields.masked[k] && (!std::isfinite(a.phi_peak) || a.fields.phi[k] > a.phi_peak))
      a.phi_peak = a.fields.phi[k];
  a.ma_target = phys.nominal_mach(phys.mass_definition);
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
  return analyse_fields(scene.scene, std::move(grid), std::move(profile), o);
}

}  // namespace granshock
