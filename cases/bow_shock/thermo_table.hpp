// The run's thermo table, as LAMMPS' thermo output (docs/output_format.md, "thermo.txt"):
// one row per progress report (every output.progress_interval of wall time, and at the
// end of each leg) with the step, the simulated time, the particles, contacts, kinetic
// energy, temperature, insertions, deletions, the rate, the share done and the ETA, in
// columns a header names. The rows go to stderr and log.txt as the progress lines, and to
// thermo.txt in the run directory, which `pandas.read_csv(path, sep=r"\s+", comment="#")`
// reads as it is: a header at the top, a "#" comment where each leg starts.
#pragma once

#include <filesystem>
#include <string>

#include "core/time_series.hpp"
#include "io/appended_file.hpp"

namespace granshock {

struct ThermoRow {
  long step = 0;
  double time_s = 0;
  long particles = 0;
  long contacts = 0;
  double kinetic_energy_j = 0;  // translational + rotational, J (as /observables)
  double temperature_j = 0;     // mixture granular temperature, J
  long inserted = 0;            // cumulative since the run's start
  long deleted = 0;             // cumulative, through the outlet and the inlet
  double particle_steps_per_s = 0;
  double done_percent = 0;
  long eta_s = 0;
};

// The state columns of a row (step to deleted) from the run's time-series row.
ThermoRow thermo_row(const TimeSeriesRow& row);

// The header line, and a row under it: fixed-width columns separated by blanks, no blank
// inside a value (the ETA is H:MM:SS).
std::string thermo_header();
std::string thermo_line(const ThermoRow& row);

// DIR/thermo.txt, appended to as log.txt is (io/appended_file.hpp): one of the run's
// outputs, never through a link, a hard-linked file refused, a failed write said once. A
// new file starts with the header; each leg starts with a comment.
class ThermoFile {
 public:
  // Opens DIR/thermo.txt and writes "# leg_note" (the header first when the file is new).
  // Throws UserError when it cannot be opened.
  void open(const std::filesystem::path& dir, const std::string& leg_note);
  void append(const ThermoRow& row);

 private:
  AppendedFile file_{"its thermo table"};
};

}  // namespace granshock
