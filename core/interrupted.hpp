// A run stopped by SIGINT or SIGTERM before it could write a checkpoint (during its setup:
// calibrations, the prefill): thrown at the next check, so that the run ends with one line
// and exit code 128 + signal (docs/output_format.md, "Signals") instead of dying silently.
#pragma once

#include <stdexcept>
#include <string>

namespace granshock {

class Interrupted : public std::runtime_error {
 public:
  explicit Interrupted(int signal)
      : std::runtime_error("interrupted by signal " + std::to_string(signal)), signal_(signal) {}
  int signal() const { return signal_; }
  int exit_code() const { return 128 + signal_; }

 private:
  int signal_;
};

}  // namespace granshock
