// `granshock study STUDY.toml` (docs/study.md): runs a parameter study, a base scene and the
// overrides of each case, into one run directory per case, and tabulates the results.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "analysis/figure_switch.hpp"
#include "core/run_modes.hpp"

namespace granshock {

struct StudyOptions {
  std::filesystem::path study_file;
  std::filesystem::path out_dir;       // empty: the study file's out, else runs/<study name>
  std::vector<std::string> overrides;  // --set: every case, after the file's [study] set
  std::optional<long> only_case;       // --case K: run case K alone (array jobs); no table
  bool collect = false;                // build the table from the directories, run nothing
  std::optional<BatchScript> emit;     // slurm: write <out>/study.slurm, run nothing
  bool dry_run = false;                // list the cases with their overrides and cost
  long stop_after_steps = 0;           // passed to the case that runs: it stops, and the study
  bool quiet = false;                  // no progress lines from the runs
  // --accuracy BUDGET [--accuracy-table FILE]: each case's settings chosen for the budget
  // (docs/study.md, "An error budget"); empty: the settings as given.
  std::string accuracy;
  std::filesystem::path accuracy_table;
  // Each case's, the comparison's and the axes' figures (figure_switch.hpp).
  bool figures = figures_by_default();
  // Without figures: the command the closing note names to draw them later (default: this
  // study with --collect).
  std::vector<std::string> redraw;
};

// The process exit code: 0 every case (or case K) finished; 1 a case failed or, after the
// run or with --collect, is not finished (listed; the table has its row); 130/143 stopped by
// SIGINT/SIGTERM after the running case's checkpoint. Throws UserError for a bad study, a
// case the run would refuse or an unusable directory, before any case runs.
int study_command(const StudyOptions& options);

}  // namespace granshock
