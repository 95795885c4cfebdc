// docs/fields.md, "The fitted front": a tanh step averaged over bins of 0.5, 1, 2 and 3 d,
// with noise that differs from block to block, gives back its centre y_s and thickness w
// within two block errors at every bin size, and the 3 d and 0.5 d estimates agree within
// two errors, where the half-rise of the same bins does not (it interpolates between bin
// centres, and a 3 d bin's average is not the profile at its centre); the fit stops at the end of
// the profile's top, so a cooled cap at the wall does not move the front; and the fitted fronts
// reach the detachment length with a thickness and its error.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "analysis/block_error.hpp"
#include "analysis/detachment.hpp"
#include "analysis/front_crossing.hpp"
#include "analysis/shock_profile_fit.hpp"
#include "synthetic_run.hpp"

using namespace granshock;

namespace {

constexpr double kD = 1e-3;
constexpr double kFace = 110 * kD;  // the obstacle's face: bins are laid from it upstream
constexpr double kStart = 3 * kD;   // the search start (beyond the insertion strip)
const ShockProfile kTrue{105.3 * kD, 1.2 * kD, 0.1, 0.6};  // y_s, w, low, high
constexpr int kBlocks = 10;
constexpr double kNoise = 0.02;  // per block, in a 0.5 d bin; a bin of h has 0.5 d / h of it

struct Line {
  std::vector<double> y;  // bin centres
  double dy = 0;
};

// Bins of height h from the face upstream to the search start.
Line bins_of(double h) {
  Line line;
  line.dy = h;
  const int n = static_cast<int>(std::floor((kFace - kStart) / h + 1e-9));
  for (int k = n - 1; k >= 0; --k) line.y.push_back(kFace - (k + 0.5) * h);
  return line;
}

// The step at a point, written out here so that the test does not take the model from the
// code under test.
double step_at(double y) {
  return kTrue.low + (kTrue.high - kTrue.low) * 0.5 * (1 + std::tanh((y - kTrue.y_s) / kTrue.w));
}

// The bin averages of a profile, by the midpoint rule on 4000 points per bin.
template <class Profile>
std::vector<double> averages(const Line& line, Profile profile) {
  constexpr int kSub = 4000;
  std::vector<double> v;
  for (double c : line.y) {
    double sum = 0;
    for (int j = 0; j < kSub; ++j) sum += profile(c + ((j + 0.5) / kSub - 0.5) * line.dy) / kSub;
    v.push_back(sum);
  }
  return v;
}

struct Estimate {
  double y_s = 0, w = 0, y_s_err = 0, w_err = 0;  // of the pooled blocks
  double half_rise = 0, half_rise_err = 0;        // the half-rise on the same bins
  bool found = false;
};

// Blocks of the same exact bin averages with independent noise: fits of the pooled mean,
// errors from the blocks' own fits (block_error.hpp), as the detachment length has them.
Estimate measure(double h, unsigned seed) {
  const Line line = bins_of(h);
  const std::vector<double> exact = averages(line, step_at);
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> noise(0.0, kNoise * std::sqrt(0.5 * kD / h));
  std::vector<double> pooled(exact.size(), 0.0), ys, ws, rises;
  const int n = static_cast<int>(exact.size());
  for (int b = 0; b < kBlocks; ++b) {
    std::vector<double> block = exact;
    for (std::size_t i = 0; i < block.size(); ++i) {
      block[i] += noise(rng);
      pooled[i] += block[i] / kBlocks;
    }
    const ShockProfileFit fit = fit_shock_profile(block, line.y, h, 0, n, 1.5);
    if (fit.found) {
      ys.push_back(fit.profile.y_s);
      ws.push_back(fit.profile.w);
    }
    const FrontCrossing rise = find_largest_rise(block, line.y, 0, n, ThresholdRule{});
    if (rise.found) rises.push_back(rise.y_threshold);
  }
  Estimate e;
  const ShockProfileFit fit = fit_shock_profile(pooled, line.y, h, 0, n, 1.5);
  const FrontCrossing rise = find_largest_rise(pooled, line.y, 0, n, ThresholdRule{});
  e.found = fit.found && rise.found && ys.size() == kBlocks && rises.size() == kBlocks;
  e.y_s = fit.profile.y_s;
  e.w = fit.profile.w;
  e.y_s_err = block_standard_error(ys);
  e.w_err = block_standard_error(ws);
  e.half_rise = rise.y_threshold;
  e.half_rise_err = block_standard_error(rises);
  return e;
}

}  // namespace

