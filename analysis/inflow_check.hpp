// Does the measured upstream state match what the scene asked for? phi_inf measured beyond
// the insertion strip against inflow.area_fraction, and Ma_inf measured there against the
// target, as relative deviations; a warning when phi_inf falls short of the target by more
// than a tolerance (docs/fields.md, "Inflow against target"): a short inflow means a
// different upstream state, so delta/D would be compared with the wrong Ma_inf and phi_inf.
#pragma once

#include <string>

#include "analysis/upstream_state.hpp"

namespace granshock {

struct InflowTolerance {
  // Flag phi_inf below (1 - phi_shortfall) of the target. 5 %: the inflow test
  // (tests/scene/test_inflow.cpp) holds the inserted phi to 5 % of the target, and a healthy
  // run sits well inside it (docs/fields.md, section 10).
  double phi_shortfall = 0.05;
  // A shortfall is called significant when it exceeds this many block standard errors.
  double significance = 2.0;
};

struct InflowCheck {
  double phi_target = 0, phi_measured = 0, phi_err = 0;  // phi_err: block standard error
  double phi_deviation = 0;                              // phi_measured / phi_target - 1
  double ma_target = 0, ma_measured = 0;
  double ma_deviation = 0;               // ma_measured / ma_target - 1
  std::string ma_rows = "beyond_strip";  // where ma_measured is taken: "beyond_strip" | "inlet"
  bool phi_short = false;                // phi_deviation < -phi_shortfall
  std::string warning;                   // one line when phi_short, else empty
  // Why a number is NaN (empty when it is a number).
  std::string phi_deviation_reason, phi_err_reason, ma_deviation_reason;
};

// beyond_strip: the upstream state one bin beyond the strip; phi_err: its block standard
// error (NaN when unknown, phi_err_reason says why); ma_target: the run's target (NaN when
// there is none, ma_target_reason says why).
InflowCheck check_inflow(const UpstreamState& beyond_strip, double phi_err,
                         const std::string& phi_err_reason, double phi_target, double ma_target,
                         const std::string& ma_target_reason, const InflowTolerance& = {});

}  // namespace granshock
