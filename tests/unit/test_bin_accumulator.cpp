// Field sampling on the device (docs/fields.md): atomic, ScatterView and
// row-owner accumulation equal a serial reference accumulation on the host; row owners
// give bitwise the same sums with 1 and 2 threads. Counts are exact; the
// velocity moments and the contact virial agree to round-off (summation order differs),
// relative 1e-12. The reference virial comes from the elastic Hertz force written here
// (e = 1: F = 4/3 Y* sqrt(R*) dn^(3/2) along n), not from the solver's kernel. The host and
// the device paths of the kernels (docs/cuda.md, "Branch points") agree within the bound
// of a sum taken in another order.
#include <gtest/gtest.h>

#include <Kokkos_Core.hpp>
#include <cmath>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "cases/gas/homogeneous_gas.hpp"
#include "core/solver.hpp"
#include "kernels/device/backends.hpp"
#include "same_particles.hpp"
#include "solver_on_paths.hpp"

using namespace granshock;

namespace {

struct Fixture {
  SolverSetup setup;
  FieldSampling sampling;
  std::unique_ptr<Solver> solver;
};

Fixture dense_gas(int warmup_steps) {
  Fixture f;
  f.setup = paper_mixture(1.0);  // elastic: the force is the Hertz spring alone
  GasSpec spec;
  spec.particles = 3000;
  spec.area_fraction = 0.5;
  spec.sigma_m_per_s = 2.0;
  size_periodic_box(f.setup, spec);
  f.setup.dt = 5e-8;
  f.solver = make_solver(f.setup, spec.particles);
  f.solver->set_particles(make_homogeneous_gas(f.setup, spec));
  f.solver->advance(warmup_steps);
  // A grid like the bow-shock's (cases/bow_shock/sampling_plan.cpp): rectangular bins whose
  // columns tile the periodic width from x0 > 0, so that the last column wraps across x = 0.
  BinLayout& g = f.sampling.grid;
  g.n_species = 2;
  g.nx = int(f.setup.box.length(0) / 3e-3);
  g.dx = f.setup.box.length(0) / g.nx;
  g.x0 = f.setup.box.lo[0] + 0.4 * g.dx;
  g.x_period = f.setup.box.length(0);
  g.dy = 2.5e-3;
  g.ny = int(f.setup.box.length(1) / g.dy);
  g.blocks = 4;
  BinLayout& pr = f.sampling.profile;
  pr = g;
  pr.x_period = 0;
  pr.nx = 8;
  pr.dx = pr.dy = 5e-4;
  pr.x0 = 0.01;
  pr.y0 = 0.0;
  pr.ny = 40;
  return f;
}

// The host reference: the same binning, summed serially; with `magnitudes` the sum of
// each term's absolute value instead (the scale of a summation's round-off).
std::vector<double> reference_sums(const Fixture& f, const HostParticles& p, int block,
                                   bool profile, bool magnitudes = false) {
  const auto term = [magnitudes](double x) { return magnitudes ? std::abs(x) : x; };
  const BinLayout& g = f.sampling.grid;
  const BinLayout& layout = profile ? f.sampling.profile : g;
  const int q = g.quantities();
  const long bins = layout.bins();
  std::vector<double> sums(std::size_t(g.blocks) * bins * q, 0.0);
  const double length[2] = {f.setup.box.length(0), f.setup.box.length(1)};
  for (std::size_t i = 0; i < p.size(); ++i) {
    const double x = p.position[i][0], y = p.position[i][1];
    // Left of x0 on a periodic axis: the same place one period further right.
    const double xs = x < layout.x0 && layout.x_period > 0 ? x + layout.x_period : x;
    const long ix = long(std::floor((xs - layout.x0) / layout.dx)),
               iy = long(std::floor((y - layout.y0) / layout.dy));
    if (ix < 0 || ix >= layout.nx || iy < 0 || iy >= layout.ny) continue;
    const long bin = iy * layout.nx + ix;
    double* s = &sums[(std::size_t(block) * bins + bin) * q];
    const double vx = p.velocity[i][0], vy = p.velocity[i][1];
    double* sp = s + BinLayout::per_species * p.species[i];
    sp[0] += 1;
    sp[1] += term(vx);
    sp[2] += term(vy);
    sp[3] += vx * vx;
    sp[4] += term(vx * vy);
    sp[5] += vy * vy;
    // Virial of particle i: sum over partners j of 1/2 r_ij (x) F_ij (elastic Hertz).
    for (std::size_t j = 0; j < p.size(); ++j) {
      if (j == i) continue;
      double r[2];
      for (int d = 0; d < 2; ++d) {
        r[d] = p.position[i][d] - p.position[j][d];
        r[d] -= length[d] * std::round(r[d] / length[d]);
      }
      const double dist = std::hypot(r[0], r[1]);
      const PairProperties pp = f.setup.pair(p.species[i], p.species[j]);
      const double dn = 2 * 0.5e-3 - dist;
      if (dn <= 0) continue;
      const double fn = 4.0 / 3.0 * pp.youngs_star * std::sqrt(pp.radius_star) * std::pow(dn, 1.5);
      for (int a = 0; a < 2; ++a)
        for (int b = 0; b < 2; ++b)
          s[g.virial_index(BinLayout::w_xx) + 2 * a + b] += term(0.5 * r[a] * fn * r[b] / dist);
    }
  }
  return sums;
}

void expect_close(const std::vector<double>& got, const std::vector<double>& want,
                  const char* what) {
  ASSERT_EQ(got.size(), want.size()) << what;
  double scale = 0;
  for (double w : want) scale = std::max(scale, std::abs(w));
  std::size_t bad = 0;
  for (std::size_t k = 0; k < got.size(); ++k)
    bad += std::abs(got[k] - want[k]) > 1e-12 * std::max(std::abs(want[k]), 1e-300) + 1e-14 * scale;
  EXPECT_EQ(bad, 0u) << what << ": entries differing from the serial reference";
}

}  // namespace