TEST(FittedFront, RecoversAStepFromItsBinAveragesAtEveryBinSize) {
  for (double h_d : {0.5, 1.0, 2.0, 3.0}) {
    const Line line = bins_of(h_d * kD);
    const std::vector<double> v = averages(line, step_at);
    const ShockProfileFit fit =
        fit_shock_profile(v, line.y, line.dy, 0, static_cast<int>(v.size()), 1.5);
    ASSERT_TRUE(fit.found) << h_d << " d: " << fit.why;
    EXPECT_NEAR(fit.profile.y_s, kTrue.y_s, 1e-4 * kD) << h_d << " d";
    EXPECT_NEAR(fit.profile.w, kTrue.w, 1e-4 * kD) << h_d << " d";
    EXPECT_NEAR(fit.profile.low, kTrue.low, 1e-6) << h_d << " d";
    EXPECT_NEAR(fit.profile.high, kTrue.high, 1e-6) << h_d << " d";
    // The 20 d window ahead of the top that the analysis fits gives the same step.
    const ShockProfileFit near =
        fit_shock_profile(v, line.y, line.dy, 0, static_cast<int>(v.size()), 1.5, 20 * kD);
    ASSERT_TRUE(near.found) << h_d << " d: " << near.why;
    EXPECT_LT(near.points, fit.points);
    EXPECT_NEAR(near.profile.y_s, kTrue.y_s, 1e-4 * kD) << h_d << " d";
    EXPECT_NEAR(near.profile.w, kTrue.w, 1e-4 * kD) << h_d << " d";
    // The model's own bin average is that integral.
    for (std::size_t i = 0; i < v.size(); ++i)
      ASSERT_NEAR(bin_average(kTrue, line.y[i] - 0.5 * line.dy, line.y[i] + 0.5 * line.dy), v[i],
                  1e-8)
          << h_d << " d, bin " << i;
  }
}

TEST(FittedFront, NoisyBlocksGiveTheFrontWithinItsErrorsAndTheSameAtEveryBinSize) {
  const Estimate fine = measure(0.5 * kD, 11);
  for (double h_d : {0.5, 1.0, 2.0, 3.0}) {
    const Estimate e = measure(h_d * kD, 11);
    ASSERT_TRUE(e.found) << h_d << " d";
    ASSERT_GT(e.y_s_err, 0);
    ASSERT_GT(e.w_err, 0);
    EXPECT_LT(std::abs(e.y_s - kTrue.y_s), 2 * e.y_s_err)
        << h_d << " d: y_s " << e.y_s / kD << " d +- " << e.y_s_err / kD;
    EXPECT_LT(std::abs(e.w - kTrue.w), 2 * e.w_err)
        << h_d << " d: w " << e.w / kD << " d +- " << e.w_err / kD;
    // Two cuts of the same flow: within two of the larger error (as the convergence table).
    EXPECT_LT(std::abs(e.y_s - fine.y_s), 2 * std::max(e.y_s_err, fine.y_s_err)) << h_d << " d";
    EXPECT_LT(std::abs(e.w - fine.w), 2 * std::max(e.w_err, fine.w_err)) << h_d << " d";
  }
}

// The defect the fit removes: the half-rise interpolates linearly between bin averages, which
// moves it by a fraction of a bin, more than its error, on 3 d bins.
TEST(FittedFront, TheHalfRiseOfTheSameBinsMovesWithTheBinSize) {
  const Estimate fine = measure(0.5 * kD, 11), coarse = measure(3 * kD, 11);
  ASSERT_TRUE(fine.found && coarse.found);
  const double tolerance = 2 * std::max(fine.half_rise_err, coarse.half_rise_err);
  EXPECT_GT(std::abs(coarse.half_rise - fine.half_rise), tolerance)
      << "half-rise " << fine.half_rise / kD << " d (0.5 d bins), " << coarse.half_rise / kD
      << " d (3 d bins), two errors " << tolerance / kD << " d";
  EXPECT_GT(std::abs(coarse.half_rise - kTrue.y_s), 2 * coarse.half_rise_err);
}

