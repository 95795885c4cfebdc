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
//     g(phi) = (16 - 7 phi) / (16 (1 - phi)^2) (Henderson 1975, as in docs/fields.md).
//   Equivalently T^(-1/2) = T0^(-1/2) + s t with the T0-independent slope
//       s = (1 - e^2) n sigma g(phi) sqrt(pi / m) / 2,
//   so the test fits a straight line to T^(-1/2)(t) and reports tau = 1 / (s sqrt(T0)).
// Neglected: the non-Gaussian velocity distribution of the cooling state (Sonine
// coefficient a2 = -0.027 in 2-D at e = 0.9, changing the cooling rate by 3 a2 / 16 =
// -0.5 %, Brilliantov & Poeschel 2004) and velocity correlations (small at phi = 0.05).
//
// Scene: 529 steel spheres (d = 1 mm, Young's modulus scaled down 1000x: contacts last
// 1000^(2/5) = 16x longer, so the run is 16x cheaper) at area fraction phi = 0.05,
// e = 0.9, no friction, in a periodic square box of L = 91 d (18 mean free paths
// l = 1 / (2 sqrt(2) n sigma g)), started on the jittered lattice of make_homogeneous_gas
// with Gaussian velocities. The cooling run lasts 2 tau (T falls to T0 / 9; ~23
// collisions per particle, 6e3 in all).
//
// Homogeneity. The cooling state is unstable to shear (vortex) modes longer than
// L_c = 2 pi / k_c: a transverse velocity mode decays by viscosity at nu_visc k^2 while
// the thermal speed decays at 1 / tau (at t = 0), with the dilute 2-D kinematic viscosity
// nu_visc = sqrt(T / (pi m)) / (2 n sigma) (Chapman & Cowling), so modes with
// k^2 < (1 - e^2) pi g (n sigma)^2 grow relative to the thermal motion. Here
// L_c = 123 d: the box (91 d) keeps every mode stable. (A 1024-particle box of 127 d was
// marginal: its box-scale shear modes grew to 5x their thermal energy within 2 tau.)
// The test checks both the shear modes and density clustering.
//
// Initial state: on the lattice no pair is near contact, so the first collision time
// cools more slowly than kinetic theory (which assumes the equilibrium contact value
// g(phi)). The effect is within the scatter: over 12 seeds, an elastic warm-up of 5
// collision times before the cooling moved the mean excess of the fitted tau from
// 2.8 % to 2.2 % (scatter of one run: 1.6 %), so the test starts from the lattice.
//
// Expected deviation. Over those 24 runs the fitted tau exceeded the theory by -0.1 to
// +6.1 % (mean 2.5 %, standard deviation 1.6 %); the fitted line started within 1.8 % of
// T0^(-1/2). Contributions: the Sonine correction (+0.5 %), and soft contacts: with
// finite collision duration t_c a particle spends a fraction ~nu t_c (about 1 % here)
// of its time in contact, which slows the cooling; in a larger box the excess grew with
// softening (about 2 % at E / 10^2, 4 % at E / 10^3 and 10^4).
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <vector>

#include "cases/gas/homogeneous_gas.hpp"
#include "core/solver.hpp"
#include "kernels/models/hertz.hpp"
#include "kernels/models/time_step_guard.hpp"

