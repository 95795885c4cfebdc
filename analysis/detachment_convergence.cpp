#include "analysis/detachment_convergence.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

namespace granshock {

namespace {
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

std::string format_d(const char* what, double size_d) {
  char text[48];
  std::snprintf(text, sizeof text, "%s %g d", what, size_d);
  return text;
}

// The tolerance of one comparison: two errors (the larger of the two for cuts of the same
// data, the combined one for independent data).
double tolerance(double err_ref, double err_choice, bool independent) {
  if (!std::isfinite(err_ref) && !std::isfinite(err_choice)) return kNaN;
  const double a = std::isfinite(err_ref) ? err_ref : 0,
               b = std::isfinite(err_choice) ? err_choice : 0;
  return 2 * (independent ? std::sqrt(a * a + b * b) : std::max(a, b));
}
}  // namespace

const ConvergenceVerdict& DetachmentConvergence::of(FrontDefinition definition) const {
  for (const ConvergenceVerdict& v : verdicts)
    if (v.definition == definition) return v;
  return verdicts.front();
}

DetachmentConvergence detachment_convergence(const ConvergenceInput& in, const FieldPhysics& phys,
                                             const UpstreamValues& upstream,
                                             const DetachmentSearch& search) {
  DetachmentConvergence out;
  const BinSums& profile = *in.profile;
  const double d = phys.d;
  const BinSums strip = strip_of(profile, in.x_axis, in.strip_width);
  const double strip_d = strip.dx / d;
  auto add = [&](const std::string& kind, const std::string& label, double size_d,
                 const BinSums& column) {
    out.choices.push_back(
        {kind, label, size_d, measure_detachments(column, phys, upstream, search)});
  };

  // Rows merged from the face upstream: the bin size along the line.
  for (double rows_d : {0.5, 1.0, 1.5, 2.0, 3.0}) {
    const int k = static_cast<int>(std::lround(rows_d * d / strip.dy));
    if (k < 1 || std::abs(k * strip.dy - rows_d * d) > 0.25 * strip.dy || strip.ny / k < 2)
      continue;
    add("rows", format_d("rows", rows_d) + ", " + format_d("strip", strip_d), rows_d,
        k == 1 ? strip : strip.merged_rows(k, strip.ny));
  }
  // Strip widths, on the profile's own rows.
  if (profile.nx > 1)
    for (double width_d : {1.0, 2.0, 4.0, 6.0}) {
      if (width_d * d > profile.nx * profile.dx * (1 + 1e-9)) continue;
      add("strip", format_d("strip", width_d), width_d, strip_of(profile, in.x_axis, width_d * d));
    }
  // The grid's own column on the axis.
  if (in.grid != nullptr)
    add("grid_column", format_d("grid column", in.grid->dx / d), in.grid->dx / d,
        in.grid->column(in.axis_column));
  // The two halves of the window.
  if (strip.blocks >= 4) {
    const int half = strip.blocks / 2;
    add("window", "first half of the window", 0, strip.block_range(0, half));
    add("window", "second half of the window", 0, strip.block_range(half, strip.blocks));
  }

  for (std::size_t k = 0; k < kFrontDefinitions.size(); ++k) {
    ConvergenceVerdict v;
    v.definition = kFrontDefinitions[k];
    const Detachment& ref = (*in.reference)[k];
    v.applicable = ref.found;
    if (!v.applicable) {
      v.text = "no delta at the reference cut: " + ref.reason;
      v.max_deviation = kNaN;
      out.verdicts.push_back(v);
      continue;
    }
    v.consistent = true;
    double worst_ratio = 0;
    std::string failures;
    const Detachment* first_half = nullptr;
    for (const ConvergenceChoice& c : out.choices) {
      const Detachment& r = c.result[k];
      if (c.label == "first half of the window") first_half = &r;
      if (!r.found) {
        v.consistent = false;
        // Why, in the definition's own words: a verdict that names a cut without a front
        // should say what that cut lacked (too few bins, a fit that did not converge, ...).
        failures += (failures.empty() ? "" : "; ") + c.label + ": no front" +
                    (r.reason.empty() ? "" : " (" + r.reason + ")");
        continue;
      }
      // The halves are compared with each other, every other cut with the reference.
      const bool second_half = c.label == "second half of the window";
      const Detachment& base = second_half && first_half && first_half->found ? *first_half : ref;
      if (c.kind == "window" && !second_half) continue;
      const double deviation = std::abs(r.delta - base.delta);
      if (c.kind != "window") v.max_deviation = std::max(v.max_deviation, deviation);
      const double tol = tolerance(base.delta_err, r.delta_err, c.kind == "window");
      const double ratio =
          std::isfinite(tol) && tol > 0 ? deviation / tol : (deviation > 0 ? HUGE_VAL : 0.0);
      if (ratio > worst_ratio) {
        worst_ratio = ratio;
        v.worst = c.label;
      }
      if (ratio > 1) {
        v.consistent = false;
        char text[200];
        if (std::isfinite(tol))
          std::snprintf(text, sizeof text, "%s differs by %.3g d (two errors: %.3g d)",
                        c.label.c_str(), deviation / d, tol / d);
        else  // neither delta carries an error: nothing to compare the change with
          std::snprintf(text, sizeof text, "%s differs by %.3g d (two errors: n/a)",
                        c.label.c_str(), deviation / d);
        failures += (failures.empty() ? "" : "; ") + std::string(text);
      }
    }
    char text[160];
    std::snprintf(text, sizeof text,
                  "agrees with itself across %zu analysis choices within two errors "
                  "(largest change %.3g d)",
                  out.choices.size(), v.max_deviation / d);
    v.text = v.consistent ? std::string(text) : "does not agree with itself: " + failures;
    out.verdicts.push_back(v);
  }
  return out;
}

}  // namespace granshock
