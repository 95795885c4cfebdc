// Synthetic particle states with known fields give n_a, u, T_a, T, phi in every bin within
// their statistical tolerance (docs/fields.md), through the REAL device accumulation: K
// independent particle states are generated on the host, handed to a solver
// (set_particles) and sampled on the device (sample_fields); the solver's sums
// (field_sums) then go through compute_bin_fields (analysis/) like a run's sums do.
//
// Each state: the paper's mixture (steel species 0, aluminium species 1, d = 1 mm) on a
// square lattice of spacing a = 1.2 d in a periodic 76.8 x 50.4 mm box (64 x 42 sites,
// 1680 steel and 1008 aluminium, species shuffled over the sites; phi = 0.545). The lattice is
// shifted by a uniform random offset and every particle jittered uniformly inside [r, a - r] of its
// cell, so particles never overlap (no contacts, no virial) while the expected number density of
// each species is uniform: n_a = N_a / A exactly. The bin grid (24 x 16 bins of 3 d from (2.0, 1.0)
// mm) does not cover the whole box, so particles outside it must not be counted. Velocities: per
// species a Maxwellian of per-component variance sigma_a^2 = T_a / m_a about a mean velocity field.
//
// Statistical tolerance: every comparison allows 5 standard errors (SE), with the SE
// computed for independent particle samples (formulas next to the assertions). The
// lattice makes the counts in a bin, and the positions within it, sub-Poisson (more
// regular than independent), so these SEs are upper bounds for n_a and phi and for the
// position-dependent parts of case 2; the velocity parts are exact. The estimators'
// O(1/N) biases (T about the estimated mean) are far below 1 SE at N ~ 2e3 to 6e3 per bin.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <functional>
#include <map>
#include <random>
#include <string>
#include <vector>

#include "analysis/bin_fields.hpp"
#include "analysis/field_physics.hpp"
#include "cases/gas/homogeneous_gas.hpp"
#include "core/bin_sums.hpp"
#include "core/solver.hpp"

using namespace granshock;

