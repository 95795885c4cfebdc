// docs/contact_model.md: an oblique impact of a steel sphere on the fixed
// aluminium cylinder with Coulomb friction mu = 0.3 (limit_force on, so Fn >= 0 and the
// Coulomb bound mu |Fn| integrates to mu times the normal impulse).
//  - Sliding regime (v_t/v_n = 4, above the gross-slip threshold
//    mu (1 + e_eff)(1 + m r^2 / I) = 0.3 * 1.55 * 3.5 = 1.63 for a solid sphere):
//    tangential impulse = mu x normal impulse (Coulomb's law), within 0.5 %.
//  - Sticking regime (v_t/v_n = 0.2): the tangential impulse stays below mu x normal
//    impulse and matches an independent RK4 integration of the same tangential law
//    (spring with history, damping, Coulomb cap) written here, within 2 %.
//  - Both: the cumulative tangential impulse never exceeds mu x the cumulative normal
//    impulse, and the spin-up obeys I dw = r J_t.
// The set-up and the solver run are in oblique_impact.hpp (shared with the hooke test).
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "core/solver.hpp"
#include "physics/oblique_impact.hpp"

using namespace granshock;
using namespace granshock::test;

namespace {

// Independent reference: RK4 on the overlap x and the contact-point slip velocity u
// of a sphere on a flat wall,
//   m x'' = -Fn,  Fn = max(0, 4/3 Y* sqrt(R*) x^(3/2) + gn x'),
//   u' = -(1/m + r^2/I) Ft,  xi' = u,  spring -kt xi held at |kt xi| <= mu Fn,
//   Ft = -kt xi - gt u capped at mu Fn, with kt = 8 G* sqrt(R* x) and gn, gt from beta
//   (docs/design.md, "Contact models"; the spring cap as in LIGGGHTS' tangential history model).
double reference_tangential_impulse(double vn, double vt) {
  const double m = 7850.0 * M_PI * kD * kD * kD / 6.0;
  const double inv_y = (1 - 0.303 * 0.303) / 210e9 + (1 - 0.33 * 0.33) / 69e9;
  const double inv_g = 2 * (2 - 0.303) * (1 + 0.303) / 210e9 + 2 * (2 - 0.33) * (1 + 0.33) / 69e9;
  const double Y = 1 / inv_y, G = 1 / inv_g, R = kR;
  const double beta = std::log(kE) / std::sqrt(std::log(kE) * std::log(kE) + M_PI * M_PI);
  const double damp = -2 * std::sqrt(5.0 / 6.0) * beta;
  const double inv_mt = 1 / m + kR * kR / (0.4 * m * kR * kR);  // 1/m + r^2/I = 3.5/m
  struct State {
    double x, xd, u, xi;
  };
  auto forces = [&](const State& s, double& fn, double& ft) {
    fn = ft = 0;
    if (s.x <= 0) return;
    const double sq = std::sqrt(R * s.x);
    fn = std::max(0.0, 4.0 / 3.0 * Y * sq * s.x + damp * std::sqrt(2 * Y * sq * m) * s.xd);
    const double kt = 8 * G * sq, gt = damp * std::sqrt(8 * G * sq * m);
    double spring = -kt * s.xi;
    if (std::abs(spring) > kMu * fn) spring = std::copysign(kMu * fn, spring);
    ft = spring - gt * s.u;
    if (std::abs(ft) > kMu * fn) ft = std::copysign(kMu * fn, ft);
  };
  auto deriv = [&](const State& s) {
    double fn, ft;
    forces(s, fn, ft);
    return State{s.xd, -fn / m, inv_mt * ft, s.u};
  };
  const double tc = 2.87 * std::pow(m * m / (R * Y * Y * vn), 0.2);
  const double h = tc / 20000;
  State s{0, vn, vt, 0};
  double jt = 0;
  for (int k = 0; k < 200000 && !(s.x <= 0 && k > 0); ++k) {
    const State k1 = deriv(s);
    auto add = [](const State& a, const State& b, double f) {
      return State{a.x + f * b.x, a.xd + f * b.xd, a.u + f * b.u, a.xi + f * b.xi};
    };
    const State k2 = deriv(add(s, k1, h / 2)), k3 = deriv(add(s, k2, h / 2)),
                k4 = deriv(add(s, k3, h));
    State next{s.x + h / 6 * (k1.x + 2 * k2.x + 2 * k3.x + k4.x),
               s.xd + h / 6 * (k1.xd + 2 * k2.xd + 2 * k3.xd + k4.xd),
               s.u + h / 6 * (k1.u + 2 * k2.u + 2 * k3.u + k4.u),
               s.xi + h / 6 * (k1.xi + 2 * k2.xi + 2 * k3.xi + k4.xi)};
    // Hold the spring at the Coulomb limit, as the law prescribes.
    double fn, ft;
    forces(next, fn, ft);
    if (next.x > 0) {
      const double kt = 8 * G * std::sqrt(R * next.x);
      if (kt * std::abs(next.xi) > kMu * fn) next.xi = std::copysign(kMu * fn / kt, next.xi);
    }
    // Tangential impulse from the change of the sphere's centre velocity: m dv_t = Ft dt,
    // and u changes by inv_mt Ft dt, so dJ = du / inv_mt.
    jt += -(next.u - s.u) / inv_mt;
    s = next;
  }
  return jt;
}

}  // namespace

