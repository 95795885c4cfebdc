// Homogeneous cooling of a granular gas (Haff's law) against kinetic theory.
//
// Theory (Haff, J. Fluid Mech. 134, 401 (1983); Brilliantov & Poeschel, Kinetic Theory
// of Granular Gases, Oxford 2004), for inelastic, frictionless hard disks of diameter
// sigma and mass m at number density n, area fraction phi, restitution e, in 2-D with
// the granular temperature T = m <c^2> / 2 (Dim = 2, c the velocity relative to the mean):
//   - Enskog collision frequency of a particle: nu = 2 n sigma g(phi) sqrt(pi T / m)
//     (the relative speed |c_12| of a Maxwellian pair has mean sqrt(pi T / m); the
//     collision cross-section of two disks in 2-D is 2 sigma);
//   - a collision with normal relative speed w loses (1 - e^2) (m/4) w^2; over the
//     flux-weighted distribution of w, <w^2>_coll = 4 T / m, so (1 - e^2) T is lost per
//     collision on average;
//   - N nu / 2 collisions per unit time take (1 - e^2) T each from the kinetic energy N T:
//       dT/dt = -(1 - e^2) n sigma g(phi) sqrt(pi / m) T^(3/2),
//     whose solution is Haff's law T(t) = T0 / (1 + t / tau)^2 with
//       1 / tau = (1 - e^2) n sigma g(phi) sqrt(pi T0 / m) / 2,
//     g(phi) = (16 - 7 phi) / (16 (1 - phi)^2) (Henderson 1975, as in DESIGN.md 2.3).
//   Equivalently T^(-1/2) = T0^(-1/2) + s t with the T0-independent slope
//       s = (1 - e^2) n sigma g(phi) sqrt(pi / m) / 2,
//   so the test fits a straight line to T^(-1/2)(t) and reports tau = 1 / (s sqrt(T0)).
// Neglected: the non-Gaussian velocity distribution of the cooling state (Sonine
// coefficient a2 = -0.027 in 2-D at e = 0.9, changing the cooling rate by 3 a2 / 16 =
// -0.5 %, Brilliantov & Poeschel 2004) and velocity correlations (small at phi = 0.05).
//
// Scene: 1024 steel spheres (d = 1 mm, Young's modulus scaled down 1000x: contacts last
// 1000^(2/5) = 16x longer, so the run is 16x cheaper) at area fraction 0.05, e = 0.9,
// no friction, periodic square box of 127 d (about 25 mean free paths). They start on
// the jittered lattice of make_homogeneous_gas; an elastic (e = 1) warm-up of 5 mean
// collision times randomises the positions first, so that pairs near contact occur with
// their equilibrium frequency (the contact value g(phi)) when the cooling starts; on the
// bare lattice no pair is near contact and the first collision time cools too slowly.
// The cooling run lasts 2 tau (T falls to T0 / 9, ~23 collisions per particle, 1.2e4 in
// all). Clustering (the shear and density instabilities of the cooling state) needs a
// box larger than a few tens of mean free paths and many more collisions per particle;
// the test checks that the gas stayed homogeneous by comparing the coarse-grained flow
// energy and the density fluctuations on an 8 x 8 grid with their values in an
// equilibrium gas.
//
// Soft contacts: with finite collision duration t_c a particle spends a fraction ~nu t_c
// (1-2 % here) of its time in contact, which slows the cooling slightly. In runs with
// other seeds the fitted tau exceeded the theory by 3-5 % at E / 10^3 and 4 % at E / 10^4,
// by 2 % at E / 10^2: the expected sign and trend, well inside the 10 % tolerance.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <vector>

#include "homogeneous_gas.hpp"
#include "solver.hpp"
#include "time_step_guard.hpp"

