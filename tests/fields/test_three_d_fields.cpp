// Field sampling in 3-D (docs/fields.md, "Three dimensions"): a gas of elastic steel spheres
// in a periodic cube, with contacts, is sampled through the solver's device accumulation
// (sample_fields) into 2 x 2 columns through the whole cube, and compute_bin_fields must
// give in every column what this test works out from the particles themselves:
//   - n per unit volume and the volume fraction phi = n pi d^3 / 6;
//   - the mass-averaged velocity, its z component included;
//   - T = sum m |c - u|^2 / (3 N), the z fluctuation included;
//   - the pressure tr(P_kin + P_col) / 3, P_col from the touching pairs' Hertz forces
//     F = (4/3) Y* sqrt(R*) dn^(3/2) (elastic: no damping; softened: Y* / 1e4;
//     docs/contact_model.md), each
//     particle carrying 1/2 r_ij . F_ij of its contacts (the virial's trace, W_zz included).
// Tolerances: 1e-9 relative for the sums of the sampled moments (rounding of sums of
// ~50 terms), 1e-6 for the pressure (the overlaps, ~1e-3 d, lose digits in r_ij).
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <vector>

#include "analysis/bin_fields.hpp"
#include "analysis/field_physics.hpp"
#include "cases/gas/homogeneous_gas.hpp"
#include "core/bin_sums.hpp"
#include "core/solver.hpp"
#include "kernels/models/hertz.hpp"

namespace granshock {
namespace {

TEST(ThreeDimensionalFields, ColumnsGiveTheGasStateWorkedOutFromTheParticles) {
  SolverSetup setup;
  setup.dim = 3;
  setup.species = {{"steel", steel(), 1e-3}};
  setup.contacts = ContactSettings::uniform(1, 1.0, 0.0);
  // Softened 1e4 times (moduli / 1e4): contacts last 40 times longer, so that a few
  // hundred pairs touch at any instant.
  setup.contacts.softening = 1e4;
  const GasSpec spec{216, 0.25, 1.0, 5};
  size_periodic_box(setup, spec);
  const HostParticles gas = make_homogeneous_gas(setup, spec);
  const Species& sp = setup.species[0];
  const double m = sp.mass_kg(), d = sp.diameter_m, length = setup.box.length(0);
  setup.dt = HertzModel::collision_time(setup.pair(0, 0), ContactOptions{}, 4.0) / 50;
  auto solver = make_solver(setup, gas.size());
  solver->set_particles(gas);
  solver->advance(std::lround(1e-3 / setup.dt));  // 1 mm of flight: the lattice melts
  solver->rebuild_lists();  // wraps every centre into the periodic cube, as the bins expect

  FieldSampling sampling;
  BinLayout& g = sampling.grid;
  g.n_species = 1;
  g.nx = g.ny = 2;
  g.dx = g.dy = 0.5 * length;
  g.blocks = 1;
  g.dim = 3;
  g.depth = length;
  solver->configure_sampling(sampling);
  solver->sample_fields(0);

  BinSums sums;
  sums.n_species = 1;
  sums.nx = sums.ny = 2;
  sums.dx = sums.dy = g.dx;
  sums.dim = 3;
  sums.depth = length;
  sums.samples = {1.0};
  sums.sums = solver->field_sums(false);
  sums.check_consistent();

  FieldPhysics phys;
  phys.dim = 3;
  phys.species = {"steel"};
  phys.mass = {m};
  phys.diameter = {d};
  phys.restitution = 1.0;
  phys.inflow_speed = 1.0;
  const BinFields f = compute_bin_fields(sums, phys);

  // The same quantities from the particles.
  const HostParticles p = solver->particles();
  std::map<int, std::size_t> row;
  for (std::size_t i = 0; i < p.size(); ++i) row[p.id[i]] = i;
  const double nu = sp.material.poisson_ratio, young = sp.material.youngs_modulus_pa;
  const double hertz = 4.0 / 3.0 * (1 / (2 * (1 - nu * nu) / (young / 1e4))) * std::sqrt(d / 4);
  std::vector<double> trace_w(p.size(), 0.0);
  long touching = 0;
  for (const auto& [a, b] : solver->contact_pairs()) {
    double r2 = 0;
    for (int k = 0; k < 3; ++k) {
      double dx = p.position[row.at(a)][k] - p.position[row.at(b)][k];
      dx -= length * std::round(dx / length);
      r2 += dx * dx;
    }
    const double r = std::sqrt(r2), dn = d - r;
    if (!(dn > 0)) continue;
    // r_ij . F_ij / 2 for each of the two.
    const double half = 0.5 * r * hertz * dn * std::sqrt(dn);
    trace_w[row.at(a)] += half;
    trace_w[row.at(b)] += half;
    ++touching;
  }
  ASSERT_GT(touching, 10) << "the test needs contacts for the virial (dt " << setup.dt << " s, "
                          << solver->steps_done() << " steps, " << solver->diagnostics().contacts
                          << " contacts)";

  const double inv = 1.0 / g.dx, volume = g.dx * g.dy * length;
  for (std::size_t i = 0; i < p.size(); ++i)
    for (int k = 0; k < 3; ++k)
      ASSERT_TRUE(p.position[i][k] >= 0 && p.position[i][k] < length) << "particle " << i;
  for (int bin = 0; bin < 4; ++bin) {
    SCOPED_TRACE("bin " + std::to_string(bin));
    std::vector<std::size_t> in;
    for (std::size_t i = 0; i < p.size(); ++i) {
      const int ix = int(p.position[i][0] * inv), iy = int(p.position[i][1] * inv);
      if (iy * 2 + ix == bin) in.push_back(i);
    }
    ASSERT_GT(in.size(), 20u);
    const double count = double(in.size());
    double u[3] = {0, 0, 0};
    for (std::size_t i : in)
      for (int k = 0; k < 3; ++k) u[k] += p.velocity[i][k] / count;
    double fluct = 0, virial = 0;
    for (std::size_t i : in) {
      for (int k = 0; k < 3; ++k) fluct += m * std::pow(p.velocity[i][k] - u[k], 2);
      virial += trace_w[i];
    }
    const double n = count / volume, temperature = fluct / (3 * count);
    const std::size_t k = std::size_t(bin);
    EXPECT_NEAR(f.n[k], n, 1e-12 * n);
    EXPECT_NEAR(f.phi[k], n * M_PI * d * d * d / 6, 1e-12);
    EXPECT_NEAR(f.ux[k], u[0], 1e-9);
    EXPECT_NEAR(f.uy[k], u[1], 1e-9);
    EXPECT_NEAR(f.temperature[k], temperature, 1e-9 * temperature);
    const double pressure = (fluct + virial) / (3 * volume);
    EXPECT_NEAR(f.pressure[k], pressure, 1e-6 * pressure);
    EXPECT_GT(virial, 0.05 * fluct) << "the collisional part must matter to this check";
  }
}

}  // namespace
}  // namespace granshock