TEST(FrictionImpact, SlidingTangentialImpulseIsMuTimesNormal) {
  const Impact r = simulate_oblique_impact(ContactModelKind::hertz, 1.0, 4.0);
  ASSERT_GT(r.jn, 0);
  EXPECT_NEAR(r.jt / r.jn, kMu, 0.005 * kMu);
  EXPECT_LT(r.worst_coulomb_excess, 1e-9);
  // I dw = r J_t: the torque of the tangential force at the contact point -r n.
  const Species sp{"steel", steel(), kD};
  EXPECT_NEAR(sp.moment_of_inertia() * r.spin, -kR * r.jt, 1e-3 * kR * r.jt);
}

TEST(FrictionImpact, StickingStaysBelowTheCoulombLimit) {
  const Impact r = simulate_oblique_impact(ContactModelKind::hertz, 1.0, 0.2);
  const double ref = reference_tangential_impulse(1.0, 0.2);
  ASSERT_GT(r.jn, 0);
  EXPECT_LT(r.jt / r.jn, 0.9 * kMu) << "a sticking impact must not reach gross sliding";
  EXPECT_LT(r.worst_coulomb_excess, 1e-9);
  EXPECT_NEAR(r.jt, ref, 0.02 * std::abs(ref)) << "reference tangential impulse " << ref;
  const Species sp{"steel", steel(), kD};
  EXPECT_NEAR(sp.moment_of_inertia() * r.spin, -kR * r.jt, 1e-3 * std::abs(kR * r.jt));
}

namespace {

// 3-D (docs/contact_model.md, "Tangential force"): the steel sphere strikes the flat -y
// face of a plate (0.2 m wide, 0.02 m thick, extruded along z), with the slip along the
// face's tangent t = (t_x, 0, t_z). The face is the same flat wall in every tangential
// direction and its normal n = (0, -1, 0) does not turn (unlike the cylinder's), so the
// impulses must be the 2-D impact's (slip along x) for any t, up to rounding; the spin is
// then a vector, the contact point's velocity vrel - (r w) x n and the torque -r n x Ft in
// full.
struct PlateImpact {
  double jn;                   // normal impulse on the particle: m (vn - v_y)
  std::array<double, 3> jt;    // tangential impulse on the particle, m (v - v0), y excluded
  std::array<double, 3> spin;  // final angular velocity (2-D: z only)
};

PlateImpact simulate_plate_impact(int dim, double vn, double vt, const std::array<double, 2>& t) {
  SolverSetup s = wall_setup(ContactModelKind::hertz, 0);
  s.dim = dim;
  s.obstacle = make_obstacle(ObstacleShape::plate, {0, 0, 0}, {0.2, 0.02}, aluminium());
  if (dim == 3) {
    s.box.lo[2] = -2 * kD;  // open along z; the particle moves by 1e-5 d along z
    s.box.hi[2] = 2 * kD;
  }
  s.dt = collision_time(ContactModelKind::hertz, s.obstacle_pair(0), s.contacts.options, vn) / 100;
  auto solver = make_solver(s, 1);
  HostParticles p;
  const std::array<double, 3> v0{vt * t[0], vn, vt * t[1]};
  const double y0 = -(0.01 + kR + 3 * vn * s.dt);
  p.add({0, y0, 0}, v0, 0, 0);
  solver->set_particles(p);
  const double m = s.species[0].mass_kg();
  PlateImpact out{};
  for (int step = 0; step < 2000; ++step) {
    solver->advance(1);
    const HostParticles q = solver->particles();
    out.jn = m * (vn - q.velocity[0][1]);
    for (int d : {0, 2}) out.jt[d] = m * (q.velocity[0][d] - v0[d]);
    const std::vector<double>& w = q.angular_velocity;
    out.spin = dim == 2 ? std::array<double, 3>{0, 0, w.at(0)}
                        : std::array<double, 3>{w.at(0), w.at(1), w.at(2)};
    if (q.position[0][1] < y0) break;  // rebounded past its start
  }
  return out;
}

// Returns the 3-D impact with the slip at 60 degrees to the plane of motion.
PlateImpact expect_3d_impact_as_in_the_plane(double vn, double vt) {
  const PlateImpact plane = simulate_plate_impact(2, vn, vt, {1, 0});
  const double inertia = Species{"steel", steel(), kD}.moment_of_inertia();
  EXPECT_GT(plane.jn, 0);
  EXPECT_LT(plane.jt[0], 0);  // against the slip
  PlateImpact slanted{};
  // In the plane, along z, and at 60 degrees from the plane of motion.
  for (const std::array<double, 2> t :
       {std::array<double, 2>{1, 0}, {0, 1}, {0.5, std::sqrt(0.75)}}) {
    SCOPED_TRACE("tangent (" + std::to_string(t[0]) + ", 0, " + std::to_string(t[1]) + ")");
    const PlateImpact r = simulate_plate_impact(3, vn, vt, t);
    // The same arithmetic as the 2-D solver's up to rounding: 1e-9 relative.
    const double jt = std::abs(plane.jt[0]);
    EXPECT_NEAR(r.jn, plane.jn, 1e-9 * plane.jn);
    const double along = r.jt[0] * t[0] + r.jt[2] * t[1];
    const double across = r.jt[2] * t[0] - r.jt[0] * t[1];
    EXPECT_NEAR(along, plane.jt[0], 1e-9 * jt) << "2-D impulse " << plane.jt[0];
    EXPECT_NEAR(across, 0, 1e-9 * jt) << "the impulse left the slip's direction";
    // I w = (-r n) x J_t = (0, r, 0) x (J_x, 0, J_z) = (r J_z, 0, -r J_x).
    EXPECT_NEAR(inertia * r.spin[0], kR * r.jt[2], 1e-9 * kR * jt);
    EXPECT_NEAR(inertia * r.spin[1], 0, 1e-9 * kR * jt);
    EXPECT_NEAR(inertia * r.spin[2], -kR * r.jt[0], 1e-9 * kR * jt);
    slanted = r;
  }
  EXPECT_NEAR(inertia * plane.spin[2], -kR * plane.jt[0], 1e-9 * kR * std::abs(plane.jt[0]));
  return slanted;
}

}  // namespace

