// Whether a run's production window is steady (docs/fields.md, section 12): the window
// must start after the gas that met the obstacle at t = 0 has left the domain, the
// particle count and kinetic energy (run.h5 /observables) must not drift between the
// window's halves by more than their scatter allows, and the detachment length on the
// stagnation line must agree between the halves within its errors. A run that fails any
// of these is flagged; its numbers still stand, with the warning beside them.
#pragma once

#include <string>
#include <vector>

#include "analysis/detachment_convergence.hpp"
#include "analysis/field_physics.hpp"

namespace granshock {

struct SteadinessRule {
  // A series drifts when its halves' means differ by more than this many times the
  // scatter about them: a pure ramp gives sqrt(12) = 3.46, white noise 2/sqrt(rows).
  double max_drift_over_scatter = 2;
  int min_rows_per_half = 4;  // time-series rows each half needs for a verdict
  // The halves' detachment lengths may differ by this many combined errors.
  double max_front_shift_over_error = 2;
};

// One time series over the window, cut into halves at the window's middle.
struct HalvesTrend {
  bool determined = false;  // enough rows in each half
  int rows = 0;             // rows inside the window
  double first_mean = 0, second_mean = 0;
  double scatter = 0;             // pooled standard deviation about each half's mean
  double drift_over_scatter = 0;  // (second - first) / scatter, signed
  double relative_drift = 0;      // (second - first) / |mean of the window|
  bool steady = true;             // true when undetermined: no evidence either way
  std::string reason;             // why undetermined (empty when determined)
};

struct FrontHalves {
  bool determined = false;
  double first_over_D = 0, second_over_D = 0;  // primary delta/D of each half
  double first_err = 0, second_err = 0;        // their errors (NaN: none)
  double shift_over_error = 0;                 // |second - first| / combined error
  bool steady = true;
  std::string reason;
};

struct Steadiness {
  bool steady = true;
  double flow_through_time = 0;  // L / U, s
  double washout_time = 0;       // (L - (y_c - R)) / U (L / U without obstacle), s
  double window_start = 0, window_end = 0;
  bool start_after_washout = true;
  HalvesTrend particles, kinetic_energy;
  FrontHalves front;
  std::string warning;  // one line naming every failed check; empty when steady
};

HalvesTrend halves_trend(const std::vector<double>& time, const std::vector<double>& values,
                         double window_start, double window_end, const SteadinessRule& rule = {});

// The halves of the window from the convergence table ("window" cuts), primary definition.
FrontHalves front_halves(const DetachmentConvergence& convergence, double diameter,
                         const SteadinessRule& rule = {});

struct RunSeries {
  std::vector<double> time, particles, kinetic_energy;
};

Steadiness assess_steadiness(const RunSeries& series, double window_start, double window_end,
                             const FieldPhysics& physics, const DetachmentConvergence& convergence,
                             const SteadinessRule& rule = {});

}  // namespace granshock
