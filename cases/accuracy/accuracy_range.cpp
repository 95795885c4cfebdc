#include "cases/accuracy/accuracy_range.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <cmath>

#include "models/obstacle_shapes.hpp"

namespace granshock {

SceneCorner scene_corner(const Scene& s) {
  SceneCorner c;
  const double d = s.mean_particle_diameter();
  if (s.setup.obstacle) c.obstacle_over_particle = obstacle_frontal_width(*s.setup.obstacle) / d;
  c.mach = s.inflow_mach();
  return c;
}

CertifiedRange range_of(const SceneCorner& c, const std::string& scene_name) {
  CertifiedRange r;
  r.obstacle_over_particle[0] = r.obstacle_over_particle[1] = c.obstacle_over_particle;
  r.mach[0] = r.mach[1] = c.mach;
  r.shown_on = {scene_name};
  return r;
}

namespace {
bool within(double value, const double (&span)[2]) {
  constexpr double kSlack = 0.005;
  return value >= span[0] * (1 - kSlack) && value <= span[1] * (1 + kSlack);
}
}  // namespace

bool holds_at(const CertifiedRange& r, const SceneCorner& c) {
  return c.obstacle_over_particle > 0 && c.mach > 0 &&
         within(c.obstacle_over_particle, r.obstacle_over_particle) && within(c.mach, r.mach);
}

nlohmann::json to_json(const CertifiedRange& r) {
  return {{"D_over_d", {r.obstacle_over_particle[0], r.obstacle_over_particle[1]}},
          {"mach", {r.mach[0], r.mach[1]}},
          {"shown_on", r.shown_on}};
}

std::string describe(const CertifiedRange& r) {
  return fmt::format("D/d {:.3g} to {:.3g}, Ma {:.3g} to {:.3g} (shown on {})",
                     r.obstacle_over_particle[0], r.obstacle_over_particle[1], r.mach[0], r.mach[1],
                     fmt::join(r.shown_on, ", "));
}

}  // namespace granshock
