// The inflow's Mach number measured where the paper measures it (docs/fields.md, "Three
// upstream Mach numbers"): over the first two bin rows from the inlet, with T and phi
// averaged there. Particles are inserted with the fluctuation sigma; between the strip
// and those rows they collide and cool, and the rows' phi is still building up, so the
// measured Ma differs from the inserted one (by +5 % at the paper's U = 1 m/s, +10 % at
// 0.475 m/s). With `inflow.mach_at = "inlet_bins"` sigma is calibrated before the run so
// that the measured Ma meets the target.
//
// The measurement is a short run of a channel as wide as the scene (at most
// InletChannel::max_width_bins bins) and InletChannel::length_bins bins long, without the
// obstacle, fed by the scene's inflow. Its statistics are accumulated on the host from
// particle copies in a fixed order, so the calibration is bitwise reproducible (a resumed
// run recomputes the same sigma).
#pragma once

#include <vector>

#include "core/scene.hpp"
#include "core/solver.hpp"

namespace granshock {

struct InletChannel {
  static constexpr int max_width_bins = 200;  // the paper's 500 d in 3 d bins
  static constexpr int length_bins = 4;       // the two measured rows and two beyond them
  // Particles that should pass through the measured rows in the averaging window: a
  // relative error of the Mach number of about 0.5 / sqrt(visits) (T from 2 components).
  static constexpr double visits = 6000;
  static constexpr int blocks = 8;
};

struct InletMach {
  double sigma = 0;     // inserted fluctuation, m/s
  double mach = 0;      // measured over the first two rows (the scene's mass definition)
  double mach_err = 0;  // block standard error
  double mach_mixture_mean = 0, mach_paper_sum = 0;
  double phi = 0;  // measured over the same rows
  double simulated_s = 0;
};

// Ma over the first two bin rows of the inlet channel fed with fluctuation sigma.
InletMach measure_inlet_mach(const Scene& scene, double sigma,
                             Backend backend = Backend::default_space);

struct InletCalibration {
  double target = 0;
  double sigma_inserted = 0;  // the fluctuation of the inserted convention (the first guess)
  std::vector<InletMach> iterations;
  double sigma = 0;  // the one chosen: the last iterate
  bool converged = false;
  double tolerance = 0;  // relative, on the Mach number
  // The iterate whose sigma was chosen.
  const InletMach& chosen() const;
};

// Fixed-point iteration sigma <- sigma Ma_measured / Ma_target (a secant step in log sigma
// from the second iterate on) until the measured Ma is within max(1 %, 2 block errors) of
// the target, at most max_iterations runs. Each step is clamped to a factor of 2.
// The channel runs on `backend` (one thread where the machine is busy: the same sigma).
InletCalibration calibrate_inlet_mach(const Scene& scene, int max_iterations = 6,
                                      Backend backend = Backend::default_space);

}  // namespace granshock
