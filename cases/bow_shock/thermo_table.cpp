#include "cases/bow_shock/thermo_table.hpp"

#include <fcntl.h>
#include <fmt/format.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <iostream>

#include "core/user_error.hpp"
#include "io/marked_directory.hpp"

namespace granshock {

namespace {

// Every column once: the header's names and the rows' widths agree by construction.
constexpr const char* kRowFormat =
    "{:>12} {:>12} {:>10} {:>9} {:>13} {:>13} {:>10} {:>10} {:>11} {:>6} {:>9}";

}  // namespace

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

ThermoFile::~ThermoFile() {
  if (fd_ >= 0) ::close(fd_);
}

void ThermoFile::open(const std::filesystem::path& dir, const std::string& leg_note) {
  if (fd_ >= 0) return;
  path_ = dir / "thermo.txt";
  fd_ = ::open(path_.c_str(), O_WRONLY | O_APPEND | O_CREAT | O_NOFOLLOW | O_CLOEXEC, 0644);
  if (fd_ < 0)
    throw UserError(fmt::format("cannot write '{}': {}", path_.string(), std::strerror(errno)));
  struct stat st {};
  if (::fstat(fd_, &st) == 0 && st.st_nlink > 1) {
    ::close(fd_);
    fd_ = -1;
    refuse_hard_link(path_, st.st_nlink);
  }
  if (st.st_size == 0) write(thermo_header());
  write("# " + leg_note);
}

void ThermoFile::append(const ThermoRow& row) {
  if (fd_ >= 0) write(thermo_line(row));
}

void ThermoFile::write(const std::string& line) {
  if (failed_) return;
  const std::string text = line + "\n";
  const ssize_t n = ::write(fd_, text.data(), text.size());  // one whole line per write
  if (n == ssize_t(text.size())) return;
  failed_ = true;
  std::cerr << fmt::format(
      "granshock: warning: writing '{}' failed ({}); the run goes on without its thermo table\n",
      path_.string(), n < 0 ? std::strerror(errno) : "a short write");
}

}  // namespace granshock
