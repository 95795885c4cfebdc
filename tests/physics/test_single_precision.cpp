// Single precision at the paper's size (docs/design.md, "Particles"): positions are
// stored in double in every variant and a pair's separation is formed in double before it
// is rounded to float, so a single-precision contact is as accurate at the far edge of
// the paper's 500 d box (0.5 m) as at the origin.
//  - Head-on impacts through the solver's kernels (`granshock collide --at`) near
//    x = 500 d, y = 500 d and both return the e_eff and contact time of the same impact at
//    the origin.
//  - An independent small integration written here (float arithmetic, positions of a
//    chosen type) shows that the old all-float storage misses that tolerance by far,
//    so the comparison above can fail.
//  - A cooling gas near (500 d, 500 d) in single precision loses its kinetic energy as
//    the same gas at the origin in double precision does.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>
#include <tuple>
#include <vector>

#include "cases/collision/head_on_collision.hpp"
#include "cases/gas/homogeneous_gas.hpp"
#include "core/solver.hpp"
#include "physics/contact_reference.hpp"

using namespace granshock;
using namespace granshock::test;

namespace {

constexpr double kFar = 0.5;  // m: 500 d, the far edge of the paper's box

// The tolerance of a far impact against the same impact at the origin, both in single
// precision. A separation (~1 mm) rounded to float is off by at most eps_f/2 x 1 mm =
// 6e-11 m, 7.5e-5 of the peak overlap of a 1 m/s steel impact (8e-7 m); the rounding is
// the same wherever the pair sits, up to the double rounding of the positions (1e-16 m).
// So e_eff far and at the origin may differ by about that relative error of the force,
// below 1e-4, and the contact time by below 1e-4 of t_c.
constexpr double kTolerance = 1e-4;

CollisionResult single_impact(const std::string& pair, const ImpactPlace& place) {
  CollisionOptions o;
  o.pair = pair;
  o.speed_m_per_s = 1.0;  // dt defaults to t_c / 100
  o.precision = Precision::single_precision;
  o.place = place;
  return run_head_on_collision(o);
}

using FarCase = std::tuple<std::string, double, double, int>;  // pair, x, y, axis

class SinglePrecisionFarImpact : public ::testing::TestWithParam<FarCase> {};

TEST_P(SinglePrecisionFarImpact, MatchesTheSameImpactAtTheOrigin) {
  const auto& [pair, x, y, axis] = GetParam();
  const CollisionResult origin = single_impact(pair, ImpactPlace{{0, 0}, axis});
  const CollisionResult far = single_impact(pair, ImpactPlace{{x, y}, axis});
  ASSERT_NE(far.variant.find("single"), std::string::npos) << far.variant;
  std::printf(
      "[ measured ] %-18s at (%.1f, %.1f) along %c: e_eff %.7f (origin %.7f, %+.1e), "
      "t_contact/t_c %.7f (origin %.7f, %+.1e)\n",
      pair.c_str(), x, y, axis == 0 ? 'x' : 'y', far.e_eff, origin.e_eff, far.e_eff - origin.e_eff,
      far.t_contact / far.t_c, origin.t_contact / origin.t_c,
      (far.t_contact - origin.t_contact) / origin.t_c);
  EXPECT_NEAR(far.e_eff, origin.e_eff, kTolerance);
  EXPECT_NEAR(far.t_contact / far.t_c, origin.t_contact / origin.t_c, kTolerance);
  EXPECT_NEAR(far.max_overlap, origin.max_overlap, kTolerance * origin.max_overlap);
  // And both are the contact law's (the double-precision test's 0.5 %, test_head_on_collision).
  EXPECT_NEAR(far.e_eff, 0.5, 0.005 * 0.5);
}

std::string far_case_name(const ::testing::TestParamInfo<FarCase>& info) {
  std::string name = std::get<0>(info.param);
  for (char& c : name)
    if (c == '-') c = '_';
  const auto d = [](double v) { return std::to_string(int(std::lround(v * 1000))); };
  return name + "_at_" + d(std::get<1>(info.param)) + "d_" + d(std::get<2>(info.param)) +
         "d_along_" + (std::get<3>(info.param) == 0 ? "x" : "y");
}

INSTANTIATE_TEST_SUITE_P(PaperBoxEdges, SinglePrecisionFarImpact,
                         ::testing::Combine(::testing::Values("steel-steel", "steel-aluminium",
                                                              "aluminium-obstacle"),
                                            ::testing::Values(kFar), ::testing::Values(0.0, kFar),
                                            ::testing::Values(0, 1)),
                         far_case_name);

TEST(SinglePrecisionImpact, NearTheYEdgeAlongBothAxes) {
  for (const int axis : {0, 1}) {
    const CollisionResult origin = single_impact("steel-steel", ImpactPlace{{0, 0}, axis});
    const CollisionResult far = single_impact("steel-steel", ImpactPlace{{0, kFar}, axis});
    EXPECT_NEAR(far.e_eff, origin.e_eff, kTolerance) << "axis " << axis;
    EXPECT_NEAR(far.t_contact / far.t_c, origin.t_contact / origin.t_c, kTolerance)
        << "axis " << axis;
  }
}

// An independent head-on impact of two steel spheres along x around `centre`, written
// here: velocity Verlet with the Hertz law of docs/contact_model.md, every quantity in
// float except the positions, stored as P and differenced in P before the separation is
// rounded to float (P = float is the old all-float storage, P = double the solver's).
// Returns e_eff (NaN if the impact does not complete: positions that cannot resolve a
// step's displacement freeze) and the contact time over the step count's t_c / 100.
template <class P>
std::pair<double, double> impact_with_positions(double centre, double dt_over_tc) {
  const PairReference ref = reference_for("steel-steel");
  const float m = float(2 * ref.mass_star);  // each sphere
  const float r = 0.5e-3f, ys = float(ref.youngs_star), rs = float(ref.radius_star);
  const float ms = float(ref.mass_star), beta = float(reference_beta(0.5));
  const double v0 = 1.0;  // relative approach speed
  const double tc = 2.87 * std::pow(ref.mass_star * ref.mass_star /
                                        (ref.radius_star * ref.youngs_star * ref.youngs_star * v0),
                                    0.2);
  const float dt = float(dt_over_tc * tc), half = 0.5f * dt;
  const double gap0 = 5.5 * v0 * double(dt);
  P xa = P(centre - double(r) - 0.5 * gap0), xb = P(centre + double(r) + 0.5 * gap0);
  float va = float(0.5 * v0), vb = float(-0.5 * v0);
  const auto force_on_b = [&]() {
    const float dx = float(xb - xa);  // formed in P, then rounded
    const float dn = 2 * r - std::fabs(dx);
    if (dn <= 0) return 0.0f;
    const float vn = vb - va;  // along +x, negative when approaching
    const float kn = 4.0f / 3.0f * ys * std::sqrt(rs * dn);
    const float gn =
        -2.0f * std::sqrt(5.0f / 6.0f) * beta * std::sqrt(2.0f * ys * std::sqrt(rs * dn) * ms);
    return kn * dn - gn * vn;
  };
  const auto gap = [&]() { return double(xb) - double(xa) - 2 * double(r); };
  float f = force_on_b();
  double previous = gap(), t_start = -1, t_end = -1;
  const long max_steps = long(20 / dt_over_tc) + 1000;
  for (long step = 1; step <= max_steps && t_end < 0; ++step) {
    va += half * (-f / m);
    vb += half * (f / m);
    xa += dt * va;
    xb += dt * vb;
    f = force_on_b();
    va += half * (-f / m);
    vb += half * (f / m);
    const double now = gap(), t = double(step) * double(dt);
    if (previous > 0 && now <= 0 && t_start < 0) t_start = t - double(dt) * now / (now - previous);
    if (previous <= 0 && now > 0 && t_start >= 0) t_end = t - double(dt) * now / (now - previous);
    previous = now;
  }
  if (t_end < 0) return {std::numeric_limits<double>::quiet_NaN(), 0.0};
  return {double(vb - va) / v0, (t_end - t_start) / tc};
}

// The comparison above can fail: with the old all-float storage, the same impact at
// 500 d returns an e_eff far outside kTolerance of the origin's, while float arithmetic
// on double positions stays within it.
TEST(SinglePrecisionImpact, AllFloatStorageWouldFailTheTolerance) {
  std::printf("[ measured ] independent float impact, steel-steel 1 m/s, e = 0.5:\n");
  for (const double dt_over_tc : {0.01, 0.166}) {  // collide's default, the paper's 5e-7 s
    const auto origin_d = impact_with_positions<double>(0, dt_over_tc);
    const auto origin_f = impact_with_positions<float>(0, dt_over_tc);
    for (const double centre : {0.0, 0.005, 0.05, kFar}) {
      const auto d = impact_with_positions<double>(centre, dt_over_tc);
      const auto f = impact_with_positions<float>(centre, dt_over_tc);
      std::printf(
          "[ measured ]   dt/t_c %.3f, at %5.0f d: e_eff double positions %.7f (%+.1e), "
          "float positions %.7f (%+.1e)\n",
          dt_over_tc, centre / 1e-3, d.first, d.first - origin_d.first, f.first,
          f.first - origin_f.first);
      EXPECT_NEAR(d.first, origin_d.first, kTolerance) << "double positions at " << centre;
      EXPECT_NEAR(d.second, origin_d.second, kTolerance) << "double positions at " << centre;
    }
    const double far_error =
        std::fabs(impact_with_positions<float>(kFar, dt_over_tc).first - origin_f.first);
    EXPECT_FALSE(far_error < 10 * kTolerance)
        << "all-float storage at 500 d would pass: error " << far_error;
  }
}

// A cooling gas of the paper's mixture (e = 0.5, phi = 0.3, 2500 particles, periodic box
// of 81 d), in double precision at the origin and in single precision near (500 d, 500 d):
// the kinetic energy left after about two collisions per particle agrees. The two runs
// start from the same state, but their trajectories separate within a few collisions
// (round-off grows exponentially in a gas), so they are two realisations of the same
// cooling: their energies differ by the statistical spread of the energy of N particles,
// whose relative standard deviation in 2-D is 1/sqrt(N) (2 N quadratic terms). The
// tolerance is three of it.
TEST(SinglePrecisionGas, CoolsFarFromTheOriginAsDoubleDoesAtTheOrigin) {
  SolverSetup setup = paper_mixture(0.5);
  setup.dt = 5e-8;
  GasSpec spec;
  spec.particles = 2500;
  spec.area_fraction = 0.3;
  spec.sigma_m_per_s = 1.0;
  size_periodic_box(setup, spec);
  const HostParticles gas = make_homogeneous_gas(setup, spec);

  SolverSetup far_setup = setup;
  far_setup.precision = Precision::single_precision;
  const double shift = kFar - 0.5 * setup.box.length(0);  // box centred on (500 d, 500 d)
  HostParticles far_gas = gas;
  for (int d = 0; d < 2; ++d) {
    far_setup.box.lo[std::size_t(d)] += shift;
    far_setup.box.hi[std::size_t(d)] += shift;
    for (auto& x : far_gas.position) x[std::size_t(d)] += shift;
  }
  auto reference = make_solver(setup, gas.size());
  auto single = make_solver(far_setup, far_gas.size());
  ASSERT_NE(single->variant().find("single"), std::string::npos);
  reference->set_particles(gas);
  single->set_particles(far_gas);
  const double e0_reference = reference->diagnostics().kinetic_energy;
  const double e0_single = single->diagnostics().kinetic_energy;
  const double tolerance = 3 / std::sqrt(double(gas.size()));
  for (int sample = 1; sample <= 4; ++sample) {
    reference->advance(10000);
    single->advance(10000);
    const Diagnostics a = reference->diagnostics(), b = single->diagnostics();
    const double left_reference = a.kinetic_energy / e0_reference;
    const double left_single = b.kinetic_energy / e0_single;
    std::printf(
        "[ measured ] t = %.1f ms: kinetic energy left, double at origin %.4f, single at "
        "500 d %.4f (%+.2f %%); contacts %ld vs %ld\n",
        1e3 * reference->time(), left_reference, left_single,
        100 * (left_single / left_reference - 1), a.contacts, b.contacts);
    EXPECT_NEAR(left_single / left_reference, 1.0, tolerance) << "sample " << sample;
    EXPECT_EQ(b.non_finite, 0);
    EXPECT_EQ(single->size(), gas.size());
  }
  // The gas cooled (the comparison is about dissipation, not a frozen state).
  EXPECT_LT(reference->diagnostics().kinetic_energy / e0_reference, 0.8);
}

}  // namespace