namespace granshock {
namespace {

constexpr double kRestitution = 0.9;
constexpr int kGrid = 8;  // homogeneity grid, kGrid x kGrid bins

struct GasState {
  double temperature = 0;    // m <c^2> / 2, c relative to the mean velocity
  double shear_ratio = 0;    // energy of the longest shear modes / its equilibrium value
  double density_ratio = 0;  // variance / mean of the bin counts (1 for Poisson)
};

// Temperature from the particle velocities, and two homogeneity measures.
// Shear: the transverse velocity field of the four longest modes k = 2 pi (1,0)/L,
// (0,1)/L, (1,1)/L, (1,-1)/L, u_k = sum_i (c_i . t_k) exp(i k . x_i) with t_k the unit
// vector normal to k. In equilibrium each |u_k|^2 averages N T / m (independent
// particles), so shear_ratio = (m / (4 N T)) sum_k |u_k|^2 averages 1. In the cooling
// state the stable long modes are enhanced by 1 / (1 - (k_c / k)^2) (fluctuating
// hydrodynamics: van Noije, Ernst, Brito & Orza, Phys. Rev. Lett. 79, 411 (1997)), here
// 2.2 for the two longest modes and 1.4 for the diagonal ones: mean ~1.8 once the
// cooling state is established, with the scatter of a sum of 4 exponential variables
// (seen over seven runs: sample maxima 1.6 to 3.5). An unstable mode grows without bound.
// Clustering: variance over mean of the particle counts on a kGrid x kGrid grid: ~1 in
// equilibrium (Poisson; slightly less with excluded volume), larger when clusters form.
GasState measure(const HostParticles& p, double mass, double box_length) {
  const double n = double(p.size());
  double mean_v[2] = {0, 0};
  for (const auto& v : p.velocity)
    for (int d = 0; d < 2; ++d) mean_v[d] += v[d] / n;
  std::vector<double> count(kGrid * kGrid, 0);
  double kinetic = 0;
  const int modes[4][2] = {{1, 0}, {0, 1}, {1, 1}, {1, -1}};
  double re[4] = {0, 0, 0, 0}, im[4] = {0, 0, 0, 0};
  for (std::size_t i = 0; i < p.size(); ++i) {
    const double c[2] = {p.velocity[i][0] - mean_v[0], p.velocity[i][1] - mean_v[1]};
    kinetic += 0.5 * mass * (c[0] * c[0] + c[1] * c[1]);
    for (int k = 0; k < 4; ++k) {
      const double kx = modes[k][0], ky = modes[k][1];
      const double transverse = (-c[0] * ky + c[1] * kx) / std::sqrt(kx * kx + ky * ky);
      const double phase = 2 * M_PI * (kx * p.position[i][0] + ky * p.position[i][1]) / box_length;
      re[k] += transverse * std::cos(phase);
      im[k] += transverse * std::sin(phase);
    }
    const int bx = std::min(kGrid - 1, int(p.position[i][0] / box_length * kGrid));
    const int by = std::min(kGrid - 1, int(p.position[i][1] / box_length * kGrid));
    count[bx + kGrid * by] += 1;
  }
  GasState s;
  s.temperature = kinetic / n;  // Dim = 2
  for (int k = 0; k < 4; ++k)
    s.shear_ratio += mass * (re[k] * re[k] + im[k] * im[k]) / (4 * n * s.temperature);
  const double mean_count = n / (kGrid * kGrid);
  double variance = 0;
  for (double c : count) variance += (c - mean_count) * (c - mean_count) / (kGrid * kGrid);
  s.density_ratio = variance / mean_count;
  return s;
}

// The least-squares line y = intercept + slope x through the points.
struct Line {
  double slope, intercept;
};
Line least_squares_line(const std::vector<double>& x, const std::vector<double>& y) {
  const double count = double(x.size());
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (std::size_t k = 0; k < x.size(); ++k) {
    sx += x[k];
    sy += y[k];
    sxx += x[k] * x[k];
    sxy += x[k] * y[k];
  }
  const double slope = (count * sxy - sx * sy) / (count * sxx - sx * sx);
  return {slope, (sy - slope * sx) / count};
}

TEST(HomogeneousCooling, HaffLawMatchesKineticTheory) {
  const auto start = std::chrono::steady_clock::now();
  SolverSetup setup;
  setup.species = {{"steel", steel(), 1e-3}};
  setup.species[0].material.youngs_modulus_pa *= 1e-3;  // softened, see the top
  setup.contacts = ContactSettings::uniform(1, kRestitution, 0.0);
  GasSpec spec;
  spec.particles = 529;  // a full 23 x 23 lattice
  spec.area_fraction = 0.05;
  spec.sigma_m_per_s = 1.0;
  spec.seed = 1;
  size_periodic_box(setup, spec);
  const HostParticles gas = make_homogeneous_gas(setup, spec);

  const double mass = setup.species[0].mass_kg();
  const double sigma = setup.species[0].diameter_m;
  const double length = setup.box.length(0);
  const double n = double(gas.size()) / (length * length);
  const double phi = n * M_PI * sigma * sigma / 4;
  const double g = (16 - 7 * phi) / (16 * (1 - phi) * (1 - phi));  // Henderson 1975
  const GasState initial = measure(gas, mass, length);
  const double t0 = initial.temperature;

  // Time step: t_c / 50 (well inside the guard's t_c/10 warning, docs/contact_model.md) at the
  // impact speed exceeded by one collision in 10^4 at the initial temperature (the flux-weighted
  // normal speed w has P(w > x) = exp(-x^2 / (2 s^2)), s^2 = 2 T / m); the gas only cools from
  // there. At this step the Verlet-integrated contact restores e = 0.9 to within 1e-4 (a direct
  // integration of the two-particle contact law, averaged over where in a step the
  // contact begins), which changes 1 - e^2 by < 0.1 %.
  const double v_fast = std::sqrt(2 * t0 / mass) * std::sqrt(2 * std::log(1e4));
  setup.dt = HertzModel::collision_time(setup.pair(0, 0), ContactOptions{}, v_fast) / 50;

  auto solver = make_solver(setup, gas.size());
  solver->set_particles(gas);
  const double slope_theory =
      (1 - kRestitution * kRestitution) * n * sigma * g * std::sqrt(M_PI / mass) / 2;
  const double tau_theory = 1 / (slope_theory * std::sqrt(t0));

  // 100 samples of T over 2 tau; least-squares line through (t, T^(-1/2)).
  const int samples = 100;
  const long steps_per_sample = std::lround(2 * tau_theory / samples / setup.dt);
  std::vector<double> time{0}, inv_sqrt_t{1 / std::sqrt(t0)};
  double worst_shear = initial.shear_ratio, worst_density = initial.density_ratio;
  double t_end = t0;
  for (int k = 1; k <= samples; ++k) {
    solver->advance(steps_per_sample);
    const GasState s = measure(solver->particles(), mass, length);
    time.push_back(solver->time());
    inv_sqrt_t.push_back(1 / std::sqrt(s.temperature));
    worst_shear = std::max(worst_shear, s.shear_ratio);
    worst_density = std::max(worst_density, s.density_ratio);
    t_end = s.temperature;
  }
  const auto [slope, intercept] = least_squares_line(time, inv_sqrt_t);
  const double tau_fit = 1 / (slope * std::sqrt(t0));
  const double wall =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf(
      "  N = %zu, phi = %.4f, g = %.4f, L = %.1f d, dt = %.3g s (t_c/50), %ld steps\n"
      "  tau fitted %.5g s, kinetic theory %.5g s: %+.2f %%; intercept * sqrt(T0) = %.4f; "
      "T(end) / T0 = %.4f at t = %.3f tau_theory (Haff: %.4f)\n"
      "  worst shear-mode ratio %.2f, worst density ratio %.2f; %.1f s wall\n",
      gas.size(), phi, g, length / sigma, setup.dt, solver->steps_done(), tau_fit, tau_theory,
      100 * (tau_fit / tau_theory - 1), intercept * std::sqrt(t0), t_end / t0,
      time.back() / tau_theory, 1 / std::pow(1 + time.back() / tau_theory, 2), worst_shear,
      worst_density, wall);

  // Reference: Haff's law with the Enskog cooling rate (top of the file). Tolerance 10 %
  // (required); expected: +2.5 % from neglected effects, scatter 1.6 % (top of the file).
  EXPECT_NEAR(tau_fit / tau_theory, 1.0, 0.10);
  // Haff's law, not only its mean slope: the fitted line T^(-1/2) = a + s t must start at
  // the measured T0, a = T0^(-1/2), within 3 % (24 runs with other seeds: within 1.8 %,
  // standard deviation 0.9 %); a transient at the start or a bending curve (cooling that
  // slows down or speeds up) would move it.
  EXPECT_NEAR(intercept * std::sqrt(t0), 1.0, 0.03);
  // Homogeneity over the fit window (see measure()): the shear-mode ratio below 8 (about
  // 4x its expected value of ~1.8 in the cooling state; with its Gamma(4) scatter a
  // sample exceeds 8 with probability ~1e-4), the density variance below twice the
  // Poisson value (expected ~0.9, sampling scatter 18 % on 64 bins; seen: up to 1.5).
  EXPECT_LT(worst_shear, 8.0);
  EXPECT_LT(worst_density, 2.0);
}

// 3-D, spheres (Brilliantov & Poeschel 2004, as above with the 3-D forms): T = m <c^2> / 3;
// a pair at relative velocity g collides over the cross-section pi sigma^2, and over a
// Maxwellian <|g|^3> = 8 sqrt(2 / pi) (2 T / m)^(3/2), so the loss per unit volume is
// 2 sqrt(pi) n^2 sigma^2 g(phi) (1 - e^2) T^(3/2) / sqrt(m) out of (3/2) n T:
//   dT/dt = -(4/3) sqrt(pi) n sigma^2 g(phi) (1 - e^2) sqrt(T / m) T,
//   T^(-1/2) = T0^(-1/2) + s t,  s = (2/3) sqrt(pi) n sigma^2 g(phi) (1 - e^2) / sqrt(m),
// with Carnahan-Starling's g = (1 - phi/2) / (1 - phi)^3. The Sonine correction is
// -0.3 % at e = 0.9 (a2 = -0.015 in 3-D).
// Scene: 512 spheres (8^3 lattice) at volume fraction 0.05, e = 0.9, the softened steel
// above, in a periodic cube of 17.5 d (8 mean free paths, l = 1 / (sqrt(2) pi n sigma^2 g)).
// The 3-D shear instability sets in at L_c = 2 pi / k_c with
// k_c^2 = (32/15) pi g (1 - e^2) (n sigma^2)^2 (dilute viscosity 5/(16 sigma^2)
// sqrt(m T / pi) against the cooling rate): L_c = 56 d, three times the box, so the box's
// modes are stable and the test checks the density only. Cooling over 2 tau takes about
// 35 collisions per particle (6 / (1 - e^2) per tau at the start).
// Measured over 12 seeds (1-12): the fitted tau exceeded the theory by +1.3 to +5.3 %
// (mean +3.5 %: soft contacts, as in 2-D, with 3.2 times the 2-D collision rate per
// particle here), the fitted line started within 1.9 % of T0^(-1/2), the density ratio
// stayed below 1.30.
TEST(HomogeneousCooling, HaffLawIn3dMatchesKineticTheory) {
  const auto start = std::chrono::steady_clock::now();
  SolverSetup setup;
  setup.dim = 3;
  setup.species = {{"steel", steel(), 1e-3}};
  setup.species[0].material.youngs_modulus_pa *= 1e-3;  // softened, see the top
  setup.contacts = ContactSettings::uniform(1, kRestitution, 0.0);
  GasSpec spec;
  spec.particles = 512;
  spec.area_fraction = 0.05;  // of volume in 3-D
  spec.sigma_m_per_s = 1.0;
  spec.seed = 1;
  size_periodic_box(setup, spec);
  const HostParticles gas = make_homogeneous_gas(setup, spec);
  const double mass = setup.species[0].mass_kg();
  const double sigma = setup.species[0].diameter_m;
  const double length = setup.box.length(0);
  const double n = double(gas.size()) / std::pow(length, 3);
  const double phi = n * M_PI * std::pow(sigma, 3) / 6;
  const double g = (1 - phi / 2) / std::pow(1 - phi, 3);  // Carnahan-Starling

  constexpr int bins = 4;  // 4^3 bins, 8 spheres each on average
  // T = m <c^2> / 3 and the variance / mean of the bins' counts (1 for Poisson).
  auto measure_3d = [&](const HostParticles& p, double& temperature, double& density_ratio) {
    const double count = double(p.size());
    double mean_v[3] = {0, 0, 0};
    for (const auto& v : p.velocity)
      for (int d = 0; d < 3; ++d) mean_v[d] += v[d] / count;
    double kinetic = 0;
    std::vector<double> in_bin(bins * bins * bins, 0);
    for (std::size_t i = 0; i < p.size(); ++i) {
      int flat = 0;
      for (int d = 2; d >= 0; --d) {
        const double c = p.velocity[i][d] - mean_v[d];
        kinetic += 0.5 * mass * c * c;
        flat = flat * bins + std::min(bins - 1, int(p.position[i][d] / length * bins));
      }
      in_bin[std::size_t(flat)] += 1;
    }
    temperature = kinetic / count * (2.0 / 3.0);
    const double mean = count / in_bin.size();
    double variance = 0;
    for (double c : in_bin) variance += (c - mean) * (c - mean) / double(in_bin.size());
    density_ratio = variance / mean;
  };
  double t0, density0;
  measure_3d(gas, t0, density0);

  // t_c / 50 at the fast impacts of the initial temperature, as in 2-D above.
  const double v_fast = std::sqrt(2 * t0 / mass) * std::sqrt(2 * std::log(1e4));
  setup.dt = HertzModel::collision_time(setup.pair(0, 0), ContactOptions{}, v_fast) / 50;
  auto solver = make_solver(setup, gas.size());
  solver->set_particles(gas);
  const double slope_theory = (2.0 / 3.0) * std::sqrt(M_PI) * n * sigma * sigma * g *
                              (1 - kRestitution * kRestitution) / std::sqrt(mass);
  const double tau_theory = 1 / (slope_theory * std::sqrt(t0));

  const int samples = 100;
  const long steps_per_sample = std::lround(2 * tau_theory / samples / setup.dt);
  std::vector<double> time{0}, inv_sqrt_t{1 / std::sqrt(t0)};
  double worst_density = density0, t_end = t0;
  for (int k = 1; k <= samples; ++k) {
    solver->advance(steps_per_sample);
    double temperature, density;
    measure_3d(solver->particles(), temperature, density);
    time.push_back(solver->time());
    inv_sqrt_t.push_back(1 / std::sqrt(temperature));
    worst_density = std::max(worst_density, density);
    t_end = temperature;
  }
  const auto [slope, intercept] = least_squares_line(time, inv_sqrt_t);
  const double tau_fit = 1 / (slope * std::sqrt(t0));
  const double wall =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf(
      "  3-D: N = %zu, phi = %.4f, g = %.4f, L = %.1f d, dt = %.3g s (t_c/50), %ld steps\n"
      "  tau fitted %.5g s, kinetic theory %.5g s: %+.2f %%; intercept * sqrt(T0) = %.4f; "
      "T(end) / T0 = %.4f at t = %.3f tau_theory (Haff: %.4f)\n"
      "  worst density ratio %.2f; %.1f s wall\n",
      gas.size(), phi, g, length / sigma, setup.dt, solver->steps_done(), tau_fit, tau_theory,
      100 * (tau_fit / tau_theory - 1), intercept * std::sqrt(t0), t_end / t0,
      time.back() / tau_theory, 1 / std::pow(1 + time.back() / tau_theory, 2), worst_density, wall);

  // The 2-D test's tolerances: tau within 10 % of kinetic theory, the line's start within
  // 3 % of the measured T0, and the density variance below twice Poisson's (64 bins of 8:
  // sampling scatter 18 %).
  EXPECT_NEAR(tau_fit / tau_theory, 1.0, 0.10);
  EXPECT_NEAR(intercept * std::sqrt(t0), 1.0, 0.03);
  EXPECT_LT(worst_density, 2.0);
}

}  // namespace
}  // namespace granshock
