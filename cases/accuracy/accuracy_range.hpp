// Where a trade table's settings were shown to hold (docs/accuracy.md, "Where a certificate
// holds"): the span of D/d and Ma_inf over the scenes a table was measured or checked on.
// `--accuracy` certifies a setting only for a scene inside it.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "core/scene.hpp"

namespace granshock {

// A scene's place in the study's plane: the obstacle's frontal width (the D of delta/D,
// docs/fields.md) over the mean particle diameter (by area, weighted by number fraction) and the
// upstream Mach number the scene asks for (inflow.mach, or the one inflow.sigma gives by kinetic
// theory).
struct SceneCorner {
  double obstacle_over_particle = 0;  // 0: no obstacle
  double mach = 0;
};
SceneCorner scene_corner(const Scene& scene);

struct CertifiedRange {
  double obstacle_over_particle[2] = {0, 0};  // lowest and highest D/d
  double mach[2] = {0, 0};                    // lowest and highest Ma_inf
  std::vector<std::string> shown_on;          // the scenes it was measured or checked on
};

// The range of one scene (what `granshock tradeoff` writes for its own scene).
CertifiedRange range_of(const SceneCorner& corner, const std::string& scene_name);

// Whether `corner` lies inside `range`, within 0.5 % of either end (a scene's D/d and Ma
// come out of unit conversions).
bool holds_at(const CertifiedRange& range, const SceneCorner& corner);

// trade.json's "certified_range": {"D_over_d": [lo, hi], "mach": [lo, hi], "shown_on": [...]}.
nlohmann::json to_json(const CertifiedRange& range);
// "D/d 50 to 50, Ma 13.7 to 13.7 (shown on paper_d50_u2375)".
std::string describe(const CertifiedRange& range);

}  // namespace granshock