// T falls again in the compacted cap at the wall: from 2.5 d before the face to 0.2 at it.
// The fit ends with the profile's top, so the front and its thickness stay where they are
// (within 0.1 d and 10 %, the part of the fall inside the top's last tenth) on rows fine
// enough to see the top (0.5 and 1 d).
TEST(FittedFront, StopsAtTheEndOfTheTopSoTheCapAtTheWallDoesNotMoveIt) {
  const double cap = kFace - 2.5 * kD;
  auto capped = [&](double y) {
    const double v = step_at(y);
    return y > cap ? v - (kTrue.high - 0.2) * (y - cap) / (kFace - cap) : v;
  };
  for (double h_d : {0.5, 1.0}) {
    const Line line = bins_of(h_d * kD);
    const std::vector<double> v = averages(line, capped);
    const ShockProfileFit fit =
        fit_shock_profile(v, line.y, line.dy, 0, static_cast<int>(v.size()), 1.5);
    ASSERT_TRUE(fit.found) << h_d << " d: " << fit.why;
    EXPECT_LT(fit.y_end, cap + 1.01 * kD) << h_d << " d";
    EXPECT_NEAR(fit.profile.y_s, kTrue.y_s, 0.1 * kD) << h_d << " d";
    EXPECT_NEAR(fit.profile.w, kTrue.w, 0.1 * kTrue.w) << h_d << " d";
  }
}

// Too few bins up to the top: no front, and the reason says so.
TEST(FittedFront, TooFewBinsIsNoFrontWithAReason) {
  const std::vector<double> y = {0.5 * kD, 1.5 * kD, 2.5 * kD, 3.5 * kD, 4.5 * kD};
  const ShockProfileFit fit = fit_shock_profile({0.1, 0.1, 0.6, 0.4, 0.2}, y, kD, 0, 5, 1.5);
  EXPECT_FALSE(fit.found);
  EXPECT_NE(fit.why.find("holds 3 bins"), std::string::npos) << fit.why;
}

// Through the detachment length: a stagnation line (cylinder of 12 d, face at 54 d) whose
// blocks hold a phi step (0.1 to 0.4, w = 1 d) at 47.6 d moved by -0.2 ... +0.2 d from block
// to block. The density fit finds the mean front and its thickness, and both get an error
// from the blocks; the definitions that fit nothing have no thickness.
TEST(FittedFront, GivesTheDetachmentLengthAndTheThicknessWithErrors) {
  const FieldPhysics phys = test::physics_of(test::bow_shock_scene(12));
  const double surface = 54 * kD, y_s = 47.6 * kD, w = 1.0 * kD, dy = 0.5 * kD;
  const int ny = static_cast<int>(std::lround(surface / dy)), blocks = 10;
  const double t_cold = test::temperature_for_mach(phys, 0.1, 1.0, 6.0);
  const test::BinState pre = test::mixture_state(phys, 0.1, t_cold, 0, 1.0);
  const test::BinState post = test::mixture_state(phys, 0.4, 20 * t_cold, 0, 0.1);
  BinSums profile = test::empty_sums(1, ny, blocks, 28 * kD, 0, 4 * kD, dy);
  const double shifts[] = {-0.2, 0.1, 0.2, -0.1, 0.0, 0.15, -0.15, 0.05, -0.05, 0.0};
  for (int b = 0; b < blocks; ++b) {
    profile.samples[static_cast<std::size_t>(b)] = 400;
    const ShockProfile step{y_s + shifts[b] * kD, w, 0, 1};
    for (int iy = 0; iy < ny; ++iy) {
      const double g = bin_average(step, iy * dy, (iy + 1) * dy);  // the share behind the front
      test::add_state(profile, b, iy, 0, pre, phys, 400, 1 - g);
      test::add_state(profile, b, iy, 0, post, phys, 400, g);
    }
  }
  DetachmentSearch search;
  search.y_begin = 10 * kD;
  const Detachments all = measure_detachments(profile, phys, {0.1}, search);
  const Detachment& fit = of(all, FrontDefinition::density_fit);
  ASSERT_TRUE(fit.found) << fit.reason;
  // The pooled profile is the mean of ten steps 0.2 d apart at most: its centre is theirs.
  EXPECT_NEAR(fit.y_shock, y_s, 0.02 * kD);
  EXPECT_NEAR(fit.delta, surface - y_s, 0.02 * kD);
  EXPECT_NEAR(fit.width, w, 0.05 * w);
  EXPECT_NEAR(fit.peak, 0.4, 0.01);
  EXPECT_NEAR(fit.low, 0.1, 0.01);
  EXPECT_EQ(fit.blocks_used, blocks);
  EXPECT_GT(fit.delta_err, 0.02 * kD);  // the blocks' spread, 0.13 d / sqrt(10) at least
  EXPECT_LT(fit.delta_err, 0.3 * kD);
  EXPECT_TRUE(std::isfinite(fit.width_err)) << fit.err_reason;
  EXPECT_GE(fit.width_err, 0);
  EXPECT_LT(fit.width_err, 0.1 * w);
  EXPECT_GT(fit.fit_end, y_s);
  EXPECT_LE(fit.fit_end, surface);
  EXPECT_TRUE(std::isnan(of(all, FrontDefinition::density_threshold).width));
  EXPECT_TRUE(std::isnan(of(all, FrontDefinition::temperature_jump).width_err));
}

