// Where the benchmark gas starts (cases/gas/homogeneous_gas.hpp). Random sequential
// addition places every particle of the lattice's box without an overlap, the same for
// the same seed, and gives the pairs of a random gas within a neighbour list's reach,
// where the jittered lattice of a dilute gas has few; it refuses a fraction past
// jamming with one message.
#include <gtest/gtest.h>

#include <cmath>

#include "cases/gas/homogeneous_gas.hpp"
#include "core/user_error.hpp"

using namespace granshock;

namespace {

// Pairs closer than `reach` (minimum image in the periodic square), and the closest.
struct PairCount {
  long within = 0;
  double closest = 1e9;
};
PairCount pairs_within(const HostParticles& p, double length, double reach) {
  PairCount c;
  for (std::size_t i = 0; i < p.size(); ++i)
    for (std::size_t j = i + 1; j < p.size(); ++j) {
      double r2 = 0;
      for (int d = 0; d < 2; ++d) {
        double dx = p.position[i][d] - p.position[j][d];
        dx -= length * std::round(dx / length);
        r2 += dx * dx;
      }
      c.closest = std::min(c.closest, std::sqrt(r2));
      if (r2 < reach * reach) ++c.within;
    }
  return c;
}

HostParticles gas(GasPlacement placement, double phi, std::uint64_t seed = 1) {
  SolverSetup setup = paper_mixture(0.5);
  GasSpec spec;
  spec.particles = 4096;
  spec.area_fraction = phi;
  spec.sigma_m_per_s = 0.15;
  spec.seed = seed;
  spec.placement = placement;
  size_periodic_box(setup, spec);
  return make_homogeneous_gas(setup, spec);
}

}  // namespace

// At phi = 0.1 (number density n = 0.1 / (pi d^2 / 4)) an uncorrelated gas outside contact
// has n pi ((1.3 d)^2 - d^2) / 2 pairs per particle between d and the list's reach 1.3 d
// (the default skin 0.3 d); hard disks' pair correlation lifts that by about
// g(d) = (1 - 7 phi / 16) / (1 - phi)^2 = 1.18 at contact, falling to 1 farther out, and
// random sequential addition differs from equilibrium only at second order in phi. So the
// ratio lies in [1.0, 1.3] (the count's own scatter over 4096 particles is about 4 %).
TEST(GasPlacement, RandomAdditionGivesTheNeighboursOfARandomGas) {
  const double d = 1e-3, phi = 0.1;
  const double length = std::sqrt(4096 * M_PI * d * d / 4 / phi);
  const HostParticles random = gas(GasPlacement::random, phi);
  ASSERT_EQ(random.size(), 4096u);  // the lattice's count, 64^2
  const PairCount r = pairs_within(random, length, 1.3 * d);
  EXPECT_GE(r.closest, d * (1 - 1e-12)) << "two particles overlap";
  const double uncorrelated = 4096 * (phi / (M_PI * d * d / 4)) * M_PI * (1.69 - 1.0) * d * d / 2;
  EXPECT_GE(double(r.within) / uncorrelated, 1.0);
  EXPECT_LE(double(r.within) / uncorrelated, 1.3);
  const PairCount l = pairs_within(gas(GasPlacement::lattice, phi), length, 1.3 * d);
  // Lattice sites 2.8 d apart, each centre jittered by up to 0.9 d along each axis: few
  // pairs come within 1.3 d (51 of 4096 particles with this seed).
  EXPECT_LT(5 * l.within, r.within) << "the lattice start has as many pairs as the random one";
}

TEST(GasPlacement, TheSameSeedPlacesTheSameGas) {
  const HostParticles a = gas(GasPlacement::random, 0.3), b = gas(GasPlacement::random, 0.3);
  const HostParticles c = gas(GasPlacement::random, 0.3, 2);
  EXPECT_EQ(a.position, b.position);
  EXPECT_EQ(a.velocity, b.velocity);
  EXPECT_NE(a.position, c.position);
}

TEST(GasPlacement, PastJammingIsRefused) {
  try {
    gas(GasPlacement::random, 0.6);
    FAIL() << "phi 0.6 cannot be reached by random addition";
  } catch (const UserError& e) {
    EXPECT_NE(std::string(e.what()).find("too dense for random placement"), std::string::npos)
        << e.what();
  }
}
