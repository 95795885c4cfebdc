// `granshock fields DIR... [--out DIR]` (docs/design.md, "The command-line contract"): recompute
// the fields, derived quantities, figures and summary keys from each DIR/run.h5.
#pragma once

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "analysis/figure_switch.hpp"

namespace granshock {

struct FieldsCommandOptions {
  // Draw the PNG figures (needs Python with matplotlib; figure_switch.hpp).
  bool figures = figures_by_default();
  bool quiet = false;  // no result line on stdout
  // Called just before each DIR/run.h5 is read, with DIR: what another process could do
  // meanwhile, for the tests of the directory's lock (tests/fields/test_fields_command.cpp).
  std::function<void(const std::filesystem::path&)> before_read = nullptr;
};

// For each run directory DIR: reads DIR/run.h5, writes fields.h5, fields.xmf,
// figures/*.png and merges its keys into summary.json, all in DIR (or, with one DIR and a
// non-empty `out`, in `out`, starting from DIR/summary.json). With several directories it
// also writes the comparison of their detachment lengths (the paper's Fig. 6) into `out`:
// detachment.csv, detachment.json and figures/detachment_length.png; `out` is then
// required. Directories follow the rules of docs/output_format.md: DIR is written only
// when granshock marked it as a run directory, under its lock; `out` must be new, empty,
// or a directory `granshock fields` made (or, for a comparison, a study directory); every
// output is a file granshock creates itself. All of that, the runs and their summaries
// are checked before anything is written. The files that do not need Python are written
// before the figures, so that a missing matplotlib costs only the PNGs. An inflow that
// misses its target phi_inf is a warning on stderr (docs/fields.md, section 10), printed
// also when `quiet`. Returns 0; throws UserError for bad input (no run.h5, no field sums,
// a summary.json that is not a JSON object, a directory it may not write, several DIRs
// without `out`, no matplotlib).
int fields_command(const std::vector<std::filesystem::path>& run_dirs,
                   const std::filesystem::path& out);
// The same, without figures or without the result line on stdout.
int fields_command(const std::vector<std::filesystem::path>& run_dirs,
                   const std::filesystem::path& out, const FieldsCommandOptions& options);

}  // namespace granshock
