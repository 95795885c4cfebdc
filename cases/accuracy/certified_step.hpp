// A time step that `granshock run --accuracy` chose and a measured trade table certified
// within the budget (docs/accuracy.md, "Choosing settings for an error budget"): made here
// (accuracy_choice.hpp), read by the run's checks (cases/bow_shock/run_checks.hpp), which
// then say the step is certified instead of "results lose accuracy".
#pragma once

#include <string>

namespace granshock {

struct CertifiedStep {
  double dt = 0;    // s: the step chosen; a step up to it is certified
  std::string why;  // the measurement, one clause
};

}  // namespace granshock
