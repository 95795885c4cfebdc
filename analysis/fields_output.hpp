// The files of `granshock fields` for one run directory: fields.h5 + fields.xmf (every
// field on the bin grid, the lines, the profile; io/fields_file.hpp, io/fields_xdmf.hpp)
// and the keys it adds to summary.json. Layout: docs/fields.md.
#pragma once

#include <filesystem>
#include <nlohmann/json.hpp>

#include "analysis/field_analysis.hpp"
#include "io/fields_file.hpp"

namespace granshock {

FieldsFileContent fields_file_content(const FieldAnalysis& analysis);

// The convergence table of delta (docs/fields.md, "Convergence table") as CSV: one row per
// analysis choice, delta/D and its error by every definition; empty cells where undetermined.
std::string convergence_csv(const FieldAnalysis& analysis);

// Writes dir/fields.h5, dir/fields.xmf and dir/detachment_convergence.csv (atomically).
void write_fields_outputs(const FieldAnalysis& analysis, const std::filesystem::path& dir);

// The summary.json keys: ma_inf_target, ma_inf_measured, ma_inf_measured_downstream,
// phi_inf_measured, delta_over_D, delta_over_D_err, phi_peak, shock_angle_deg,
// eos_deviation_dilute, eos_deviation_dense, the inflow against its target, mass_definition,
// and a few more that say how they were obtained (docs/fields.md). NaN becomes null, with
// KEY_reason saying why (null when KEY is a number).
nlohmann::json summary_keys(const FieldAnalysis& analysis);

}  // namespace granshock
