// The comparison of several runs (the paper's Fig. 6): delta/D against D/d for each
// upstream Mach number, as a CSV and a JSON table.
#pragma once

#include <array>
#include <filesystem>
#include <string>
#include <vector>

#include "analysis/field_analysis.hpp"

namespace granshock {

struct DetachmentRow {
  std::string run;             // the run directory
  double d_over_particle = 0;  // D/d
  double ma_inf_target = 0, ma_inf_measured = 0, ma_inf_measured_downstream = 0;
  double delta_over_D = 0, delta_over_D_err = 0;
  double phi_peak = 0, shock_angle_deg = 0;
  double phi_inf_deviation = 0;  // phi_inf beyond the strip / target - 1
  // Why a number is NaN (empty when it is a number), and the inflow warning (empty: none).
  std::string delta_over_D_reason, delta_over_D_err_reason, shock_angle_deg_reason;
  std::string inflow_warning;
  // delta/D and its error by every definition (kFrontDefinitions order), and whether the
  // primary one agrees with itself across analysis choices (NaN: undetermined).
  std::array<double, kFrontDefinitions.size()> by_definition{}, by_definition_err{};
  double consistent = 0, spread = 0;
  std::string verdict;
  // The fitted fronts' thickness w/d and its error: temperature_fit, density_fit.
  std::array<double, 2> fit_w_over_d{}, fit_w_over_d_err{};
};

DetachmentRow detachment_row(const std::filesystem::path& run_dir, const FieldAnalysis& analysis,
                             double ma_inf_target);

// Writes out_dir/detachment.csv and out_dir/detachment.json (a list of objects with the
// CSV's columns; NaN as an empty CSV cell and as JSON null, an empty reason as an empty cell
// and null), atomically.
void write_detachment_table(const std::filesystem::path& out_dir,
                            const std::vector<DetachmentRow>& rows);

}  // namespace granshock