TEST(FrictionImpact, ThreeDimensionsSlidingAlongAnyTangentIsThePlaneImpact) {
  const PlateImpact r = expect_3d_impact_as_in_the_plane(1.0, 4.0);
  EXPECT_NEAR(std::hypot(r.jt[0], r.jt[2]) / r.jn, kMu, 0.005 * kMu);  // Coulomb's law
}

TEST(FrictionImpact, ThreeDimensionsStickingAlongAnyTangentIsThePlaneImpact) {
  const PlateImpact r = expect_3d_impact_as_in_the_plane(1.0, 0.2);
  EXPECT_LT(std::hypot(r.jt[0], r.jt[2]) / r.jn, 0.9 * kMu) << "it must not slide";
}

namespace {

// A 3-D slab's walls (kernels/models/z_walls.hpp): the steel sphere, spinning, strikes the
// lower or upper wall of a slab 4 d thick with slip (vt, 0) along the wall. The walls are
// frictionless and of the obstacle's material and restitution, so the normal impulse must
// be the one the plate's flat face gives at the same normal speed (same law, same
// coefficients, the normal along z instead of y), up to rounding, and the velocity along
// the wall and the spin must not change at all.
struct WallImpact {
  double jn;                // normal impulse on the particle, m (|vz'| + vn)
  double vx, vy;            // velocity along the wall after the rebound
  std::array<double, 3> w;  // spin after the rebound
};

WallImpact simulate_wall_impact(bool upper, double vn, double vt) {
  SolverSetup s = wall_setup(ContactModelKind::hertz, 0);
  s.dim = 3;
  s.obstacle = make_obstacle(ObstacleShape::plate, {0, 0.1, 0}, {0.02, 0.002}, aluminium());
  s.box.lo[2] = 0;
  s.box.hi[2] = 4 * kD;
  s.z_walls = true;
  s.dt = collision_time(ContactModelKind::hertz, s.obstacle_pair(0), s.contacts.options, vn) / 100;
  auto solver = make_solver(s, 1);
  HostParticles p;
  const double gap = kR + 3 * vn * s.dt;
  p.add({0, 0, upper ? 4 * kD - gap : gap}, {vt, 0, upper ? vn : -vn}, 0, 0);
  p.angular_velocity = {100.0, -50.0, 30.0};
  solver->set_particles(p);
  const double m = s.species[0].mass_kg();
  WallImpact out{};
  for (int step = 0; step < 2000; ++step) {
    solver->advance(1);
    const HostParticles q = solver->particles();
    const double vz = q.velocity[0][2];
    out = {m * (vn + (upper ? -vz : vz)),
           q.velocity[0][0],
           q.velocity[0][1],
           {q.angular_velocity.at(0), q.angular_velocity.at(1), q.angular_velocity.at(2)}};
    if (upper ? q.position[0][2] < p.position[0][2] : q.position[0][2] > p.position[0][2]) break;
  }
  return out;
}

}  // namespace

