// The field analysis of one run written beside its data (docs/fields.md): what `granshock
// fields` does for each run directory and what `granshock run` does at the end of its own
// run, without the command's arguments, locks or comparison of several runs.
#pragma once

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "analysis/detachment_table.hpp"
#include "analysis/field_analysis.hpp"

namespace granshock {

struct AnalysedRun {
  std::filesystem::path run_dir, dest;
  DetachmentRow row;
  std::string steady_warning;  // empty when the window is steady (docs/fields.md, section 12)

  // The warnings about the run's data (a short inflow, an unsteady window), each naming it.
  std::vector<std::string> data_warnings() const;
  // One line for the terminal; an undeterminable number is "n/a", and delta/D and the shock
  // angle say why in brackets.
  std::string result_line() const;
};

// Writes the analysis of the run in run_dir into dest: fields.h5, fields.xmf and the
// summary keys, merged into dest/summary.json when dest is the run's own directory
// (in_place), else written over `summary` (the run's summary.json as read before). The
// caller holds both directories; no figures are drawn here.
AnalysedRun write_run_analysis(const std::filesystem::path& run_dir,
                               const std::filesystem::path& dest, FieldAnalysis& analysis,
                               const nlohmann::json& summary, bool in_place);

// Whether run_dir/run.h5 exists and holds field sums (/fields/grid): a run stopped before
// its production window has none, and `granshock run` can skip the fields then.
bool run_has_field_sums(const std::filesystem::path& run_dir);

// The analysis of a run that has just finished, into its own directory, which the caller
// holds (`granshock run`): reads run.h5, writes the outputs, draws the figures when asked
// (figures.hpp), and says each data warning through `say`. Throws UserError as `granshock
// fields` does.
AnalysedRun analyse_finished_run(const std::filesystem::path& run_dir, bool figures,
                                 const std::function<void(const std::string&)>& say);

}  // namespace granshock
