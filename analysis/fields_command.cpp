#include "fields_command.hpp"

#include <cmath>
#include <fstream>
#include <iostream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "bin_sums.hpp"
#include "detachment_table.hpp"
#include "field_analysis.hpp"
#include "field_sums_file.hpp"
#include "fields_output.hpp"
#include "figures.hpp"
#include "regular_file.hpp"
#include "run_file.hpp"
#include "summary_json.hpp"
#include "user_error.hpp"

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
  require_regular_file(summary, "summary");  // a FIFO would block the read
  std::ifstream in(summary);
  std::stringstream text;
  text << in.rdbuf();
  const nlohmann::json j = nlohmann::json::parse(text.str(), nullptr, false);
  if (!j.is_object() || !j.contains("ma_inf_target") || !j["ma_inf_target"].is_number())
    return {nominal, false};
  const bool at_inlet = j.contains("inflow_mach_at") && j["inflow_mach_at"] == "inlet_bins";
  return {j["ma_inf_target"].get<double>(), at_inlet};
}

void make_directory(const fs::path& dir) {
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec) throw UserError("cannot create '" + dir.string() + "': " + ec.message());
}

std::string number(double v, int digits) {
  if (!std::isfinite(v)) return "n/a";
  std::ostringstream s;
  s.precision(digits);
  s << v;
  return s.str();
}

struct Done {
  fs::path run_dir, dest;
  DetachmentRow row;
};

// One line per run; an undeterminable number is "n/a", and delta/D and the shock angle say
// why in brackets.
std::string result_line(const Done& d) {
  const DetachmentRow& r = d.row;
  std::string line = "granshock fields: " + d.run_dir.string() + ": Ma_inf " +
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
  return line + "; results in " + d.dest.string();
}

}  // namespace

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

int fields_command(const std::vector<fs::path>& run_dirs, const fs::path& out) {
  return fields_command(run_dirs, out, FieldsCommandOptions{});
}

int fields_command(const std::vector<fs::path>& run_dirs, const fs::path& out,
                   const FieldsCommandOptions& o) {
  if (run_dirs.empty()) throw UserError("granshock fields needs at least one run directory");
  const bool several = run_dirs.size() > 1;
  if (several && out.empty())
    throw UserError(
        "granshock fields with " + std::to_string(run_dirs.size()) +
        " run directories needs --out DIR for their comparison (detachment table and figure)");
  // Every run is checked before anything is written.
  std::vector<FieldAnalysis> analyses;
  for (const fs::path& dir : run_dirs) analyses.push_back(analyse_run_file(dir / "run.h5"));

  std::vector<Done> done;
  for (std::size_t i = 0; i < run_dirs.size(); ++i) {
    const fs::path& dir = run_dirs[i];
    const fs::path dest = (!several && !out.empty()) ? out : dir;
    make_directory(dest);
    const RunTarget target = target_mach(dir / "summary.json", analyses[i].ma_target);
    set_target_mach(analyses[i], target.mach, target.at_inlet);
    write_fields_outputs(analyses[i], dest);
    const nlohmann::json keys = summary_keys(analyses[i]);
    std::error_code ec;
    if (dest != dir && fs::exists(dir / "summary.json", ec) &&
        !fs::exists(dest / "summary.json", ec))
      fs::copy_file(dir / "summary.json", dest / "summary.json", ec);
    merge_summary_json(dest / "summary.json", keys);
    done.push_back({dir, dest, detachment_row(dir, analyses[i], target.mach)});
  }
  if (several) {
    make_directory(out);
    std::vector<DetachmentRow> rows;
    for (const Done& d : done) rows.push_back(d.row);
    write_detachment_table(out, rows);
  }

  if (o.figures) {
    require_plotting_python();
    for (const Done& d : done) plot_run_figures(d.dest / "fields.h5", d.dest / "figures");
    if (several)
      plot_detachment_figure(out / "detachment.json", out / "figures" / "detachment_length.png");
  }

  // A short inflow is a warning about the data, printed even when the result line is not.
  for (const Done& d : done)
    if (!d.row.inflow_warning.empty())
      std::cerr << "granshock: warning: " << d.run_dir.string() << ": " << d.row.inflow_warning
                << "\n";
  if (!o.quiet) {
    for (const Done& d : done) std::cout << result_line(d) << "\n";
    if (several) std::cout << "granshock fields: comparison in " << out.string() << "\n";
  }
  return 0;
}

}  // namespace granshock
