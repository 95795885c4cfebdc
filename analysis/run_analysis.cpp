#include "analysis/run_analysis.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "analysis/fields_output.hpp"
#include "analysis/figures.hpp"
#include "analysis/json_file.hpp"
#include "analysis/summary_json.hpp"
#include "core/choice_names.hpp"
#include "core/user_error.hpp"
#include "io/field_sums_file.hpp"
#include "io/run_file.hpp"

namespace granshock {

namespace fs = std::filesystem;

namespace {

struct RunTarget {
  double mach;
  bool at_inlet;  // inflow.mach_at = "inlet_bins"
};

// The run's own target Mach number and where it is meant (summary.json of `granshock run`),
// else the inflow's nominal one, meant for the inserted state.
RunTarget target_mach(const fs::path& summary, double nominal) {
  std::error_code ec;
  if (!fs::exists(summary, ec)) return {nominal, false};
  const nlohmann::json j = read_json_file(summary, "summary").value;
  if (!j.is_object() || !j.contains("ma_inf_target") || !j["ma_inf_target"].is_number())
    return {nominal, false};
  const bool at_inlet =
      j.contains("inflow_mach_at") && j["inflow_mach_at"] == choice_name(MachReference::inlet_bins);
  return {j["ma_inf_target"].get<double>(), at_inlet};
}

std::string number(double v, int digits) {
  if (!std::isfinite(v)) return "n/a";
  std::ostringstream s;
  s.precision(digits);
  s << v;
  return s.str();
}

}  // namespace

std::vector<std::string> AnalysedRun::data_warnings() const {
  std::vector<std::string> out;
  for (const std::string* warning : {&row.inflow_warning, &steady_warning})
    if (!warning->empty()) out.push_back(run_dir.string() + ": " + *warning);
  return out;
}

std::string AnalysedRun::result_line() const {
  const DetachmentRow& r = row;
  std::string line = "granshock fields: " + run_dir.string() + ": Ma_inf " +
                     number(r.ma_inf_target, 3) + " (target), " + number(r.ma_inf_measured, 3) +
                     " (measured at the inlet), " + number(r.ma_inf_measured_downstream, 3) +
                     " (beyond the strip); delta/D = " + number(r.delta_over_D, 3);
  if (std::isfinite(r.delta_over_D)) {
    line += " +- " + number(r.delta_over_D_err, 2);
    if (r.consistent == 0)
      line += " (analysis choices move it by up to " + number(r.spread, 2) + ": " + r.verdict + ")";
  } else
    line += " (" + r.delta_over_D_reason + ")";
  line += "; shock angle " + number(r.shock_angle_deg, 3) + " deg";
  if (!std::isfinite(r.shock_angle_deg)) line += " (" + r.shock_angle_deg_reason + ")";
  if (!steady_warning.empty()) line += "; NOT YET STEADY (see the warning)";
  return line + "; results in " + dest.string();
}

AnalysedRun write_run_analysis(const fs::path& run_dir, const fs::path& dest,
                               FieldAnalysis& analysis, const nlohmann::json& summary,
                               bool in_place) {
  const RunTarget target = target_mach(run_dir / "summary.json", analysis.ma_target);
  set_target_mach(analysis, target.mach, target.at_inlet);
  write_fields_outputs(analysis, dest);
  AnalysedRun done{run_dir, dest, detachment_row(run_dir, analysis, target.mach),
                   analysis.steadiness.warning};
  nlohmann::json keys = summary_keys(analysis);
  // summary.json keeps every warning printed about its run (docs/output_format.md): the
  // run's own, then these about its data.
  nlohmann::json warnings = summary.value("warnings", nlohmann::json::array());
  if (!warnings.is_array()) warnings = nlohmann::json::array();
  for (const std::string& w : done.data_warnings())
    if (std::find(warnings.begin(), warnings.end(), w) == warnings.end()) warnings.push_back(w);
  keys["warnings"] = warnings;
  if (in_place)
    merge_summary_json(dest / "summary.json", keys);  // read again, under the lock
  else
    write_summary_json(dest / "summary.json", summary, keys);
  return done;
}

bool run_has_field_sums(const fs::path& run_dir) {
  std::error_code ec;
  if (!fs::exists(run_dir / "run.h5", ec)) return false;
  try {
    const RunFile run = RunFile::open_read_only(run_dir / "run.h5");
    static_cast<void>(read_grid_sums(run));
    return true;
  } catch (const UserError&) {
    return false;
  }
}

AnalysedRun analyse_finished_run(const fs::path& run_dir, bool figures,
                                 const std::function<void(const std::string&)>& say) {
  FieldAnalysis analysis = analyse_run_file(run_dir / "run.h5");
  const nlohmann::json summary = read_summary_json(run_dir / "summary.json");
  AnalysedRun done = write_run_analysis(run_dir, run_dir, analysis, summary, true);
  if (figures) {
    require_plotting_python();
    plot_run_figures({{run_dir / "fields.h5", run_dir / "figures"}});
  }
  for (const std::string& w : done.data_warnings()) say("granshock: warning: " + w);
  return done;
}

}  // namespace granshock
