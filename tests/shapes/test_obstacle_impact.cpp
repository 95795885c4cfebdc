// One frictionless steel sphere (d = 1 mm, e = 0.5) hitting each face and corner of a
// wedge and a plate through the solver (docs/design.md, "Obstacles"): the contact law is
// the cylinder's, only the normal comes from the shape, so the sphere leaves with
// v' = v - (1 + e) (v . n) n for the hand-geometry normal n of what it hit. Damped Hertz
// returns e at every impact speed (docs/contact_model.md); dt = t_c / 100 leaves it
// within 0.5 %.
#include <gtest/gtest.h>

#include <cmath>

#include "core/solver.hpp"
#include "kernels/models/time_step_guard.hpp"
#include "models/obstacle_shapes.hpp"

using namespace granshock;

namespace {

constexpr double kD = 1e-3, kR = 0.5e-3, kE = 0.5;

SolverSetup setup_with(const Obstacle& o) {
  SolverSetup s;
  s.species = {{"steel", steel(), kD}};
  s.contacts = ContactSettings::uniform(1, kE, 0);
  s.box.lo = {0, 0, 0};
  s.box.hi = {0.04, 0.06, kD};
  s.obstacle = o;
  s.obstacle->material = aluminium();
  return s;
}

// The sphere starts 3 steps away from touching `at` along n, moving with v; returns its
// velocity once it has left the surface.
std::array<double, 2> rebound(const Obstacle& o, double ax, double ay, double nx, double ny,
                              double vx, double vy, Precision precision) {
  SolverSetup s = setup_with(o);
  s.precision = precision;
  const double speed = std::hypot(vx, vy);
  s.dt = collision_time(s.contacts.model, s.obstacle_pair(0), s.contacts.options, speed) / 100;
  auto solver = make_solver(s, 1);
  HostParticles p;
  const double gap = kR + 3 * speed * s.dt;
  p.add({ax + gap * nx, ay + gap * ny, 0.5 * kD}, {vx, vy, 0}, 0, 0);
  solver->set_particles(p);
  bool touched = false;
  for (int step = 0; step < 4000; ++step) {
    solver->advance(1);
    const HostParticles q = solver->particles();
    const bool touching = obstacle_distance(o, q.position[0][0], q.position[0][1]) < kR;
    touched = touched || touching;
    if (touched && !touching) return {q.velocity[0][0], q.velocity[0][1]};
  }
  ADD_FAILURE() << "the sphere did not leave the surface";
  return {0, 0};
}

// Hits the point (ax, ay) whose surface normal is (nx, ny) with velocity v, and compares
// the rebound with v - (1 + e) (v . n) n.
void expect_rebound(const Obstacle& o, double ax, double ay, double nx, double ny, double vx,
                    double vy, Precision precision = Precision::double_precision) {
  const auto v = rebound(o, ax, ay, nx, ny, vx, vy, precision);
  const double vn = vx * nx + vy * ny;
  const double ex = vx - (1 + kE) * vn * nx, ey = vy - (1 + kE) * vn * ny;
  const double tolerance = 5e-3 * std::hypot(vx, vy);
  EXPECT_NEAR(v[0], ex, tolerance) << "expected (" << ex << ", " << ey << ")";
  EXPECT_NEAR(v[1], ey, tolerance) << "expected (" << ex << ", " << ey << ")";
}

Obstacle wedge() {
  return make_obstacle(ObstacleShape::wedge, {0.02, 0.03, 0}, {20, 10e-3});
}

Obstacle plate() {
  return make_obstacle(ObstacleShape::plate, {0.02, 0.03, 0}, {8e-3, 2e-3});
}

}  // namespace

// Falling with the flow (+y) onto the wedge's left face, whose normal is
// (-cos theta, -sin theta): the sphere is turned aside, not sent back upstream.
TEST(ObstacleImpact, WedgeFaceTurnsTheFlowAside) {
  const Obstacle o = wedge();
  const double t = 20 * M_PI / 180, along = 4e-3 / std::cos(t);
  const double ax = o.centre[0] - along * std::sin(t),
               ay = o.centre[1] - 5e-3 + along * std::cos(t);
  expect_rebound(o, ax, ay, -std::cos(t), -std::sin(t), 0, 1);
}

// Head-on into the tip along a line 40 deg off the axis: the normal is that line.
TEST(ObstacleImpact, WedgeTipSendsBackAlongTheLineOfImpact) {
  const Obstacle o = wedge();
  const double a = 40 * M_PI / 180, nx = std::sin(a), ny = -std::cos(a);
  expect_rebound(o, o.centre[0], o.centre[1] - 5e-3, nx, ny, -nx, -ny);
}

// Oblique onto the plate's upstream face: the normal part reversed and scaled by e, the
// tangential part kept (frictionless).
TEST(ObstacleImpact, PlateFaceReversesTheNormalPartOnly) {
  const Obstacle o = plate();
  expect_rebound(o, o.centre[0] + 1e-3, o.centre[1] - 1e-3, 0, -1, 0.5, 1);
}

// The single-precision variant forms the offset from the centre in double and the rest
// in float (kernels/device/position.hpp): the same rebound off the tip.
TEST(ObstacleImpact, WedgeTipInSinglePrecision) {
  const Obstacle o = wedge();
  const double a = 40 * M_PI / 180, nx = std::sin(a), ny = -std::cos(a);
  expect_rebound(o, o.centre[0], o.centre[1] - 5e-3, nx, ny, -nx, -ny, Precision::single_precision);
}

// Head-on into the plate's corner along its diagonal.
TEST(ObstacleImpact, PlateCornerSendsBackAlongTheDiagonal) {
  const Obstacle o = plate();
  const double s = std::sqrt(0.5);
  expect_rebound(o, o.centre[0] - 4e-3, o.centre[1] - 1e-3, -s, -s, s, s);
}
