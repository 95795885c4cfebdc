#include "analysis/fields_command.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iostream>
#include <nlohmann/json.hpp>
#include <optional>
#include <sstream>

#include "analysis/detachment_table.hpp"
#include "analysis/field_analysis.hpp"
#include "analysis/fields_output.hpp"
#include "analysis/figures.hpp"
#include "analysis/json_file.hpp"
#include "analysis/summary_json.hpp"
#include "core/bin_sums.hpp"
#include "core/choice_names.hpp"
#include "core/user_error.hpp"
#include "io/field_sums_file.hpp"
#include "io/fields_directory.hpp"
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

struct Done {
  fs::path run_dir, dest;
  DetachmentRow row;
  std::string steady_warning;  // empty when the window is steady (docs/fields.md, section 12)
};

// The warnings about a run's data (a short inflow, an unsteady window), each naming the run.
std::vector<std::string> data_warnings(const Done& d) {
  std::vector<std::string> out;
  for (const std::string* warning : {&d.row.inflow_warning, &d.steady_warning})
    if (!warning->empty()) out.push_back(d.run_dir.string() + ": " + *warning);
  return out;
}

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
  if (!d.steady_warning.empty()) line += "; NOT YET STEADY (see the warning)";
  return line + "; results in " + d.dest.string();
}

bool same_directory(const fs::path& a, const fs::path& b) {
  std::error_code ec;
  return fs::equivalent(a, b, ec) && !ec;
}

// Each DIR holds a run file, and no directory is given twice (it would be claimed twice).
void check_run_directories(const std::vector<fs::path>& run_dirs) {
  for (std::size_t i = 0; i < run_dirs.size(); ++i) {
    const fs::path run_file = run_dirs[i] / "run.h5";
    std::error_code ec;
    const fs::file_status status = fs::status(run_file, ec);
    if (!fs::exists(status))
      throw UserError("'" + run_file.string() +
                      "' does not exist: granshock fields analyses the run.h5 of a run directory");
    if (!fs::is_regular_file(status))
      throw UserError("'" + run_file.string() + "' is not a regular file");
    for (std::size_t j = 0; j < i; ++j)
      if (same_directory(run_dirs[i], run_dirs[j]))
        throw UserError("run directory '" + run_dirs[i].string() + "' is given twice (as '" +
                        run_dirs[j].string() + "')");
  }
}

bool held_by_caller(const FieldsCommandOptions& o, const fs::path& dir) {
  return o.held != nullptr && same_directory(o.held->path(), dir);
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
  check_run_directories(run_dirs);
  // Each run's analysis goes into its own run directory, or (one run) into OUT; OUT takes
  // the comparison of several (docs/output_format.md, "The fields directory").
  const bool in_place = several || out.empty() || same_directory(out, run_dirs[0]);
  const bool writes_out = !in_place || several;
  const FieldsOutput out_kind = several ? FieldsOutput::comparison : FieldsOutput::one_run;

  // Every directory is locked from before its first read to after its last write (the
  // figures), so that no run replaces run.h5 meanwhile: a run directory written in place
  // exclusively, one only read (its analysis goes to --out) shared, which refuses a run but
  // not another reader. Every run is analysed and every summary read before anything is
  // written.
  std::vector<RunDirectory> claimed;
  std::vector<DirectoryLock> read_locks;
  for (const fs::path& dir : run_dirs) {
    if (!in_place) {
      if (std::optional<DirectoryLock> lock = hold_for_reading(dir))
        read_locks.push_back(std::move(*lock));
    } else if (!held_by_caller(o, dir)) {
      claimed.push_back(RunDirectory::hold(dir, DirectoryMode::fields));
    }
  }
  if (writes_out) FieldsDirectory::check(out, out_kind);
  std::vector<FieldAnalysis> analyses;
  for (const fs::path& dir : run_dirs) {
    if (o.before_read) o.before_read(dir);
    analyses.push_back(analyse_run_file(dir / "run.h5"));
  }
  std::vector<nlohmann::json> summaries;
  for (const fs::path& dir : run_dirs) summaries.push_back(read_summary_json(dir / "summary.json"));

  // Then claimed: marked as this command's, and still locked until the figures are drawn.
  for (RunDirectory& held : claimed) held.settle();
  std::optional<FieldsDirectory> out_dir;
  if (writes_out) out_dir.emplace(FieldsDirectory::claim(out, out_kind));

  std::vector<Done> done;
  for (std::size_t i = 0; i < run_dirs.size(); ++i) {
    const fs::path& dir = run_dirs[i];
    const fs::path dest = in_place ? dir : out;
    const RunTarget target = target_mach(dir / "summary.json", analyses[i].ma_target);
    set_target_mach(analyses[i], target.mach, target.at_inlet);
    write_fields_outputs(analyses[i], dest);
    Done d{dir, dest, detachment_row(dir, analyses[i], target.mach),
           analyses[i].steadiness.warning};
    nlohmann::json keys = summary_keys(analyses[i]);
    // summary.json keeps every warning printed about its run (docs/output_format.md): the
    // run's own, then these about its data.
    nlohmann::json warnings = summaries[i].value("warnings", nlohmann::json::array());
    if (!warnings.is_array()) warnings = nlohmann::json::array();
    for (const std::string& w : data_warnings(d))
      if (std::find(warnings.begin(), warnings.end(), w) == warnings.end()) warnings.push_back(w);
    keys["warnings"] = warnings;
    if (in_place)
      merge_summary_json(dest / "summary.json", keys);  // read again, under the lock
    else
      write_summary_json(dest / "summary.json", summaries[i], keys);
    done.push_back(d);
  }
  if (several) {
    std::vector<DetachmentRow> rows;
    for (const Done& d : done) rows.push_back(d.row);
    write_detachment_table(out, rows);
  }

  if (o.figures) {
    require_plotting_python();
    std::vector<std::pair<fs::path, fs::path>> runs;
    for (const Done& d : done) runs.emplace_back(d.dest / "fields.h5", d.dest / "figures");
    plot_run_figures(runs);
    if (several)
      plot_detachment_figure(out / "detachment.json", out / "figures" / "detachment_length.png");
  }

  // A short inflow and an unsteady window are warnings about the data, printed even when
  // the result line is not.
  for (const Done& d : done)
    for (const std::string& w : data_warnings(d)) {
      const std::string line = "granshock: warning: " + w;
      if (o.say)
        o.say(line);
      else
        std::cerr << line << "\n";
    }
  if (!o.quiet) {
    for (const Done& d : done) std::cout << result_line(d) << "\n";
    if (several) std::cout << "granshock fields: comparison in " << out.string() << "\n";
  }
  return 0;
}

}  // namespace granshock