namespace {

constexpr double kD = 1e-3;          // particle diameter, m
constexpr double kLattice = 1.2e-3;  // lattice spacing a, m
constexpr int kSitesX = 64, kSitesY = 42;
constexpr int kSteel = 1680, kAluminium = 1008;  // number fraction 0.625 / 0.375
constexpr double kBin = 3e-3;                    // bin side h, m
constexpr int kBinsX = 24, kBinsY = 16;
constexpr double kGridX0 = 2.0e-3, kGridY0 = 1.0e-3;
constexpr int kBlocks = 4;
constexpr int kSamples = 1000;    // K independent states (250 per block)
constexpr double kTolerance = 5;  // standard errors

double box_x() {
  return kSitesX * kLattice;
}
double box_y() {
  return kSitesY * kLattice;
}

SolverSetup mixture_setup() {
  SolverSetup s = paper_mixture(0.5);
  s.box.lo = {0, 0, 0};
  s.box.hi = {box_x(), box_y(), kD};
  s.box.periodic = {true, true, false};
  s.dt = 1e-7;  // unused: the solver is never advanced
  return s;
}

FieldPhysics physics_of(const SolverSetup& s) {
  FieldPhysics p;
  p.dim = 2;
  for (const Species& sp : s.species) {
    p.species.push_back(sp.name);
    p.mass.push_back(sp.mass_kg());
    p.diameter.push_back(sp.diameter_m);
  }
  p.restitution = 0.5;
  p.mass_definition = MassDefinition::mixture_mean;
  p.d = kD;
  p.inflow_speed = 1.0;
  p.box_x_lo = s.box.lo[0];
  p.box_x_hi = s.box.hi[0];
  p.box_y_lo = s.box.lo[1];
  p.box_y_hi = s.box.hi[1];
  return p;
}

// The mean velocity of a particle at x (m/s).
using MeanVelocity = std::function<std::array<double, 2>(double x)>;

// One random state: shifted, jittered lattice with the species shuffled over the sites.
HostParticles random_state(std::mt19937_64& rng, std::vector<int>& species,
                           const std::vector<double>& sigma, const MeanVelocity& mean) {
  std::uniform_real_distribution<double> shift(0.0, kLattice), jitter(0.0, kLattice - kD);
  std::normal_distribution<double> gauss(0.0, 1.0);
  std::shuffle(species.begin(), species.end(), rng);
  const double sx = shift(rng), sy = shift(rng);
  HostParticles p;
  int id = 0;
  for (int j = 0; j < kSitesY; ++j) {
    for (int i = 0; i < kSitesX; ++i) {
      double x = i * kLattice + sx + 0.5 * kD + jitter(rng);
      double y = j * kLattice + sy + 0.5 * kD + jitter(rng);
      x = std::fmod(x, box_x());
      y = std::fmod(y, box_y());
      const int a = species[static_cast<std::size_t>(id)];
      const std::array<double, 2> u = mean(x);
      const double s = sigma[static_cast<std::size_t>(a)];
      p.add({x, y, 0.0}, {u[0] + s * gauss(rng), u[1] + s * gauss(rng), 0.0}, a, id);
      ++id;
    }
  }
  return p;
}

// Samples K states through the solver and returns the sums as `granshock fields` reads them.
BinSums accumulate(std::uint64_t seed, const std::vector<double>& sigma, const MeanVelocity& mean) {
  const SolverSetup setup = mixture_setup();
  auto solver = make_solver(setup, kSitesX * kSitesY);
  FieldSampling sampling;
  sampling.grid.n_species = 2;
  sampling.grid.nx = kBinsX;
  sampling.grid.ny = kBinsY;
  sampling.grid.x0 = kGridX0;
  sampling.grid.y0 = kGridY0;
  sampling.grid.dx = sampling.grid.dy = kBin;
  sampling.grid.blocks = kBlocks;
  solver->configure_sampling(sampling);

  std::vector<int> species(kSteel, 0);
  species.insert(species.end(), kAluminium, 1);
  std::mt19937_64 rng(seed);
  BinSums sums;
  sums.n_species = 2;
  sums.nx = kBinsX;
  sums.ny = kBinsY;
  sums.blocks = kBlocks;
  sums.x0 = kGridX0;
  sums.y0 = kGridY0;
  sums.dx = sums.dy = kBin;
  sums.samples.assign(kBlocks, 0.0);
  for (int k = 0; k < kSamples; ++k) {
    solver->set_particles(random_state(rng, species, sigma, mean));
    if (k == 0) {
      EXPECT_EQ(solver->diagnostics().contacts, 0) << "the lattice must not overlap";
    }
    const int block = k % kBlocks;
    solver->sample_fields(block);
    sums.samples[static_cast<std::size_t>(block)] += 1;
  }
  sums.sums = solver->field_sums(false);
  sums.check_consistent();
  return sums;
}

// Collects |measured - expected| / SE over every comparison; each must stay within 5 SE.
// The RMS of the deviations per quantity is printed as well: about 1 where the SE is exact,
// below 1 where it is an upper bound (the lattice's sub-Poisson counts).
struct Deviations {
  double worst = 0;
  std::string where;
  int checks = 0;
  std::map<std::string, std::pair<double, int>> squares;  // quantity: sum z^2, count
  void operator()(const std::string& what, std::size_t bin, double got, double want, double se) {
    ++checks;
    const double z = std::abs(got - want) / se;
    squares[what].first += z * z;
    squares[what].second += 1;
    EXPECT_LE(z, kTolerance) << what << " in bin " << bin << ": " << got << " against " << want
                             << " (SE " << se << ")";
    if (!(z <= worst)) {  // NaN is recorded as the worst
      worst = z;
      where = what + " in bin " + std::to_string(bin);
    }
  }
  void report(const char* name) const {
    std::printf(
        "[%s] %d comparisons, max |deviation| = %.3f SE = %.3f of the 5-SE tolerance (%s)\n", name,
        checks, worst, worst / kTolerance, where.c_str());
    std::printf("[%s] RMS deviation / SE:", name);
    for (const auto& [what, sum] : squares)
      std::printf(" %s %.2f", what.c_str(), std::sqrt(sum.first / sum.second));
    std::printf("\n");
  }
};

// The number densities, area fraction and species counts, common to both cases.
// N_a: the particle samples of species a in the bin, E_a = n_a V K their expectation.
void check_densities(const BinFields& f, std::size_t k, const std::vector<double>& n_true,
                     Deviations& dev) {
  const double volume = kBin * kBin, samples = kSamples;
  double n = 0;
  for (std::size_t a = 0; a < 2; ++a) {
    n += n_true[a];
    // n_a = N_a / (K V); SE(n_a) = sqrt(E_a) / (K V) (Poisson; the lattice is sub-Poisson).
    const double expected = n_true[a] * volume * samples;
    dev("n_" + std::to_string(a), k, f.species_n[a][k], n_true[a],
        std::sqrt(expected) / (samples * volume));
  }
  // phi = n pi d^2 / 4 (equal diameters); SE(phi) = (pi d^2 / 4) sqrt(n V K) / (K V).
  const double area = M_PI * kD * kD / 4;
  dev("phi", k, f.phi[k], n * area, area * std::sqrt(n * volume * samples) / (samples * volume));
}

// T = sum_a xi_a T_a, with xi_a = n_a / n the true fractions. The measured T is
// sum_a xi^_a T^_a with xi^_a = N_a / N: SE(T)^2 = sum_a N_a se_a^2 N_a / N^2 (the T_a
// noise, se_a = SE(T^_a)) + (T_0 - T_1)^2 xi_0 xi_1 / N (the noise of the fractions).
void check_mixture_temperature(const BinFields& f, std::size_t k, const std::vector<double>& n_true,
                               const std::array<double, 2>& t_species,
                               const std::array<double, 2>& se_species, Deviations& dev) {
  const double n = n_true[0] + n_true[1];
  const double xi0 = n_true[0] / n, xi1 = n_true[1] / n;
  const double big_n = f.particle_samples[k];
  double var = 0;
  for (std::size_t a = 0; a < 2; ++a) {
    const double na = f.species_samples[a][k];
    var += na * na * se_species[a] * se_species[a] / (big_n * big_n);
  }
  var += (t_species[0] - t_species[1]) * (t_species[0] - t_species[1]) * xi0 * xi1 / big_n;
  dev("T", k, f.temperature[k], xi0 * t_species[0] + xi1 * t_species[1], std::sqrt(var));
}

}  // namespace

