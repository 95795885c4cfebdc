#include "cases/bow_shock/thermo_table.hpp"

#include <fmt/format.h>

namespace granshock {

namespace {

// Every column once: the header's names and the rows' widths agree by construction.
constexpr const char* kRowFormat =
    "{:>12} {:>12} {:>10} {:>9} {:>13} {:>13} {:>10} {:>10} {:>11} {:>6} {:>9}";

}  // namespace

ThermoRow thermo_row(const TimeSeriesRow& r) {
  ThermoRow row;
  row.step = r.step;
  row.time_s = r.time;
  row.particles = r.particles;
  row.contacts = r.contacts;
  row.kinetic_energy_j = r.kinetic_energy;
  row.temperature_j = r.temperature;
  row.inserted = r.inserted;
  row.deleted = r.deleted_outlet + r.deleted_inlet;
  return row;
}

std::string thermo_header() {
  return fmt::format(kRowFormat, "Step", "Time", "Particles", "Contacts", "KinEng", "Temp",
                     "Inserted", "Deleted", "PartSteps/s", "Done", "ETA");
}

std::string thermo_line(const ThermoRow& r) {
  const long eta = r.eta_s < 0 ? 0 : r.eta_s;
  return fmt::format(kRowFormat, r.step, fmt::format("{:.6g}", r.time_s), r.particles, r.contacts,
                     fmt::format("{:.6e}", r.kinetic_energy_j),
                     fmt::format("{:.6e}", r.temperature_j), r.inserted, r.deleted,
                     fmt::format("{:.3e}", r.particle_steps_per_s),
                     fmt::format("{:.1f}%", r.done_percent),
                     fmt::format("{}:{:02d}:{:02d}", eta / 3600, eta / 60 % 60, eta % 60));
}

void ThermoFile::open(const std::filesystem::path& dir, const std::string& leg_note) {
  if (file_.is_open()) return;
  file_.open(dir / "thermo.txt");
  file_.append((file_.was_empty() ? thermo_header() + "\n" : std::string()) + "# " + leg_note +
               "\n");
}

void ThermoFile::append(const ThermoRow& row) {
  file_.append(thermo_line(row) + "\n");
}

}  // namespace granshock
