// When must the Verlet list be rebuilt? Once some particle has moved more than skin/2
// from its position at the last build (docs/design.md, "The skin test"). Measuring that
// exactly reads every particle's reference position each step; this watch avoids most of
// those reads with a bound that needs only the fastest particle's speed of each step:
//
//   no particle has moved more than  B = d + sum over the drifts since of dt * max|v|,
//
// where d is the largest displacement at the last exact measurement (0 at a build). While
// B stays below skin/2 (less a margin far above round-off), the exact test would answer
// "still valid" as well; only when B reaches it is the exact displacement measured. So the
// list is rebuilt at exactly the steps the exact test gives, and the trajectory is bitwise
// that of measuring every step (tests/unit/test_rebuild_watch.cpp).
// The bookkeeping is the host's (the kernels report max|v|^2 or the exact max
// displacement^2); its bound alone, SpeedBound, also runs inside the host backends'
// multi-step pass (solver/fused_steps.hpp), and the whole watch on the device between the
// chained steps of device paths (solver/chained_steps.hpp): both must decide as the host
// would, so every member is callable on either side.
#pragma once

#include <Kokkos_Core.hpp>

#include "kernels/device/device_math.hpp"

namespace granshock {

// B and the top speed of the last drift, and the two questions asked of them.
struct SpeedBound {
  double limit, dt;
  double bound = 0;
  // The top speed of the last drift reported by speed (0 before the first: that drift
  // is then reported by speed, and at worst one exact pass follows).
  double speed = 0;

  // A drift is reported by speed only while this many more steps at the last known top
  // speed keep the bound below the limit; near the limit every step is measured exactly
  // instead of paying an extra exact pass after a bound that failed.
  static constexpr double lookahead_steps = 16;

  KOKKOS_INLINE_FUNCTION void drifted(double max_v2) {
    speed = dmath::sqrt(max_v2);
    bound += dt * speed;
  }
  KOKKOS_INLINE_FUNCTION bool proves_valid() const { return bound < limit; }
  KOKKOS_INLINE_FUNCTION bool next_drift_by_speed() const {
    return bound + lookahead_steps * dt * speed < limit;
  }
};

class RebuildWatch {
 public:
  // rebuild_distance: skin/2; dt: the drift's time step.
  KOKKOS_INLINE_FUNCTION RebuildWatch(double rebuild_distance, double dt)
      : bound_{rebuild_distance * (1 - margin), dt} {}
  RebuildWatch() = default;  // a device View's element, assigned before use

  // The largest squared displacement since the last build, measured exactly.
  KOKKOS_INLINE_FUNCTION void measured(double max_d2) {
    exact_d2_ = max_d2;
    bound_.bound = dmath::sqrt(max_d2);
  }
  // A drift by dt at speeds up to sqrt(max_v2) happened and was not measured.
  KOKKOS_INLINE_FUNCTION void drifted(double max_v2) {
    exact_d2_ = unknown;
    bound_.drifted(max_v2);
  }
  KOKKOS_INLINE_FUNCTION void rebuilt() { measured(0); }

  // True when the exact displacement is known for the current positions.
  KOKKOS_INLINE_FUNCTION bool exact_known() const { return exact_d2_ >= 0; }
  KOKKOS_INLINE_FUNCTION double exact_d2() const { return exact_d2_; }
  // True when the bound proves the list still valid: no exact measurement needed.
  KOKKOS_INLINE_FUNCTION bool bound_proves_valid() const { return bound_.proves_valid(); }
  // Whether the next drift should report speeds (the bound) rather than the exact
  // displacement: only while the bound is far enough from the limit that measuring
  // exactly afterwards is unlikely. A heuristic: the answer changes the cost, never the
  // rebuild steps.
  KOKKOS_INLINE_FUNCTION bool next_drift_by_speed() const { return bound_.next_drift_by_speed(); }
  KOKKOS_INLINE_FUNCTION const SpeedBound& speed_bound() const { return bound_; }

  // Far above the relative round-off of the displacements and speeds (single precision
  // included), so that B < limit implies the computed displacement is below skin/2.
  static constexpr double margin = 1e-4;

 private:
  static constexpr double unknown = -1;
  SpeedBound bound_{0, 0};
  double exact_d2_ = 0;
};

}  // namespace granshock
