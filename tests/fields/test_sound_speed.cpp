// docs/fields.md: the sound speed of the paper's eq. 6 against a hand
// calculation at phi = 0.1, 0.3, 0.5 for e = 0.5 in 2-D, for both masses of eq. 7, through
// the kinetic-theory functions and through the field computation of a bin.
#include <gtest/gtest.h>

#include <cmath>

#include "analysis/bin_fields.hpp"
#include "core/kinetic_theory.hpp"
#include "synthetic_run.hpp"

using namespace granshock;

namespace {

// The hand calculation (2-D, e = 0.5, so F = 1 + 1.5 phi g and 2/Dim = 1):
//   phi = 0.1: g = 15.3/12.96 = 1.18055556, F = 1.17708333, g' = 24.3/11.664 = 2.08333333,
//              F' = 1.5 (g + 0.1 g') = 2.08333333, K = (1 + F + 0.1 F'/F) F = 2.77094184
//   phi = 0.3: g = 13.9/7.84 = 1.77295918, F = 1.79783163, g' = 22.9/5.488 = 4.17274052,
//              F' = 4.53717201, K = 6.39118182
//   phi = 0.5: g = 12.5/4 = 3.125, F = 3.34375, g' = 21.5/2 = 10.75, F' = 12.75,
//              K = (4.34375 + 0.5 * 12.75 / 3.34375) 3.34375 = 20.8994141
// Masses: m_steel = 7850 pi (1e-3)^3 / 6 = 4.11025039e-6 kg, m_al = m_steel / 2.907 =
// 1.41391482e-6 kg; equimolar: mixture mean 2.76208261e-6 kg, paper's sum 5.52416521e-6 kg.
// With T = 2e-7 J, a = sqrt(T K / m):
struct HandValue {
  double phi, factor, a_mixture_mean, a_paper_sum;
};
constexpr HandValue kHand[] = {
    {0.1, 2.7709418403, 0.4479302284, 0.3167345020},
    {0.3, 6.3911818155, 0.6802792945, 0.4810301022},
    {0.5, 20.8994140625, 1.2301660057, 0.8698587246},
};
constexpr double kTemperature = 2e-7;
constexpr double kMassSteel = 4.1102503884e-06, kMassAluminium = 1.4139148223e-06;

}  // namespace

TEST(SoundSpeed, MatchesHandCalculationForBothMassDefinitions) {
  const std::vector<double> masses{kMassSteel, kMassAluminium}, xi{0.5, 0.5};
  for (const HandValue& h : kHand) {
    EXPECT_NEAR(sound_speed_factor(h.phi, 0.5, 2), h.factor, 1e-9 * h.factor) << "phi " << h.phi;
    const double m_mean = sound_speed_mass(MassDefinition::mixture_mean, masses, xi);
    const double m_sum = sound_speed_mass(MassDefinition::paper_sum, masses, xi);
    EXPECT_NEAR(m_mean, 2.7620826054e-06, 1e-15);
    EXPECT_NEAR(m_sum, 5.5241652108e-06, 1e-15);
    EXPECT_NEAR(sound_speed(kTemperature, m_mean, h.phi, 0.5, 2), h.a_mixture_mean, 1e-9)
        << "phi " << h.phi;
    EXPECT_NEAR(sound_speed(kTemperature, m_sum, h.phi, 0.5, 2), h.a_paper_sum, 1e-9)
        << "phi " << h.phi;
  }
}