TEST(BinAccumulator, EveryStrategyEqualsTheSerialReference) {
  Fixture f = dense_gas(4000);  // about two mean free times: contacts form
  const HostParticles p = f.solver->particles();
  ASSERT_GT(f.solver->diagnostics().contacts, 20) << "the test needs contacts for the virial";
  const auto grid_ref = reference_sums(f, p, 2, false);
  const auto profile_ref = reference_sums(f, p, 2, true);
  for (const ScatterStrategy strategy : {ScatterStrategy::atomic, ScatterStrategy::scatter_view,
                                         ScatterStrategy::rows, ScatterStrategy::automatic}) {
    f.sampling.strategy = strategy;
    f.solver->configure_sampling(f.sampling);
    f.solver->sample_fields(2);
    const char* names[] = {"automatic", "atomic", "scatter_view", "rows"};
    const char* name = names[int(strategy)];
    expect_close(f.solver->field_sums(false), grid_ref, name);
    expect_close(f.solver->field_sums(true), profile_ref, name);
  }
}

TEST(BinAccumulator, SamplingDoesNotChangeTheTrajectory) {
  Fixture a = dense_gas(500), b = dense_gas(500);
  b.solver->configure_sampling(b.sampling);
  for (int k = 0; k < 5; ++k) {
    a.solver->advance(50);
    b.solver->advance(50);
    b.solver->sample_fields(k % 4);
  }
  const HostParticles pa = a.solver->particles(), pb = b.solver->particles();
  EXPECT_EQ(pa.position, pb.position);
  EXPECT_EQ(pa.velocity, pb.velocity);
}

// Row owners add each bin's particles in particle order whatever the thread count: the
// Serial backend (one owner) and the default backend (its threads) agree bitwise.
TEST(BinAccumulator, RowOwnersAreBitwiseTheSameForAnyThreadCount) {
  if constexpr (!GRANSHOCK_SEPARATE_SERIAL)
    GTEST_SKIP() << "needs Serial beside the default backend (this Kokkos or build has none)";
  if (Kokkos::DefaultExecutionSpace().concurrency() < 2)
    GTEST_SKIP() << "needs the default backend with 2 or more threads (OMP_NUM_THREADS=2)";
  Fixture f = dense_gas(0);
  const HostParticles gas = f.solver->particles();
  auto serial = make_solver(f.setup, gas.size(), Backend::serial);
  serial->set_particles(gas);
  f.solver->set_particles(gas);
  f.sampling.strategy = ScatterStrategy::rows;
  for (Solver* s : {f.solver.get(), serial.get()}) {
    s->configure_sampling(f.sampling);
    for (int k = 0; k < 3; ++k) {
      s->advance(300);
      s->sample_fields(k);
    }
  }
  EXPECT_EQ(f.solver->field_sums(false), serial->field_sums(false));
  EXPECT_EQ(f.solver->field_sums(true), serial->field_sums(true));
  EXPECT_GT(f.solver->diagnostics().contacts, 0);
}