TEST(SlabWalls, FrictionlessWallsReboundAsTheObstacleFaceWithoutTangentialImpulse) {
  const double vn = 1.0, vt = 2.0;
  const PlateImpact face = simulate_plate_impact(2, vn, 0.0, {1, 0});
  const double m = Species{"steel", steel(), kD}.mass_kg();
  EXPECT_GT(face.jn, 1.2 * m * vn);  // a rebound: e_eff above 0.2
  for (const bool upper : {false, true}) {
    SCOPED_TRACE(upper ? "upper wall" : "lower wall");
    const WallImpact r = simulate_wall_impact(upper, vn, vt);
    EXPECT_NEAR(r.jn, face.jn, 1e-9 * face.jn);
    EXPECT_EQ(r.vx, vt);
    EXPECT_EQ(r.vy, 0.0);
    EXPECT_EQ(r.w[0], 100.0);
    EXPECT_EQ(r.w[1], -50.0);
    EXPECT_EQ(r.w[2], 30.0);
  }
}

namespace {

// The sphere obstacle (models/sphere.hpp) in 3-D: a steel sphere struck head-on along a
// line at 45 degrees to the x-y plane through its centre rebounds along that line with the
// normal impulse of the plate's flat face at the same normal speed (the same law, R* = r_i
// for every obstacle), and a particle that passes above the sphere's top, where a cylinder
// would stand, keeps its velocity exactly.
struct SphereImpact {
  double jn;                // impulse along the line, on the particle
  std::array<double, 3> v;  // velocity at the end
};

SphereImpact simulate_sphere_impact(const std::array<double, 3>& start,
                                    const std::array<double, 3>& v0, double dt, int steps) {
  SolverSetup s = wall_setup(ContactModelKind::hertz, 0);
  s.dim = 3;
  s.box.lo[2] = -0.11;
  s.box.hi[2] = 0.11;
  s.obstacle = make_obstacle(ObstacleShape::sphere, {0, 0, 0}, {kCylinder}, aluminium());
  s.dt = dt;
  auto solver = make_solver(s, 1);
  HostParticles p;
  p.add(start, v0, 0, 0);
  solver->set_particles(p);
  solver->advance(steps);
  const HostParticles q = solver->particles();
  const double m = s.species[0].mass_kg();
  const double speed = std::sqrt(v0[0] * v0[0] + v0[1] * v0[1] + v0[2] * v0[2]);
  double along = 0;  // final velocity along the incoming direction
  for (int d = 0; d < 3; ++d) along += q.velocity[0][d] * v0[d] / speed;
  return {m * (speed - along), q.velocity[0]};
}

}  // namespace

TEST(SphereObstacle, HeadOnAlongAnyLineReboundsAsTheFlatFaceAndAParticleAboveItPasses) {
  const double vn = 1.0;
  const PlateImpact face = simulate_plate_impact(2, vn, 0.0, {1, 0});
  SolverSetup probe = wall_setup(ContactModelKind::hertz, 0);
  const double dt =
      collision_time(ContactModelKind::hertz, probe.obstacle_pair(0), probe.contacts.options, vn) /
      100;
  // Along (0, 1, 1)/sqrt(2) towards the centre, from 3 steps' travel off the surface.
  const double c = std::sqrt(0.5), gap = 0.5 * kCylinder + kR + 3 * vn * dt;
  const SphereImpact hit =
      simulate_sphere_impact({0, -gap * c, -gap * c}, {0, vn * c, vn * c}, dt, 800);
  EXPECT_NEAR(hit.jn, face.jn, 1e-9 * face.jn);
  EXPECT_NEAR(hit.v[0], 0.0, 1e-12);
  EXPECT_NEAR(hit.v[1], hit.v[2], 1e-9 * vn) << "the rebound must stay on the line";
  EXPECT_LT(hit.v[1], 0.0);
  // Above the top (z = R + r + 0.1 d), moving along y over the apex, where a cylinder's
  // cross-section lies: no contact.
  const double over = 0.5 * kCylinder + kR + 0.1 * kD;
  const SphereImpact miss =
      simulate_sphere_impact({0, -2 * kD, over}, {0, vn, 0}, dt, int(4 * kD / (vn * dt)));
  EXPECT_EQ(miss.v[0], 0.0);
  EXPECT_EQ(miss.v[1], vn);
  EXPECT_EQ(miss.v[2], 0.0);
}
