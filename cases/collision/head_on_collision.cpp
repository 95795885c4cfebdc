#include "cases/collision/head_on_collision.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <nlohmann/json.hpp>

#include "core/solver.hpp"
#include "core/user_error.hpp"
#include "models/law_parameters.hpp"
#include "models/obstacle_shapes.hpp"

namespace {
constexpr double kDiameter = 1e-3;  // the paper's d
}

namespace granshock {

namespace {

const std::vector<std::string> kPairs = {"steel-steel", "steel-aluminium", "aluminium-aluminium",
                                         "steel-obstacle", "aluminium-obstacle"};

// The collision's own small world: the scene's species, contacts and precision, an open
// box around the impact's place, and (for impacts on the obstacle) the obstacle's shape
// of the scene's obstacle material centred there.
struct Geometry {
  SolverSetup setup;
  double radius_a = 0, radius_b = 0;
  // The obstacle: from its centre to the surface the particle strikes, along the line.
  double surface = 0;
  bool on_obstacle = false;
  ImpactPlace place;
  // A coordinate along the line of impact, relative to the impact's place.
  double along(const std::array<double, 3>& position) const {
    return position[std::size_t(place.axis)] - place.centre[std::size_t(place.axis)];
  }
  // A point at distance s along the line of impact from the impact's place.
  std::array<double, 3> at(double s) const {
    std::array<double, 3> x = {place.centre[0], place.centre[1], 0};
    x[std::size_t(place.axis)] += s;
    return x;
  }
};

// `dmax`: the largest diameter of the whole scene, which sizes the box alike for every
// pair. `body`: the obstacle's shape and sizes, for an impact on it.
Geometry build(const SolverSetup& scene, int a, int b, double dt, const ImpactPlace& place,
               double dmax, const Obstacle& body, double surface) {
  Geometry g;
  g.on_obstacle = b < 0;
  g.place = place;
  g.setup.species = scene.species;
  g.setup.contacts = scene.contacts;
  g.setup.precision = scene.precision;
  g.setup.dt = dt;
  g.radius_a = scene.species[a].radius_m();
  g.radius_b = g.on_obstacle ? 0 : scene.species[b].radius_m();
  const double half = 20 * dmax;
  g.setup.box.lo = {place.centre[0] - half, place.centre[1] - half, 0};
  g.setup.box.hi = {place.centre[0] + half, place.centre[1] + half, dmax};
  if (g.on_obstacle) {
    Obstacle o = body;
    o.centre = g.at(0);
    o.material = scene.obstacle->material;
    g.setup.obstacle = o;
    g.surface = surface;
    // The box reaches at least 15 d_max upstream of the surface, as it did from the
    // default cylinder's (radius 5 d_max); the obstacle may reach past the box.
    const std::size_t k = std::size_t(place.axis);
    g.setup.box.lo[k] = place.centre[k] - std::max(half, surface + 15 * dmax);
  }
  return g;
}

// Surface-to-surface distance between the colliding bodies (negative = overlap): along the
// line of impact for two particles, from the obstacle's outline for the obstacle (what
// its contacts see: models/shape_outline.hpp).
double gap(const Geometry& g, const HostParticles& p) {
  if (g.on_obstacle)
    return obstacle_distance(*g.setup.obstacle, p.position[0][0], p.position[0][1]) - g.radius_a;
  return std::abs(g.along(p.position[1]) - g.along(p.position[0])) - g.radius_a - g.radius_b;
}

// Relative normal velocity, positive when separating.
double separation_speed(const Geometry& g, const HostParticles& p) {
  const std::size_t k = std::size_t(g.place.axis);
  if (g.on_obstacle) return -p.velocity[0][k];  // particle on the low side of the obstacle
  return p.velocity[1][k] - p.velocity[0][k];
}

// Whether the bodies have swapped sides: a particle past the surface it struck (through
// the obstacle, or around it), or the two particles in the wrong order along the line.
bool passed_through(const Geometry& g, const HostParticles& p) {
  if (g.on_obstacle) return g.along(p.position[0]) > -g.surface;
  return g.along(p.position[1]) < g.along(p.position[0]);
}

// From the obstacle's centre to its upstream surface on the flow's line (the axis x =
// centre): what the flow of a scene strikes first (models/obstacle_shapes.hpp).
double upstream_surface_distance(const Obstacle& body) {
  Obstacle at_origin = body;
  at_origin.centre = {0, 0, 0};
  double y = 0;
  if (!obstacle_upstream_surface(at_origin, 0, y))
    throw UserError(fmt::format("the {} ({}) has no surface on the flow's line: it is {:g} m wide",
                                choice_name(body.shape), obstacle_size_text(body),
                                obstacle_frontal_width(at_origin)));
  return -y;
}

// The particle strikes the obstacle `surface` before its centre on the line of impact
// (`axis`), and the impact must be head-on there: the point on the surface, and the
// surface's normal along the line (its sine within kHeadOnNormal), as the contacts see it
// (the outline's signed distance, whose gradient outside is the normal from the closest
// point). A wedge's apex and a square's corner at 45 degrees pass (a corner symmetric
// about the line); a slanted face does not. Returns what is struck: "flat face", "corner"
// or "curved surface".
std::string check_head_on(const Obstacle& body, int axis, double surface, double radius) {
  Obstacle o = body;
  o.centre = {0, 0, 0};
  const auto distance = [&](double before, double aside) {
    std::array<double, 2> x = {0, 0};
    x[std::size_t(axis)] = -before;
    x[std::size_t(1 - axis)] = aside;
    return obstacle_distance(o, x[0], x[1]);
  };
  const char* line = axis == 0 ? "x" : "y";
  const std::string shape = choice_name(o.shape);
  const double scale = surface + radius;
  if (std::abs(distance(surface, 0)) > 1e-9 * scale)
    throw UserError(fmt::format(
        "--along {}: the {} ({}) is struck on its upstream surface, {:.3g} m before its "
        "centre on the flow's line y, and the line along {} meets its surface elsewhere: "
        "strike it along y (the default for the obstacle)",
        line, shape, obstacle_size_text(o), surface, line));
  const double h = 1e-4 * radius;
  const double aside = (distance(surface + radius, h) - distance(surface + radius, -h)) / (2 * h);
  if (!(std::abs(aside) <= kHeadOnNormal))
    throw UserError(fmt::format(
        "the {} ({}) is not struck head-on: its surface where the line of impact along {} "
        "meets it is slanted, its normal {:.3g} degrees off the line; a head-on impact needs "
        "a face across the line or a corner symmetric about it there{}",
        shape, obstacle_size_text(o), line, std::asin(std::min(1.0, std::abs(aside))) * 180 / M_PI,
        axis == 1 ? "" : ": strike it along y, the flow's line (the default for the obstacle)"));
  const ShapeOutline outline = obstacle_outline(o);
  if (outline.kind == ShapeOutline::Kind::disk) return "curved surface";
  for (int c = 0; c < outline.corners; ++c) {
    std::array<double, 2> at = {0, 0};
    at[std::size_t(axis)] = -surface;
    if (std::hypot(outline.corner[c][0] - at[0], outline.corner[c][1] - at[1]) <= 1e-9 * scale)
      return "corner";
  }
  return "flat face";
}

int paper_species(const std::string& name) {
  return name == "steel" ? 0 : 1;
}

// collide_species against `body` (its shape and sizes; the setup's obstacle gives only
// the material).
CollisionResult collide(const SolverSetup& given, int a, int b, double speed, double dt, bool force,
                        double phase, const ImpactPlace& place, Backend backend,
                        const Obstacle& body) {
  // The pair's own species alone (a -> 0, b -> 1 or 0): summary.json collides every pair
  // of a scene, and a copy of every pair's tables per collision made that O(species^4).
  SolverSetup scene;
  std::vector<int> kept = {a};
  if (b >= 0 && b != a) kept.push_back(b);
  for (const int k : kept) scene.species.push_back(given.species.at(std::size_t(k)));
  scene.contacts = given.contacts.of_species(kept);
  scene.precision = given.precision;
  scene.obstacle = given.obstacle;
  const double dmax = given.max_diameter();
  b = b < 0 ? -1 : b == a ? 0 : 1;
  a = 0;
  // A scene without an obstacle collides with an aluminium cylinder: its pair properties
  // (softening, calibrated damping) then come from SolverSetup like any obstacle's.
  if (b < 0 && !scene.obstacle)
    scene.obstacle = make_obstacle(ObstacleShape::cylinder, {}, {0}, aluminium());
  const PairProperties props = b >= 0 ? scene.pair(a, b) : scene.obstacle_pair(a);
  CollisionResult r;
  r.pair = props.name;
  r.speed = speed;
  r.e_in = props.restitution;
  r.limit_force = scene.contacts.options.limit_force;
  r.phase = phase;
  r.place = place;
  r.beta = props.beta;
  r.model = to_string(scene.contacts.model);
  const ContactSettings& contacts = scene.contacts;
  r.t_c = collision_time(contacts.model, props, contacts.options, speed);
  r.dt = dt > 0 ? dt : r.t_c / 100.0;
  // The overlap first: an impact past the law's range also makes t_c, and with it the
  // default dt, meaningless.
  r.overlap = assess_overlap({props}, contacts.model, contacts.options, speed);
  if (r.overlap.verdict == TimeStepAssessment::Verdict::refuse && !force)
    throw UserError(r.overlap.message);
  r.time_step = assess_time_step({props}, contacts.model, contacts.options, speed, r.dt,
                                 contacts.has_friction());
  if (r.time_step.verdict == TimeStepAssessment::Verdict::refuse && !force)
    throw UserError(r.time_step.message);
  if (20.0 * r.t_c / r.dt > kMaxCollisionSteps)
    throw UserError(fmt::format(
        "time step dt = {:.3g} s would take {:.3g} steps to integrate the {} collision (t_c = "
        "{:.3g} s); collide integrates at most {:.0e}: use dt >= {:.3g} s",
        r.dt, 20.0 * r.t_c / r.dt, r.pair, r.t_c, kMaxCollisionSteps,
        20.0 * r.t_c / kMaxCollisionSteps));
  if (place.axis != 0 && place.axis != 1)
    throw UserError(fmt::format("the line of impact must be along x or y (axis {})", place.axis));
  for (const double c : place.centre)
    if (!std::isfinite(c)) throw UserError("the impact's place must be finite");
  // On the obstacle: where the particle strikes it, and that it strikes it head-on there.
  double surface = 0;
  std::array<double, 2> struck_at = place.centre;
  if (b < 0) {
    surface = upstream_surface_distance(body);
    r.struck = check_head_on(body, place.axis, surface, scene.species[a].radius_m());
    struck_at[std::size_t(place.axis)] -= surface;
  }
  const double drift = speed * r.dt;  // the relative drift of one step
  const double farthest = kPlaceResolution * drift / std::numeric_limits<double>::epsilon();
  // The place, and the point where the particle strikes the obstacle (the particle's
  // position is rounded there).
  const std::pair<const char*, std::array<double, 2>> points[] = {
      {"the impact's place", place.centre},
      {"the obstacle's surface where the particle strikes it", struck_at}};
  for (const auto& [what, at] : points)
    if (std::max(std::abs(at[0]), std::abs(at[1])) > farthest)
      throw UserError(fmt::format(
          "{} ({:g}, {:g}) m is too far from the origin: positions there are rounded to {:.3g} "
          "m, more than {:g} of the {:.3g} m the bodies approach per step at this speed and "
          "dt; place the impact within {:.3g} m of the origin",
          what, at[0], at[1],
          std::max(std::abs(at[0]), std::abs(at[1])) * std::numeric_limits<double>::epsilon(),
          kPlaceResolution, drift, farthest));
  Geometry g = build(scene, a, b, r.dt, place, dmax, body, surface);
  if (g.on_obstacle) {
    r.obstacle = g.setup.obstacle;
    r.struck_at = struck_at;
  }

  // Start a few steps before contact, in the zero-momentum frame for two particles; the
  // sixth drift overlaps them by phase x speed x dt.
  HostParticles start;
  const double gap0 = (6.0 - phase) * speed * r.dt;
  const auto velocity = [&](double u) {
    std::array<double, 3> v = {0, 0, 0};
    v[std::size_t(place.axis)] = u;
    return v;
  };
  if (g.on_obstacle) {
    start.add(g.at(-(g.surface + g.radius_a + gap0)), velocity(speed), a, 0);
  } else {
    const double ma = scene.species[a].mass_kg(), mb = scene.species[b].mass_kg();
    start.add(g.at(-(g.radius_a + 0.5 * gap0)), velocity(speed * mb / (ma + mb)), a, 0);
    start.add(g.at(g.radius_b + 0.5 * gap0), velocity(-speed * ma / (ma + mb)), b, 1);
  }
  auto solver = make_solver(g.setup, start.size(), backend);
  solver->set_particles(start);
  r.variant = solver->variant();

  // Step until the bodies have touched and parted. Contact start and end times come
  // from linear interpolation of the gap between the steps around each zero crossing.
  const double v_before = separation_speed(g, start);
  double prev_gap = gap(g, start), t_start = -1, t_end = -1;
  const long max_steps = long(20.0 * r.t_c / r.dt) + 1000;
  HostParticles p = start;
  for (long step = 1; step <= max_steps && t_end < 0; ++step) {
    solver->advance(1);
    p = solver->particles();
    const double now = gap(g, p);
    r.max_overlap = std::max(r.max_overlap, -now);
    const double t = step * r.dt;
    if (prev_gap > 0 && now <= 0 && t_start < 0) t_start = t - r.dt * now / (now - prev_gap);
    if (prev_gap <= 0 && now > 0 && t_start >= 0) t_end = t - r.dt * now / (now - prev_gap);
    prev_gap = now;
    r.steps = step;
  }
  if (t_start < 0 || t_end < 0)
    throw UserError(fmt::format("the {} collision did not complete within {} steps (dt = {:g} s)",
                                r.pair, max_steps, r.dt));
  if (passed_through(g, p))
    throw UserError(fmt::format(
        "the {} collision at {:g} m/s is past the contact law's range: the bodies passed "
        "through each other (peak overlap {:.3g} of a diameter)",
        r.pair, speed, r.max_overlap / (2 * g.radius_a)));
  r.t_contact = t_end - t_start;
  r.e_eff = separation_speed(g, p) / -v_before;
  return r;
}

}  // namespace

std::vector<std::string> collision_pair_names() {
  return kPairs;
}

CollisionResult collide_species(const SolverSetup& given, int a, int b, double speed, double dt,
                                bool force, double phase, const ImpactPlace& place,
                                Backend backend) {
  return collide(given, a, b, speed, dt, force, phase, place, backend,
                 make_obstacle(ObstacleShape::cylinder, {}, {10 * given.max_diameter()}));
}

std::string key_option(const char* key) {
  std::string option = std::string("--") + key;
  std::replace(option.begin(), option.end(), '_', '-');
  return option;
}

double collision_shape_size(const ShapeKey& key) {
  if (!key.required()) return key.fallback;
  if (key.kind == ShapeKey::Kind::length) return 10 * kDiameter;
  return 0.5 * (key.lo + key.hi);
}

std::string collision_shape_range(const ShapeKey& key) {
  if (key.kind == ShapeKey::Kind::length)
    return fmt::format("[{:g}, {:g}] m", kDiameter, kMaxCollisionObstacleSize);
  return fmt::format("{}{:g}, {:g}) degrees", key.lo_closed ? "[" : "(", key.lo, key.hi);
}

namespace {

// The obstacle an -obstacle pair strikes (its shape and sizes) from the options: each size
// given or collision_shape_size's, in its range; a size of another shape refused, and the
// shape or a size given with two particles.
Obstacle collision_obstacle(const CollisionOptions& o, bool on_obstacle) {
  const auto given = std::find_if(o.shape_sizes.begin(), o.shape_sizes.end(),
                                  [](const auto& size) { return size.second.has_value(); });
  if (!on_obstacle) {
    if (o.shape || given != o.shape_sizes.end())
      throw UserError(fmt::format(
          "{} is the obstacle's, and --pair {} is two particles: strike the obstacle with an "
          "-obstacle pair (steel-obstacle, aluminium-obstacle)",
          o.shape ? "--shape" : key_option(given->first.c_str()), o.pair));
    return make_obstacle(ObstacleShape::cylinder, {}, {});
  }
  const ObstacleShape shape = o.shape.value_or(ObstacleShape::cylinder);
  for (const auto& [name, value] : o.shape_sizes) {
    if (!value || shape_key_index(shape, name)) continue;
    std::vector<std::string> owners;
    for (const ObstacleShape owner : shapes_with_key(name))
      owners.push_back(std::string("--shape ") + choice_name(owner));
    throw UserError(fmt::format(
        "{} is a size of {}, and the shape is {}", key_option(name.c_str()),
        owners.empty() ? std::string("no shape") : fmt::format("{}", fmt::join(owners, " or ")),
        choice_name(shape)));
  }
  Obstacle body = make_obstacle(shape, {}, {});
  with_obstacle_shape(shape, [&](auto s) {
    for (std::size_t i = 0; i < std::size(s.keys); ++i) {
      const ShapeKey& k = s.keys[i];
      const auto size = o.shape_sizes.find(k.name);
      if (size == o.shape_sizes.end() || !size->second) {
        body.size[i] = collision_shape_size(k);
        continue;
      }
      const double v = *size->second;
      const bool in_range = k.kind == ShapeKey::Kind::length
                                ? v >= kDiameter && v <= kMaxCollisionObstacleSize
                                : (k.lo_closed ? v >= k.lo : v > k.lo) && v < k.hi;
      if (!in_range)
        throw UserError(fmt::format(
            "{} {:g} must be in {} ({}){}", key_option(k.name), v, collision_shape_range(k),
            k.meaning,
            k.kind == ShapeKey::Kind::length
                ? ": at least the particle diameter, as the contact law treats the obstacle "
                  "as a wall, and at most 1 m, as the collision's box grows with it"
                : ""));
      body.size[i] = v;
    }
  });
  return body;
}

}  // namespace

// The chosen law's parameters from the options (models/law_parameters.hpp): each
// in its key's range, the impact speed where the key defaults to the inflow speed, a
// required one missing refused, and a key of another law refused.
std::array<double, kMaxLawParameters> collision_law_parameters(const CollisionOptions& o) {
  for (const auto& [name, value] : o.law_parameters) {
    if (!value) continue;
    if (law_key_index(o.model, name)) continue;
    std::vector<std::string> owners;
    for (ContactModelKind law : laws_with_key(name))
      owners.push_back(std::string("--model ") + choice_name(law));
    throw UserError(fmt::format("{} is a parameter of {}, and the model is {}",
                                key_option(name.c_str()), fmt::join(owners, " or "),
                                choice_name(o.model)));
  }
  std::array<double, kMaxLawParameters> values{};
  with_law_parameters(o.model, [&](auto parameters) {
    for (std::size_t i = 0; i < parameters.keys.size(); ++i) {
      const LawKey& k = parameters.keys[i];
      const auto given = o.law_parameters.find(k.name);
      if (given == o.law_parameters.end() || !given->second) {
        if (k.fallback == LawKey::Default::required)
          throw UserError(fmt::format("--model {} needs {} ({}: {})", choice_name(o.model),
                                      key_option(k.name), k.type, k.meaning));
        values[i] = o.speed_m_per_s;  // Default::inflow_speed
        continue;
      }
      const double v = *given->second;
      if (!(v >= k.lo && v <= k.hi))
        throw UserError(fmt::format("{} {:g} must be in [{:g}, {:g}] ({}): {}", key_option(k.name),
                                    v, k.lo, k.hi, k.type, k.why));
      values[i] = v;
    }
  });
  return values;
}

CollisionResult run_head_on_collision(const CollisionOptions& o) {
  if (std::find(kPairs.begin(), kPairs.end(), o.pair) == kPairs.end())
    throw UserError(fmt::format("--pair '{}' is not one of {}", o.pair, fmt::join(kPairs, ", ")));
  if (!(o.speed_m_per_s > 0) || !std::isfinite(o.speed_m_per_s))
    throw UserError(fmt::format("--speed {} must be a positive speed in m/s", o.speed_m_per_s));
  if (o.speed_m_per_s > kMaxCollisionSpeed)
    throw UserError(fmt::format(
        "--speed {:g} m/s is past {:g} m/s: no granular contact law describes such an impact",
        o.speed_m_per_s, kMaxCollisionSpeed));
  // Below 0.01 the damped law's rebound is not resolved (docs/contact_model.md).
  if (!(o.restitution >= 0.01 && o.restitution <= 1))
    throw UserError(fmt::format("--e {} must be in [0.01, 1]", o.restitution));
  if (o.dt && !(*o.dt > 0 && std::isfinite(*o.dt)))
    throw UserError(fmt::format("--dt {} must be a positive time step in s", *o.dt));
  if (!(o.phase > 0 && o.phase <= 1))
    throw UserError(fmt::format("--phase {} must be in (0, 1]", o.phase));

  // The paper's materials, d = 1 mm, and an aluminium cylinder.
  SolverSetup paper;
  paper.species = {{"steel", steel(), kDiameter}, {"aluminium", aluminium(), kDiameter}};
  paper.contacts = ContactSettings::uniform(2, o.restitution, 0.0);
  paper.contacts.model = o.model;
  paper.contacts.options.limit_force = o.limit_force;
  paper.contacts.options.law_parameters = collision_law_parameters(o);
  paper.precision = o.precision;
  const auto dash = o.pair.find('-');
  const std::string second = o.pair.substr(dash + 1);
  const int a = paper_species(o.pair.substr(0, dash));
  const int b = second == "obstacle" ? -1 : paper_species(second);
  // The obstacle, of aluminium, and the line of impact: the flow's onto it, x between two
  // particles, unless given.
  const Obstacle body = collision_obstacle(o, b < 0);
  paper.obstacle = body;
  paper.obstacle->material = aluminium();
  ImpactPlace place = o.place;
  if (place.axis == kImpactAxisOfThePair) place.axis = b < 0 ? 1 : 0;
  double dt = o.dt.value_or(0.0);
  std::optional<PairCalibration> calibration;
  if (o.restitution_mode == RestitutionMode::discrete) {
    // This pair alone, at this impact's speed and dt (the default dt, t_c/100, first): a
    // dt chosen for a soft pair may be past the reach of a stiffer one.
    const PairProperties p = b < 0 ? paper.obstacle_pair(a) : paper.pair(a, b);
    if (dt <= 0) dt = collision_time(o.model, p, paper.contacts.options, o.speed_m_per_s) / 100.0;
    calibration = calibrate_pair(o.model, p, paper.contacts.options, dt, o.speed_m_per_s);
    ContactSettings& c = paper.contacts;
    c.restitution_mode = RestitutionMode::discrete;
    c.calibration_speed_m_per_s = o.speed_m_per_s;
    c.calibrated_beta.assign(2, std::vector<double>(2, damping_beta(o.restitution)));
    c.obstacle_calibrated_beta.assign(2, damping_beta(o.restitution));
    if (b < 0)
      c.obstacle_calibrated_beta[a] = calibration->beta;
    else
      c.calibrated_beta[a][b] = c.calibrated_beta[b][a] = calibration->beta;
  }
  CollisionResult r = collide(paper, a, b, o.speed_m_per_s, dt, o.force, o.phase, place,
                              Backend::default_space, body);
  r.pair = o.pair;
  r.calibration = calibration;
  return r;
}

nlohmann::json to_json(const PairCalibration& c, double calibration_speed) {
  nlohmann::json residuals = nlohmann::json::array();
  for (std::size_t k = 0; k < c.speed_residuals.size(); ++k)
    residuals.push_back({{"speed", kResidualSpeedFactors[k] * calibration_speed},
                         {"e_eff_minus_e", c.speed_residuals[k]}});
  return {{"e", c.restitution},
          {"beta_continuous", c.beta_continuous},
          {"beta", c.beta},
          {"dt_over_tc", c.dt_over_tc},
          {"phases", kCalibrationPhases},
          {"e_eff_continuous", c.e_eff_continuous},
          {"e_eff", c.e_eff},
          {"e_eff_phase_min", c.phase_min},
          {"e_eff_phase_max", c.phase_max},
          {"residual_over_speed", residuals}};
}

std::string to_json(const CollisionResult& r) {
  nlohmann::json j;
  j["pair"] = r.pair;
  j["speed"] = r.speed;
  j["dt"] = r.dt;
  j["t_c"] = r.t_c;
  j["dt_over_tc"] = r.dt / r.t_c;
  j["e_in"] = r.e_in;
  // e_eff is what the restitution mode gives (docs/contact_model.md, "Restitution at the
  // chosen time step"): continuous, this collision; discrete, the average over the phase
  // of the first contact step, which the damping is calibrated to return. e_eff_is says
  // which; e_eff_at_phase is this one collision (at --phase) in either mode.
  j["e_eff"] = r.calibration ? r.calibration->e_eff : r.e_eff;
  j["e_eff_is"] = r.calibration ? "phase_average" : "this_collision";
  j["e_eff_at_phase"] = r.e_eff;
  j["t_contact"] = r.t_contact;
  j["t_contact_over_tc"] = r.t_contact / r.t_c;
  j["max_overlap"] = r.max_overlap;
  j["max_overlap_over_d"] = r.max_overlap / kDiameter;
  j["model"] = r.model;
  j["limit_force"] = r.limit_force;
  j["steps"] = r.steps;
  j["dt_stable"] = r.time_step.dt_stable;
  j["variant"] = r.variant;
  if (!r.time_step.message.empty()) j["time_step_warning"] = r.time_step.message;
  j["predicted_overlap_over_d"] = r.overlap.overlap_over_d;
  if (!r.overlap.message.empty()) j["overlap_warning"] = r.overlap.message;
  j["phase"] = r.phase;
  j["at"] = r.place.centre;
  j["along"] = r.place.axis == 0 ? "x" : "y";
  // The obstacle as a scene's [obstacle] table names it (its shape and size keys, m or
  // degrees, its centre at `at`), and where and on what the particle struck it.
  if (r.obstacle) {
    nlohmann::json obstacle;
    obstacle["shape"] = choice_name(r.obstacle->shape);
    with_obstacle_shape(*r.obstacle, [&](auto s) {
      for (std::size_t i = 0; i < std::size(s.keys); ++i)
        obstacle[s.keys[i].name] = r.obstacle->size[i];
    });
    obstacle["struck"] = r.struck;
    obstacle["struck_at"] = r.struck_at;
    j["obstacle"] = obstacle;
  }
  j["beta"] = r.beta;
  j["restitution_mode"] =
      to_string(r.calibration ? RestitutionMode::discrete : RestitutionMode::continuous);
  if (r.calibration) j["calibration"] = to_json(*r.calibration, r.speed);
  return j.dump(2);
}

}  // namespace granshock