namespace {

// Adds b to a, entry by entry (a empty: a becomes b).
void accumulate(std::vector<double>& a, const std::vector<double>& b) {
  if (a.empty()) a.assign(b.size(), 0.0);
  for (std::size_t k = 0; k < b.size(); ++k) a[k] += b[k];
}

}  // namespace

// Host paths against device paths (kernels/device/backends.hpp; docs/cuda.md, "Branch
// points"): `automatic` is row owners on host paths and atomic adds on device paths,
// `scatter_view` one copy per thread against one copy with atomic adds. Both add the same
// terms (the trajectories are bitwise the same, checked), in different orders: counts
// are equal, and every other sum within the bound of a sum of n terms in any order,
// 2 (n - 1) u sum |x_i| (u = 2^-53; Higham, Accuracy and Stability of Numerical
// Algorithms, 2002, eq. 4.4), n and sum |x_i| taken from the particles sampled.
TEST(BinAccumulator, DevicePathsAgreeWithHostPathsWithinTheSummationBound) {
  Fixture f = dense_gas(0);
  const HostParticles gas = f.solver->particles();
  const ScatterStrategy strategies[] = {ScatterStrategy::automatic, ScatterStrategy::scatter_view};
  std::vector<std::unique_ptr<Solver>> host, device;  // one of each per strategy
  for (const ScatterStrategy strategy : strategies) {
    f.sampling.strategy = strategy;
    host.push_back(test::make_solver_on_paths(f.setup, gas.size(), test::Paths::host));
    device.push_back(test::make_solver_on_paths(f.setup, gas.size(), test::Paths::device));
    for (Solver* s : {host.back().get(), device.back().get()}) {
      s->set_particles(gas);
      s->configure_sampling(f.sampling);
    }
  }
  std::vector<double> grid_scale, profile_scale;
  long terms = 0;
  for (int k = 0; k < 4; ++k) {
    for (std::size_t m = 0; m < host.size(); ++m)
      for (Solver* s : {host[m].get(), device[m].get()}) {
        s->advance(200);
        s->sample_fields(k);
      }
    // Sampling leaves the trajectory alone (above): every solver holds these particles.
    const HostParticles p = host[0]->particles();
    terms += long(p.size());
    accumulate(grid_scale, reference_sums(f, p, k, false, true));
    accumulate(profile_scale, reference_sums(f, p, k, true, true));
  }
  ASSERT_GT(host[0]->diagnostics().contacts, 20) << "the test needs contacts for the virial";
  const int q = f.sampling.grid.quantities();
  const double bound_per_scale = 2.0 * double(terms) * std::ldexp(1.0, -53);
  for (std::size_t m = 0; m < host.size(); ++m) {
    const std::string name = m == 0 ? "automatic" : "scatter_view";
    test::expect_bitwise_identical(host[m]->particles(), device[m]->particles());
    for (const bool profile : {false, true}) {
      const std::string what = name + (profile ? " profile" : " grid");
      const std::vector<double> a = host[m]->field_sums(profile),
                                b = device[m]->field_sums(profile);
      const std::vector<double>& scale = profile ? profile_scale : grid_scale;
      ASSERT_EQ(a.size(), b.size()) << what;
      ASSERT_EQ(a.size(), scale.size()) << what;
      std::size_t miscounted = 0, beyond = 0, differing = 0;
      double worst = 0;  // the largest difference, as a fraction of its bound
      for (std::size_t k = 0; k < a.size(); ++k) {
        const int quantity = int(k % std::size_t(q));
        if (quantity < BinLayout::per_species * f.sampling.grid.n_species &&
            quantity % BinLayout::per_species == 0) {
          miscounted += a[k] != b[k];
        } else {
          // The reference's virial is that of the analytic Hertz force: 1e-9 above the
          // kernel's magnitudes covers their round-off.
          const double bound = bound_per_scale * scale[k] * (1 + 1e-9);
          beyond += std::abs(a[k] - b[k]) > bound;
          differing += a[k] != b[k];
          if (a[k] != b[k]) worst = std::max(worst, std::abs(a[k] - b[k]) / bound);
        }
      }
      EXPECT_EQ(miscounted, 0u) << what << ": counts differ";
      EXPECT_EQ(beyond, 0u) << what << ": sums beyond the summation bound";
      std::cout << "[ info ] " << what << ": " << differing << " of " << a.size()
                << " sums differ, the largest by " << worst << " of its bound\n";
    }
  }
}
