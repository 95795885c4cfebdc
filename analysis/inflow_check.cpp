#include "analysis/inflow_check.hpp"

#include <cmath>
#include <cstdio>
#include <limits>

namespace granshock {

InflowCheck check_inflow(const UpstreamState& u, double phi_err, const std::string& phi_err_reason,
                         double phi_target, double ma_target, const std::string& ma_target_reason,
                         const InflowTolerance& tol) {
  constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  InflowCheck c;
  c.phi_target = phi_target;
  c.phi_measured = u.phi;
  c.ma_target = ma_target;
  c.ma_measured = u.mach;
  c.phi_deviation = c.ma_deviation = c.phi_err = kNaN;
  const std::string no_state = "no upstream state beyond the strip: " + u.reason;
  if (!u.determined()) {
    c.phi_deviation_reason = c.phi_err_reason = c.ma_deviation_reason = no_state;
    return c;
  }
  c.phi_deviation = u.phi / phi_target - 1;
  c.phi_err = phi_err;
  if (!std::isfinite(phi_err)) c.phi_err_reason = phi_err_reason;
  if (std::isfinite(ma_target) && ma_target > 0)
    c.ma_deviation = u.mach / ma_target - 1;
  else
    c.ma_deviation_reason = "no target Ma_inf: " + ma_target_reason;

  c.phi_short = c.phi_deviation < -tol.phi_shortfall;
  if (!c.phi_short) return c;
  char text[400];
  std::snprintf(text, sizeof text,
                "phi_inf measured beyond the insertion strip, %.4g, is %.1f %% below the target "
                "inflow.area_fraction = %.4g (tolerance %.0f %%)",
                u.phi, -100 * c.phi_deviation, phi_target, 100 * tol.phi_shortfall);
  c.warning = text;
  const double shortfall = phi_target - u.phi;
  if (std::isfinite(phi_err)) {
    if (shortfall > tol.significance * phi_err)
      std::snprintf(text, sizeof text,
                    "; statistical error %.2g, so the shortfall is significant (over %g errors)",
                    phi_err, tol.significance);
    else
      std::snprintf(text, sizeof text,
                    "; statistical error %.2g, so the shortfall is within %g errors (more "
                    "samples would tell)",
                    phi_err, tol.significance);
    c.warning += text;
  } else {
    c.warning += "; no statistical error (" + phi_err_reason + ")";
  }
  c.warning += "; Ma_inf and delta/D belong to the measured state, not the target";
  return c;
}

}  // namespace granshock