// Why the fitted T front is not the primary one (docs/fields.md, "The fitted front"): a
// bin's phi is the mean of phi over the bin, a bin's T is not. The same stagnation line cut
// into 3 d rows: the phi fit stays on the step, while the T fit moves upstream, since a
// 3 d bin that straddles the front counts the change of the mean velocity across it (1 to
// 0.1 m/s) as temperature.
TEST(FittedFront, ABinsTemperatureIsNotTheMeanOfTheProfileSoOnlyPhiFitsTheSameOnCoarseRows) {
  const FieldPhysics phys = test::physics_of(test::bow_shock_scene(12));
  const double surface = 54 * kD, y_s = 47.6 * kD, w = 1.0 * kD, dy = 0.5 * kD;
  const int ny = static_cast<int>(std::lround(surface / dy));
  const double t_cold = test::temperature_for_mach(phys, 0.1, 1.0, 6.0);
  const test::BinState pre = test::mixture_state(phys, 0.1, t_cold, 0, 1.0);
  const test::BinState post = test::mixture_state(phys, 0.4, 20 * t_cold, 0, 0.1);
  BinSums profile = test::empty_sums(1, ny, 1, 28 * kD, 0, 4 * kD, dy);
  profile.samples[0] = 400;
  const ShockProfile step{y_s, w, 0, 1};
  for (int iy = 0; iy < ny; ++iy) {
    const double g = bin_average(step, iy * dy, (iy + 1) * dy);
    test::add_state(profile, 0, iy, 0, pre, phys, 400, 1 - g);
    test::add_state(profile, 0, iy, 0, post, phys, 400, g);
  }
  DetachmentSearch search;
  search.y_begin = 10 * kD;
  search.bootstrap_resamples = 0;
  const Detachments fine = measure_detachments(profile, phys, {0.1}, search);
  const Detachments coarse = measure_detachments(profile.merged_rows(6, ny), phys, {0.1}, search);
  for (const Detachments* all : {&fine, &coarse}) {
    ASSERT_TRUE(of(*all, FrontDefinition::density_fit).found);
    ASSERT_TRUE(of(*all, FrontDefinition::temperature_fit).found)
        << of(*all, FrontDefinition::temperature_fit).reason;
  }
  const double phi_fine = of(fine, FrontDefinition::density_fit).y_shock,
               phi_coarse = of(coarse, FrontDefinition::density_fit).y_shock,
               t_fine = of(fine, FrontDefinition::temperature_fit).y_shock,
               t_coarse = of(coarse, FrontDefinition::temperature_fit).y_shock;
  EXPECT_NEAR(phi_fine, y_s, 1e-3 * kD);
  EXPECT_NEAR(phi_coarse, y_s, 1e-3 * kD);
  // Measured: 46.16 d on 0.5 d rows, 44.97 d on 3 d rows.
  EXPECT_LT(t_coarse, t_fine - 0.8 * kD)
      << "T fit " << t_fine / kD << " d on 0.5 d rows, " << t_coarse / kD << " d on 3 d rows";
}