namespace granshock {
namespace {

constexpr double kRestitution = 0.9;
constexpr int kGrid = 8;  // homogeneity grid, kGrid x kGrid bins

struct GasState {
  double temperature = 0;    // m <c^2> / 2, c relative to the mean velocity
  double flow_ratio = 0;     // coarse-grained flow energy / its equilibrium value
  double density_ratio = 0;  // variance / mean of the bin counts (1 for Poisson)
};

// Temperature from the particle velocities, and two homogeneity measures on a
// kGrid x kGrid grid. In an equilibrium gas the mean velocity of the n_b particles in a
// bin has variance T / (m n_b) per component, so the bin's flow energy n_b m u_b^2 / 2
// averages T: the flow ratio sum_b (n_b m u_b^2 / 2) / (kGrid^2 T) is ~1 without
// collective motion and grows with a shear (vortex) instability. The count variance over
// mean is ~1 (slightly less with excluded volume) and grows with clustering.
GasState measure(const HostParticles& p, double mass, double box_length) {
  const double n = double(p.size());
  double mean_v[2] = {0, 0};
  for (const auto& v : p.velocity)
    for (int d = 0; d < 2; ++d) mean_v[d] += v[d] / n;
  std::vector<double> count(kGrid * kGrid, 0), vx(kGrid * kGrid, 0), vy(kGrid * kGrid, 0);
  double kinetic = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const double cx = p.velocity[i][0] - mean_v[0], cy = p.velocity[i][1] - mean_v[1];
    kinetic += 0.5 * mass * (cx * cx + cy * cy);
    const int bx = std::min(kGrid - 1, int(p.position[i][0] / box_length * kGrid));
    const int by = std::min(kGrid - 1, int(p.position[i][1] / box_length * kGrid));
    const int b = bx + kGrid * by;
    count[b] += 1;
    vx[b] += cx;
    vy[b] += cy;
  }
  GasState s;
  s.temperature = kinetic / n;  // Dim = 2
  const double mean_count = n / (kGrid * kGrid);
  double flow = 0, variance = 0;
  for (int b = 0; b < kGrid * kGrid; ++b) {
    if (count[b] > 0) flow += 0.5 * mass * (vx[b] * vx[b] + vy[b] * vy[b]) / count[b];
    variance += (count[b] - mean_count) * (count[b] - mean_count) / (kGrid * kGrid);
  }
  s.flow_ratio = flow / (kGrid * kGrid * s.temperature);
  s.density_ratio = variance / mean_count;
  return s;
}

TEST(HomogeneousCooling, HaffLawMatchesKineticTheory) {
  const auto start = std::chrono::steady_clock::now();
  SystemSetup setup;
  setup.species = {{"steel", steel(), 1e-3}};
  setup.species[0].material.youngs_modulus_pa *= 1e-3;  // softened, see the top
  setup.contacts = ContactModel::uniform(1, 1.0, 0.0);   // elastic warm-up first
  GasSpec spec;
  spec.particles = 1024;
  spec.area_fraction = 0.05;
  spec.sigma_m_per_s = 1.0;
  spec.seed = 1;
  size_periodic_box(setup, spec);
  HostParticles gas = make_homogeneous_gas(setup, spec);

  const double mass = setup.species[0].mass_kg();
  const double sigma = setup.species[0].diameter_m;
  const double length = setup.box.length(0);
  const double n = double(gas.size()) / (length * length);
  const double phi = n * M_PI * sigma * sigma / 4;
  const double g = (16 - 7 * phi) / (16 * (1 - phi) * (1 - phi));  // Henderson 1975

  // Time step: t_c / 50 (DESIGN.md's safe step) for the impact speed exceeded by one
  // collision in 10^4 (the flux-weighted normal speed w has P(w > x) = exp(-x^2 / (2 s^2)),
  // s^2 = 2 T / m) at the initial temperature; the gas only cools from there. At this
  // step the Verlet-integrated contact restores e = 0.9 to within 1e-4 (a direct
  // integration of the two-particle contact, averaged over the phase of the contact
  // onset within a step), which changes 1 - e^2 by < 0.1 %.
  const double t_nominal = mass * spec.sigma_m_per_s * spec.sigma_m_per_s;
  const double v_fast = std::sqrt(2 * t_nominal / mass) * std::sqrt(2 * std::log(1e4));
  const double t_c = hertz_collision_time(setup.pair(0, 0), v_fast);
  setup.dt = t_c / 50;

  // Elastic warm-up: 5 mean collision times (the lattice melts, velocities stay Maxwellian).
  const double nu_nominal = 2 * n * sigma * g * std::sqrt(M_PI * t_nominal / mass);
  {
    auto warm = make_solver(setup, gas.size());
    warm->set_particles(gas);
    warm->advance(std::lround(5.0 / nu_nominal / setup.dt));
    gas = warm->particles();
  }

  setup.contacts = ContactModel::uniform(1, kRestitution, 0.0);
  auto solver = make_solver(setup, gas.size());
  solver->set_particles(gas);
  const GasState initial = measure(solver->particles(), mass, length);
  const double t0 = initial.temperature;
  const double slope_theory =
      (1 - kRestitution * kRestitution) * n * sigma * g * std::sqrt(M_PI / mass) / 2;
  const double tau_theory = 1 / (slope_theory * std::sqrt(t0));

  // 100 samples of T over 2 tau; least-squares line through (t, T^(-1/2)).
  const int samples = 100;
  const long steps_per_sample = std::lround(2 * tau_theory / samples / setup.dt);
  std::vector<double> time{0}, inv_sqrt_t{1 / std::sqrt(t0)}, temperature{t0};
  double worst_flow = initial.flow_ratio, worst_density = initial.density_ratio;
  for (int k = 1; k <= samples; ++k) {
    solver->advance(steps_per_sample);
    const GasState s = measure(solver->particles(), mass, length);
    time.push_back(double(k * steps_per_sample) * setup.dt);
    inv_sqrt_t.push_back(1 / std::sqrt(s.temperature));
    temperature.push_back(s.temperature);
    worst_flow = std::max(worst_flow, s.flow_ratio);
    worst_density = std::max(worst_density, s.density_ratio);
  }
  const double count = double(time.size());
  double st = 0, sy = 0, stt = 0, sty = 0;
  for (std::size_t k = 0; k < time.size(); ++k) {
    st += time[k];
    sy += inv_sqrt_t[k];
    stt += time[k] * time[k];
    sty += time[k] * inv_sqrt_t[k];
  }
  const double slope = (count * sty - st * sy) / (count * stt - st * st);
  const double intercept = (sy - slope * st) / count;
  const double tau_fit = 1 / (slope * std::sqrt(t0));
  // Largest deviation of T from the fitted Haff curve T = 1 / (intercept + slope t)^2.
  double worst_residual = 0;
  for (std::size_t k = 0; k < time.size(); ++k) {
    const double haff = 1 / std::pow(intercept + slope * time[k], 2);
    worst_residual = std::max(worst_residual, std::abs(temperature[k] / haff - 1));
  }
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf(
      "  N = %zu, phi = %.4f, g = %.4f, dt = %.3g s (t_c/50), %ld steps\n"
      "  tau fitted %.5g s, kinetic theory %.5g s: %+.2f %%; intercept sqrt(T0) = %.4f; "
      "T(2 tau) / T0 = %.4f (Haff 1/9 = 0.1111)\n"
      "  worst |T / T_fit - 1| = %.4f, worst flow ratio %.2f, worst density ratio %.2f; "
      "%.1f s wall\n",
      gas.size(), phi, g, setup.dt, solver->steps_done(), tau_fit, tau_theory,
      100 * (tau_fit / tau_theory - 1), intercept * std::sqrt(t0), temperature.back() / t0,
      worst_residual, worst_flow, worst_density, wall);

  // Reference: Haff / Enskog kinetic theory above. Tolerance 10 % (required); the known
  // neglected effects (Sonine a2, soft-contact duration, correlations) add up to ~3 %,
  // the statistical scatter between seeds is ~1 %.
  EXPECT_NEAR(tau_fit / tau_theory, 1.0, 0.10);
  // Haff's law, not just its initial slope: T^(-1/2) is a straight line through T0.
  // Intercept: within 3 % of T0^(-1/2) (the fitted line's value at t = 0; run-to-run
  // scatter seen: 1.6 %). Shape: T within 3 % of the fitted curve at every sample (T
  // falls by 9x; its scatter from the finite number of collisions is ~1 %).
  EXPECT_NEAR(intercept * std::sqrt(t0), 1.0, 0.03);
  EXPECT_LT(worst_residual, 0.03);
  // Homogeneity (the window of the fit): both ratios ~1 in equilibrium, with a sampling
  // scatter of 13-18 % per sample on this 8 x 8 grid (max over 101 samples ~1.5); a
  // developing shear or clustering instability would multiply them. Bound: 2.
  EXPECT_LT(worst_flow, 2.0);
  EXPECT_LT(worst_density, 2.0);
}

}  // namespace
}  // namespace granshock