// Case 1: uniform flow u = (0.3, 1.0) m/s, T_steel = 2 T_aluminium.
TEST(ParticleFields, UniformMixtureWithUnequalSpeciesTemperatures) {
  const auto start = std::chrono::steady_clock::now();
  const SolverSetup setup = mixture_setup();
  const FieldPhysics phys = physics_of(setup);
  const std::array<double, 2> m{phys.mass[0], phys.mass[1]};
  const std::array<double, 2> u{0.3, 1.0};
  // sigma_steel = 0.2 m/s: T_steel = m_steel sigma^2, T_al = T_steel / 2.
  const std::array<double, 2> t_species{m[0] * 0.04, m[0] * 0.02};
  const std::vector<double> sigma{std::sqrt(t_species[0] / m[0]), std::sqrt(t_species[1] / m[1])};
  const double area = box_x() * box_y();
  const std::vector<double> n_true{kSteel / area, kAluminium / area};

  const BinSums sums = accumulate(20240611, sigma, [&](double) {
    return std::array<double, 2>{u[0], u[1]};
  });
  const BinFields f = compute_bin_fields(sums, phys);

  Deviations dev;
  for (std::size_t k = 0; k < f.size(); ++k) {
    ASSERT_EQ(f.masked[k], 0) << "bin " << k;
    check_densities(f, k, n_true, dev);
    const std::array<double, 2> na{f.species_samples[0][k], f.species_samples[1][k]};
    // u = sum_a m_a C_a / sum_a m_a N_a; per component SE(u)^2 = sum_a m_a^2 N_a sigma_a^2
    // / (sum_a m_a N_a)^2 (independent velocities, counts as observed).
    const double mass = m[0] * na[0] + m[1] * na[1];
    const double se_u = std::sqrt(m[0] * m[0] * na[0] * sigma[0] * sigma[0] +
                                  m[1] * m[1] * na[1] * sigma[1] * sigma[1]) /
                        mass;
    dev("ux", k, f.ux[k], u[0], se_u);
    dev("uy", k, f.uy[k], u[1], se_u);
    std::array<double, 2> se_t{};
    for (std::size_t a = 0; a < 2; ++a) {
      const std::string s = std::to_string(a);
      // u_a = C_a / N_a; SE = sigma_a / sqrt(N_a).
      dev("ux_" + s, k, f.species_ux[a][k], u[0], sigma[a] / std::sqrt(na[a]));
      dev("uy_" + s, k, f.species_uy[a][k], u[1], sigma[a] / std::sqrt(na[a]));
      // T_a = m_a <|c_a - u|^2> / 2 = m_a 2 sigma_a^2 / 2 (u_a = u). |c - u|^2 / sigma^2 is
      // chi^2 with Dim = 2 degrees of freedom, variance 4: SE(T_a) = m_a sigma_a^2 / sqrt(N_a)
      // = T_a / sqrt(N_a).
      se_t[a] = t_species[a] / std::sqrt(na[a]);
      dev("T_" + s, k, f.species_temperature[a][k], t_species[a], se_t[a]);
    }
    check_mixture_temperature(f, k, n_true, t_species, se_t, dev);
  }
  dev.report("uniform mixture");
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf("[uniform mixture] %d samples of %d particles in %.2f s\n", kSamples,
              kSitesX * kSitesY, seconds);
}

