// Skipping the figures (docs/fields.md, "figures/"): drawing them with matplotlib takes
// seconds per run where the rest of the analysis takes a fraction of one. `--no-figures`
// (run, fields, study, tradeoff) or GRANSHOCK_FIGURES=0 in the environment writes every
// other output; `granshock fields DIR` draws the figures later from fields.h5.
#pragma once

#include <string>
#include <vector>

namespace granshock {

// Whether figures are drawn when no flag says otherwise: not when GRANSHOCK_FIGURES is
// 0, off, no or false (any case); otherwise yes, unset included.
bool figures_by_default();

// The line that says the figures were skipped, why (--no-figures or the environment) and
// the command that draws them later: `redraw`, one shell word each, quoted where needed.
std::string figures_skipped_note(const std::vector<std::string>& redraw);

}  // namespace granshock
