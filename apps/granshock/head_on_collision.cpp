#include "head_on_collision.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>

#include "solver.hpp"
#include "user_error.hpp"

namespace granshock {

namespace {

const std::vector<std::string> kPairs = {"steel-steel", "steel-aluminium",
                                         "aluminium-aluminium", "steel-wall",
                                         "aluminium-wall"};

constexpr double kDiameter = 1e-3;              // the paper's d
constexpr double kCylinderDiameter = 10 * kDiameter;

int species_index(const std::string& name) { return name == "steel" ? 0 : 1; }

struct Geometry {
  SystemSetup setup;
  HostParticles particles;
  bool wall = false;
};

Geometry build(const CollisionOptions& o) {
  const auto dash = o.pair.find('-');
  const std::string a = o.pair.substr(0, dash), b = o.pair.substr(dash + 1);
  Geometry g;
  g.wall = b == "wall";
  SystemSetup& s = g.setup;
  s.species = {{"steel", steel(), kDiameter}, {"aluminium", aluminium(), kDiameter}};
  s.contacts = ContactModel::uniform(2, o.restitution, 0.0);
  s.contacts.limit_force = o.limit_force;
  s.precision = o.precision;
  s.box.lo = {-0.02, -0.02, 0};
  s.box.hi = {0.02, 0.02, kDiameter};
  if (g.wall) s.obstacle = CylinderObstacle{{0, 0, 0}, kCylinderDiameter, aluminium()};
  return g;
}

// Surface-to-surface distance along x between the colliding bodies (negative = overlap).
double gap(const Geometry& g, const HostParticles& p) {
  const double r = 0.5 * kDiameter;
  if (g.wall) return std::abs(p.position[0][0]) - r - 0.5 * kCylinderDiameter;
  return std::abs(p.position[1][0] - p.position[0][0]) - 2 * r;
}

// Relative normal velocity, positive when separating.
double separation_speed(const Geometry& g, const HostParticles& p) {
  if (g.wall) return -p.velocity[0][0];  // particle on the -x side of the cylinder
  return p.velocity[1][0] - p.velocity[0][0];
}

}  // namespace

std::vector<std::string> collision_pair_names() { return kPairs; }

CollisionResult run_head_on_collision(const CollisionOptions& o) {
  if (std::find(kPairs.begin(), kPairs.end(), o.pair) == kPairs.end())
    throw UserError(fmt::format("--pair '{}' is not one of {}", o.pair, fmt::join(kPairs, ", ")));
  if (!(o.speed_m_per_s > 0) || !std::isfinite(o.speed_m_per_s))
    throw UserError(fmt::format("--speed {} must be a positive speed in m/s", o.speed_m_per_s));
  if (!(o.restitution > 0 && o.restitution <= 1))
    throw UserError(fmt::format("--e {} must be in (0, 1]", o.restitution));
  if (o.dt < 0 || !std::isfinite(o.dt))
    throw UserError(fmt::format("--dt {} must be a positive time step in s", o.dt));

  Geometry g = build(o);
  const auto dash = o.pair.find('-');
  const int sa = species_index(o.pair.substr(0, dash));
  const PairProperties props =
      g.wall ? particle_wall(g.setup.species[sa], aluminium(), o.restitution, 0)
             : particle_pair(g.setup.species[sa],
                             g.setup.species[species_index(o.pair.substr(dash + 1))],
                             o.restitution, 0);
  CollisionResult r;
  r.pair = o.pair;
  r.speed = o.speed_m_per_s;
  r.e_in = o.restitution;
  r.limit_force = o.limit_force;
  r.t_c = hertz_collision_time(props, o.speed_m_per_s);
  r.dt = o.dt > 0 ? o.dt : r.t_c / 100.0;
  r.time_step = assess_time_step({props}, o.speed_m_per_s, r.dt, false);
  if (r.time_step.verdict == TimeStepAssessment::Verdict::refuse && !o.force)
    throw UserError(r.time_step.message);
  g.setup.dt = r.dt;

  // Start a few steps before contact, in the zero-momentum frame for two particles.
  const double radius = 0.5 * kDiameter;
  const double gap0 = 5.0 * o.speed_m_per_s * r.dt;
  if (g.wall) {
    g.particles.add({-(0.5 * kCylinderDiameter + radius + gap0), 0, 0}, {o.speed_m_per_s, 0, 0},
                    sa, 0);
  } else {
    const int sb = species_index(o.pair.substr(dash + 1));
    const double ma = g.setup.species[sa].mass_kg(), mb = g.setup.species[sb].mass_kg();
    const double half = radius + 0.5 * gap0;
    g.particles.add({-half, 0, 0}, {o.speed_m_per_s * mb / (ma + mb), 0, 0}, sa, 0);
    g.particles.add({half, 0, 0}, {-o.speed_m_per_s * ma / (ma + mb), 0, 0}, sb, 1);
  }
  auto solver = make_solver(g.setup, g.particles.size());
  solver->set_particles(g.particles);
  r.variant = solver->variant();

  // Step until the bodies have touched and parted. Contact start and end times come
  // from linear interpolation of the gap between the steps around each zero crossing.
  const double v_before = separation_speed(g, g.particles);
  double prev_gap = gap(g, g.particles), t_start = -1, t_end = -1;
  const long max_steps = long(20.0 * r.t_c / r.dt) + 1000;
  HostParticles p = g.particles;
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
                                o.pair, max_steps, r.dt));
  r.t_contact = t_end - t_start;
  r.e_eff = separation_speed(g, p) / -v_before;
  return r;
}

std::string to_json(const CollisionResult& r) {
  nlohmann::json j;
  j["pair"] = r.pair;
  j["speed"] = r.speed;
  j["dt"] = r.dt;
  j["t_c"] = r.t_c;
  j["dt_over_tc"] = r.dt / r.t_c;
  j["e_in"] = r.e_in;
  j["e_eff"] = r.e_eff;
  j["t_contact"] = r.t_contact;
  j["t_contact_over_tc"] = r.t_contact / r.t_c;
  j["max_overlap"] = r.max_overlap;
  j["max_overlap_over_d"] = r.max_overlap / kDiameter;
  j["limit_force"] = r.limit_force;
  j["steps"] = r.steps;
  j["dt_stable"] = r.time_step.dt_stable;
  j["variant"] = r.variant;
  if (!r.time_step.message.empty()) j["time_step_warning"] = r.time_step.message;
  return j.dump(2);
}

}  // namespace granshock
