// A measured trade table (trade.json of `granshock tradeoff`, cases/tradeoff/trade_table.py)
// read as the settings `granshock run --accuracy` may choose and the error each is known to
// cost (docs/accuracy.md, "Choosing settings for an error budget").
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "cases/accuracy/accuracy_range.hpp"

namespace granshock {

// The answers a budget bounds: delta/D by each definition, the peak solid fraction and the
// measured upstream Mach number, each relative to the reference's value; and e_eff
// averaged over the phase of the first contact step (docs/accuracy.md).
inline const std::vector<std::string> kBudgetAnswers = {
    "delta_over_D.temperature_jump", "delta_over_D.sonic_line", "delta_over_D.density_threshold",
    "phi_peak", "ma_inf_measured"};

struct MeasuredSetting {
  std::string name;                      // the table's case
  std::vector<std::string> changed;      // scene keys changed against the scene as given
  double dt_over_tc = 0;                 // dt / t_c at the fastest impact (the guard's t_c)
  double softening = 1;                  // contact.softening
  bool single_precision = false;         // numerics.precision = "single"
  bool discrete_restitution = false;     // contact.restitution_mode = "discrete"
  double speedup = 0;                    // wall time of the reference / its own
  double particle_steps_per_second = 0;  // its measured rate; 0 where the table has none
  // Largest |e_eff / e - 1| over the pairs at the inflow speed and its dt: of one impact
  // whose first contact step falls at one phase of the time grid (for information), and
  // averaged over kCalibrationPhases phases, what a gas of impacts at every phase sees
  // and what the discrete restitution mode is calibrated on (the one judged).
  double e_eff_error = 0;
  double e_eff_error_phase_averaged = 0;
  // The largest relative error it is known not to exceed: over the phase-averaged e_eff
  // and every answer, (|difference from the reference| + k x noise) / |reference|, the
  // certificate of docs/accuracy.md ("The certificate"; a table of version 1:
  // max(|difference|, noise) / |reference|). Infinite when the setting lost an answer the
  // reference has.
  double error_bound = 0;
  std::string bound_by;  // the answer that sets error_bound
};

struct AccuracyTable {
  std::filesystem::path source;
  std::vector<MeasuredSetting> settings;  // in the table's order
  // The smallest bound any setting can have: k x the largest relative noise over the
  // answers.
  double noise_floor = 0;
  std::string noise_floor_by;
  // How many seeds the noise came from, and the factor on it of the certificate's bound
  // (trade.json "noise_seeds", "certificate": {"k"}; a table of version 1: from its
  // "noise_from", and 1).
  int noise_seeds = 2;
  double noise_factor = 1;
  // Where its settings were shown to hold ("certified_range"); none: a table from before
  // it was recorded, which certifies nowhere.
  std::optional<CertifiedRange> range;
};

// The version trade.json names in "table" (cases/tradeoff/trade_table.py writes it), and
// the one before it, still read: noise from seed pairs and bounds max(|difference|, noise).
inline constexpr const char* kTradeTableVersion = "granshock trade table 2";
inline constexpr const char* kTradeTableVersion1 = "granshock trade table 1";

// Reads trade.json; throws UserError naming the file and the cause where it cannot be read,
// is of another version or lacks the cases "reference", "scene" and "seed-2" or a setting's
// columns.
AccuracyTable read_accuracy_table(const std::filesystem::path& trade_json);

}  // namespace granshock
