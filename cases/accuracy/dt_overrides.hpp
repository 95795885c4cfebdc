// The overrides that run a scene at another time step (docs/accuracy.md): what the trade
// table's settings (cases/tradeoff/tradeoff_plan.hpp) and the settings `--accuracy`
// chooses (accuracy_choice.hpp) apply, so that both sample the same simulated times.
#pragma once

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "core/scene.hpp"

namespace granshock {

// time.dt = dt and the sample interval (in steps) that keeps the scene's sampling interval
// in simulated time, at least one step.
inline std::vector<std::string> overrides_at_dt(const Scene& s, double dt) {
  const double interval = double(s.run.sample_every) * s.setup.dt;
  const long every = std::max(1L, std::lround(interval / dt));
  return {fmt::format("time.dt={:.9g}", dt), fmt::format("output.sample_every={}", every)};
}

}  // namespace granshock
