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
#include "analysis/run_analysis.hpp"
#include "analysis/summary_json.hpp"
#include "core/bin_sums.hpp"
#include "core/choice_names.hpp"
#include "core/user_error.hpp"
#include "io/field_sums_file.hpp"
#include "io/fields_directory.hpp"
#include "io/run_directory.hpp"
#include "io/run_file.hpp"

namespace granshock {

namespace fs = std::filesystem;

namespace {

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

}  // namespace

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
    } else {
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

  std::vector<AnalysedRun> done;
  for (std::size_t i = 0; i < run_dirs.size(); ++i)
    done.push_back(write_run_analysis(run_dirs[i], in_place ? run_dirs[i] : out, analyses[i],
                                      summaries[i], in_place));
  if (several) {
    std::vector<DetachmentRow> rows;
    for (const AnalysedRun& d : done) rows.push_back(d.row);
    write_detachment_table(out, rows);
  }

  if (o.figures) {
    require_plotting_python();
    std::vector<std::pair<fs::path, fs::path>> runs;
    for (const AnalysedRun& d : done) runs.emplace_back(d.dest / "fields.h5", d.dest / "figures");
    plot_run_figures(runs);
    if (several)
      plot_detachment_figure(out / "detachment.json", out / "figures" / "detachment_length.png");
  }

  // A short inflow and an unsteady window are warnings about the data, printed even when
  // the result line is not.
  for (const AnalysedRun& d : done)
    for (const std::string& w : d.data_warnings()) std::cerr << "granshock: warning: " << w << "\n";
  if (!o.quiet) {
    for (const AnalysedRun& d : done) std::cout << d.result_line() << "\n";
    if (several) std::cout << "granshock fields: comparison in " << out.string() << "\n";
  }
  return 0;
}

}  // namespace granshock