// Case 2: a linear shear u = (0.3, gamma (x - x_mid)) at a uniform temperature T_0 of both
// species. The bin mean is the shear at the bin centre x_c (x uniform in the bin), and the
// bin temperature includes the shear the bin does not resolve: with xi = x - x_c uniform on
// [-h/2, h/2], c_y - u_y,bin = gamma xi + (fluctuation), so
//   <|c - u_bin|^2> = 2 sigma_a^2 + gamma^2 <xi^2> = 2 sigma_a^2 + gamma^2 h^2 / 12,
//   T_a,bin = m_a <|c - u_bin|^2> / Dim = T_0 + m_a gamma^2 h^2 / 24,
//   T_bin = sum_a xi_a T_a,bin = T_0 + (sum_a xi_a m_a) gamma^2 h^2 / 24.
TEST(ParticleFields, LinearShearAddsTheUnresolvedShearToTheBinTemperature) {
  const auto start = std::chrono::steady_clock::now();
  const SolverSetup setup = mixture_setup();
  const FieldPhysics phys = physics_of(setup);
  const std::array<double, 2> m{phys.mass[0], phys.mass[1]};
  const double t0 = m[0] * 0.04;  // sigma_steel = 0.2 m/s, sigma_al = sqrt(T_0 / m_al)
  const std::vector<double> sigma{std::sqrt(t0 / m[0]), std::sqrt(t0 / m[1])};
  // gamma^2 h^2 / 12 = 3 sigma_steel^2: the unresolved shear quadruples the steel's y variance.
  const double gamma = std::sqrt(3 * 0.04 * 12.0) / kBin;  // 1/s
  const double x_mid = 0.5 * box_x(), ux = 0.3, h = kBin;
  const double shear_var = gamma * gamma * h * h / 12;  // variance of u_y across a bin
  const double area = box_x() * box_y();
  const std::vector<double> n_true{kSteel / area, kAluminium / area};

  const BinSums sums = accumulate(987654321, sigma, [&](double x) {
    return std::array<double, 2>{ux, gamma * (x - x_mid)};
  });
  const BinFields f = compute_bin_fields(sums, phys);

  Deviations dev;
  double smallest_shear_share = 1e300;
  for (int iy = 0; iy < kBinsY; ++iy) {
    for (int ix = 0; ix < kBinsX; ++ix) {
      const std::size_t k = f.index(iy, ix);
      ASSERT_EQ(f.masked[k], 0) << "bin " << k;
      check_densities(f, k, n_true, dev);
      const double x_c = sums.x_centre(ix);
      const std::array<double, 2> na{f.species_samples[0][k], f.species_samples[1][k]};
      const double mass = m[0] * na[0] + m[1] * na[1];
      // SE(u_x)^2 = sum_a m_a^2 N_a sigma_a^2 / (sum_a m_a N_a)^2; for u_y the variance per
      // particle about the bin mean is sigma_a^2 + gamma^2 h^2 / 12.
      const double se_ux = std::sqrt(m[0] * m[0] * na[0] * sigma[0] * sigma[0] +
                                     m[1] * m[1] * na[1] * sigma[1] * sigma[1]) /
                           mass;
      const double se_uy = std::sqrt(m[0] * m[0] * na[0] * (sigma[0] * sigma[0] + shear_var) +
                                     m[1] * m[1] * na[1] * (sigma[1] * sigma[1] + shear_var)) /
                           mass;
      dev("ux", k, f.ux[k], ux, se_ux);
      dev("uy", k, f.uy[k], gamma * (x_c - x_mid), se_uy);
      std::array<double, 2> t_species{}, se_t{};
      for (std::size_t a = 0; a < 2; ++a) {
        const std::string s = std::to_string(a);
        const double s2 = sigma[a] * sigma[a];
        dev("uy_" + s, k, f.species_uy[a][k], gamma * (x_c - x_mid),
            std::sqrt((s2 + shear_var) / na[a]));
        t_species[a] = t0 + m[a] * gamma * gamma * h * h / 24;
        // Var|c - u_bin|^2 = Var(f_x^2) + Var((gamma xi + f_y)^2)
        //   = 2 s^4 + [gamma^4 h^4 / 80 + gamma^2 h^2 s^2 / 2 + 3 s^4 - (gamma^2 h^2/12 + s^2)^2]
        //   = 4 s^4 + (2/3) gamma^2 h^2 s^2 + gamma^4 h^4 / 180      (E xi^4 = h^4 / 80),
        // SE(T_a) = (m_a / Dim) sqrt(Var / N_a).
        const double g2h2 = gamma * gamma * h * h;
        const double var = 4 * s2 * s2 + 2.0 / 3.0 * g2h2 * s2 + g2h2 * g2h2 / 180;
        se_t[a] = m[a] / 2 * std::sqrt(var / na[a]);
        dev("T_" + s, k, f.species_temperature[a][k], t_species[a], se_t[a]);
        // The shear term is many SE: a T_a without it would fail.
        smallest_shear_share = std::min(smallest_shear_share, (t_species[a] - t0) / se_t[a]);
      }
      check_mixture_temperature(f, k, n_true, t_species, se_t, dev);
    }
  }
  EXPECT_GT(smallest_shear_share, 2 * kTolerance) << "the shear term must dominate the noise";
  dev.report("linear shear");
  std::printf("[linear shear] gamma = %.1f 1/s; shear term / SE(T_a) at least %.1f\n", gamma,
              smallest_shear_share);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf("[linear shear] %d samples of %d particles in %.2f s\n", kSamples, kSitesX * kSitesY,
              seconds);
}