TEST(SoundSpeed, FieldComputationUsesBothMassDefinitions) {
  const FieldPhysics phys = test::physics_of(test::bow_shock_scene());
  ASSERT_NEAR(phys.mass[0], kMassSteel, 1e-15);
  ASSERT_NEAR(phys.mass[1], kMassAluminium, 1e-15);
  ASSERT_DOUBLE_EQ(phys.restitution, 0.5);
  // One row of three bins at phi = 0.1, 0.3, 0.5, equimolar, T = 2e-7 J, u = (0, 1) m/s.
  BinSums s = test::empty_sums(3, 1, 1, 0, 0, 3e-3, 3e-3);
  s.samples = {1000};
  for (int ix = 0; ix < 3; ++ix)
    test::add_state(s, 0, 0, ix, test::mixture_state(phys, kHand[ix].phi, kTemperature, 0, 1), phys,
                    1000);
  const BinFields f = compute_bin_fields(s, phys);
  for (int ix = 0; ix < 3; ++ix) {
    const HandValue& h = kHand[ix];
    ASSERT_EQ(f.masked[static_cast<std::size_t>(ix)], 0);
    EXPECT_NEAR(f.phi[static_cast<std::size_t>(ix)], h.phi, 1e-12);
    EXPECT_NEAR(f.sound_speed_mixture_mean[static_cast<std::size_t>(ix)], h.a_mixture_mean, 1e-8);
    EXPECT_NEAR(f.sound_speed_paper_sum[static_cast<std::size_t>(ix)], h.a_paper_sum, 1e-8);
    EXPECT_NEAR(f.mach_mixture_mean[static_cast<std::size_t>(ix)], 1.0 / h.a_mixture_mean, 1e-7);
    EXPECT_NEAR(f.mach_paper_sum[static_cast<std::size_t>(ix)], 1.0 / h.a_paper_sum, 1e-7);
    // The scene's default (numerics.mass_definition = mixture_mean) is the Ma field.
    EXPECT_EQ(f.mach[static_cast<std::size_t>(ix)],
              f.mach_mixture_mean[static_cast<std::size_t>(ix)]);
  }
}

namespace {

// The Carnahan-Starling equation of state of elastic hard spheres (Carnahan & Starling
// 1969): p / (n T) = Z(phi) = (1 + phi + phi^2 - phi^3) / (1 - phi)^3.
double carnahan_starling(double phi) {
  return (1 + phi + phi * phi - phi * phi * phi) / std::pow(1 - phi, 3);
}

}  // namespace

// In 3-D the contact value is Carnahan-Starling's, so the elastic gas's pressure factor is
// the CS compressibility, written independently above.
TEST(SoundSpeed, ThreeDimensionalPressureIsCarnahanStarling) {
  for (const double phi : {0.01, 0.1, 0.2, 0.3, 0.4, 0.5})
    EXPECT_NEAR(pressure_factor(phi, 1.0, 3), carnahan_starling(phi),
                1e-12 * carnahan_starling(phi))
        << "phi " << phi;
}

// The adiabatic sound speed of a hard-particle gas (no potential energy, c_v = Dim/2 per
// particle) from thermodynamics: m a^2 / T = Z + phi dZ/dphi + (2/Dim) Z^2, with dZ/dphi by
// central differences of the CS formula; against eq. 6's factor for elastic spheres.
TEST(SoundSpeed, ThreeDimensionalSoundSpeedFromTheCarnahanStarlingState) {
  for (const double phi : {0.05, 0.1, 0.3, 0.5}) {
    const double h = 1e-5;
    const double z = carnahan_starling(phi);
    const double slope = (carnahan_starling(phi + h) - carnahan_starling(phi - h)) / (2 * h);
    const double expected = z + phi * slope + 2.0 / 3.0 * z * z;
    EXPECT_NEAR(sound_speed_factor(phi, 1.0, 3), expected, 1e-8 * expected) << "phi " << phi;
  }
}

// g's slope against central differences of g, for disks and spheres; other dimensions are
// refused.
TEST(SoundSpeed, ContactValueSlopesAndDimensions) {
  for (const int dim : {2, 3})
    for (const double phi : {0.05, 0.3, 0.6}) {
      const double h = 1e-6;
      const double numeric =
          (radial_distribution(phi + h, dim) - radial_distribution(phi - h, dim)) / (2 * h);
      EXPECT_NEAR(radial_distribution_slope(phi, dim), numeric, 1e-7 * numeric)
          << "dim " << dim << ", phi " << phi;
    }
  EXPECT_DOUBLE_EQ(radial_distribution(0.0, 2), 1.0);
  EXPECT_DOUBLE_EQ(radial_distribution(0.0, 3), 1.0);
  EXPECT_THROW(radial_distribution(0.1, 1), std::invalid_argument);
}
