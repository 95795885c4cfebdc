// An oblique impact of one steel sphere (d = 1 mm) on the fixed aluminium cylinder of
// 0.2 m, with Coulomb friction mu = 0.3, e = 0.5 and limit_force on (Fn >= 0, so the
// Coulomb bound mu |Fn| integrates to mu times the normal impulse), through the solver at
// dt = t_c/100 of the scene's contact law (test_friction_impact.cpp for hertz,
// test_hooke_contact.cpp for hooke). The cylinder's surface is flat to 1e-4 rad over the
// contact.
#pragma once

#include <algorithm>
#include <utility>
#include <vector>

#include "core/solver.hpp"
#include "kernels/models/time_step_guard.hpp"
#include "models/hooke_parameters.hpp"
#include "models/obstacle_shapes.hpp"

namespace granshock::test {

inline constexpr double kD = 1e-3, kR = 0.5e-3, kMu = 0.3, kE = 0.5, kCylinder = 0.2;

inline SolverSetup wall_setup(ContactModelKind model, double dt) {
  SolverSetup s;
  s.species = {{"steel", steel(), kD}};
  s.contacts = ContactSettings::uniform(1, kE, kMu);
  s.contacts.model = model;
  s.contacts.options.limit_force = true;
  HookeParameters::set_characteristic_velocity(s.contacts.options, 1.0);  // hooke's only key
  s.box.lo = {-0.11, -0.11, 0};
  s.box.hi = {0.11, 0.11, kD};
  s.obstacle = make_obstacle(ObstacleShape::cylinder, {0, 0, 0}, {kCylinder}, aluminium());
  s.dt = dt;
  return s;
}

struct Impact {
  double jn, jt, spin;          // impulses on the particle (normal = -x, tangential = -y), final w
  double worst_coulomb_excess;  // max over steps of (J_t - mu J_n) / J_n at the end
};

// A steel sphere approaching the cylinder's -x face with velocity (vn, vt); for hooke the
// characteristic velocity is 1 m/s (wall_setup).
inline Impact simulate_oblique_impact(ContactModelKind model, double vn, double vt) {
  SolverSetup s = wall_setup(model, 0);
  const PairProperties wall = s.obstacle_pair(0);
  s.dt = collision_time(model, wall, s.contacts.options, vn) / 100.0;
  auto solver = make_solver(s, 1);
  HostParticles p;
  p.add({-(0.5 * kCylinder + kR + 3 * vn * s.dt), 0, 0}, {vn, vt, 0}, 0, 0);
  solver->set_particles(p);
  const double m = s.species[0].mass_kg();
  Impact out{0, 0, 0, -1};
  std::vector<std::pair<double, double>> history;
  for (int step = 0; step < 2000; ++step) {
    solver->advance(1);
    const HostParticles q = solver->particles();
    const double jn = m * (vn - q.velocity[0][0]);
    const double jt = m * (vt - q.velocity[0][1]);
    history.emplace_back(jn, jt);
    out = {jn, jt, q.angular_velocity[0], -1};
    if (q.position[0][0] < p.position[0][0]) break;  // rebounded past its start
  }
  for (const auto& [jn, jt] : history)
    out.worst_coulomb_excess = std::max(out.worst_coulomb_excess, (jt - kMu * jn) / out.jn);
  return out;
}

}  // namespace granshock::test
