// The four definitions of the shock front on the stagnation line (analysis/stagnation_line.hpp,
// docs/fields.md section 6), their error bars and the convergence table, on synthetic
// profiles whose answers are known: a layered stagnation line where the temperature jumps,
// the flow turns subsonic and the density jumps at three separate, chosen places, cut by
// rows aligned with those places and by rows offset from them.
#include <gtest/gtest.h>

#include <cmath>

#include "analysis/detachment.hpp"
#include "analysis/detachment_convergence.hpp"
#include "analysis/field_analysis.hpp"
#include "analysis/fields_output.hpp"
#include "io/scene_file.hpp"
#include "synthetic_run.hpp"

using namespace granshock;

namespace {

constexpr double kD = 1e-3;
const std::string kScene = test::bow_shock_scene(12);  // cylinder of 12 d at (30 d, 60 d)
constexpr double kSurface = 54 * kD;
// Upstream to downstream: the cold inflow (Ma 6, phi 0.1), the hot layer behind the
// temperature jump (Ma 1.5, phi 0.15), the subsonic layer behind the sonic point (Ma 0.5,
// phi 0.2) and the dense cap behind the density jump (Ma 0.2, phi 0.45).
constexpr double kTemperatureJump = kSurface - 9 * kD, kSonic = kSurface - 6.5 * kD,
                 kDensityJump = kSurface - 3.5 * kD;

struct Layers {
  test::BinState cold, hot, subsonic, dense;
  double phi_up, t_up;
};

Layers layers(const FieldPhysics& phys) {
  Layers l;
  l.phi_up = 0.1;
  l.t_up = test::temperature_for_mach(phys, 0.1, 1.0, 6.0);
  l.cold = test::mixture_state(phys, 0.1, l.t_up, 0, 1.0);
  l.hot = test::mixture_state(phys, 0.15, test::temperature_for_mach(phys, 0.15, 0.9, 1.5), 0, 0.9);
  l.subsonic =
      test::mixture_state(phys, 0.2, test::temperature_for_mach(phys, 0.2, 0.2, 0.5), 0, 0.2);
  l.dense =
      test::mixture_state(phys, 0.45, test::temperature_for_mach(phys, 0.45, 0.05, 0.2), 0, 0.05);
  return l;
}

struct Layer {
  double end;  // the layer's downstream edge
  const test::BinState* state;
};

// A profile of nx columns of width dx on the axis (x = 30 d), rows of dy from y0 to the
// surface, every block filled with the layers (upstream to downstream, shifted by shift[b]
// along y), each bin with the fractions of the layers it holds.
BinSums profile_of_layers(const FieldPhysics& phys, const std::vector<Layer>& layers, int nx,
                          double dx, double y0, double dy, int blocks,
                          const std::vector<double>& shift) {
  const int ny = static_cast<int>(std::lround((kSurface - y0) / dy));
  BinSums s = test::empty_sums(nx, ny, blocks, 30 * kD - 0.5 * nx * dx, y0, dx, dy);
  constexpr int sub = 64;
  for (int b = 0; b < blocks; ++b) {
    const double move = shift.empty() ? 0 : shift[static_cast<std::size_t>(b) % shift.size()];
    s.samples[static_cast<std::size_t>(b)] = 400;
    for (int iy = 0; iy < ny; ++iy) {
      std::vector<double> f(layers.size(), 0.0);
      for (int j = 0; j < sub; ++j) {
        const double y = y0 + (iy + (j + 0.5) / sub) * dy - move;
        std::size_t k = 0;
        while (k + 1 < layers.size() && y >= layers[k].end) ++k;
        f[k] += 1.0 / sub;
      }
      for (int ix = 0; ix < nx; ++ix)
        for (std::size_t k = 0; k < layers.size(); ++k)
          if (f[k] > 0) test::add_state(s, b, iy, ix, *layers[k].state, phys, 400, f[k]);
    }
  }
  return s;
}

// The four layers from the inflow to the surface.
BinSums layered_profile(const FieldPhysics& phys, int nx, double dx, double y0, double dy,
                        int blocks, const std::vector<double>& shift = {}) {
  const Layers l = layers(phys);
  return profile_of_layers(phys,
                           {{kTemperatureJump, &l.cold},
                            {kSonic, &l.hot},
                            {kDensityJump, &l.subsonic},
                            {kSurface, &l.dense}},
                           nx, dx, y0, dy, blocks, shift);
}

DetachmentSearch search_from(double y_begin) {
  DetachmentSearch search;
  search.y_begin = y_begin;
  return search;
}

// Where each definition puts the front, for rows aligned with the layers' edges and for rows
// offset from them by 0.3 of a row.
class FrontDefinitions : public ::testing::TestWithParam<double> {};

TEST_P(FrontDefinitions, EachFindsItsOwnEdge) {
  const FieldPhysics phys = test::physics_of(kScene);
  const Layers l = layers(phys);
  const double dy = 0.5 * kD, offset = GetParam() * dy;
  const BinSums profile = layered_profile(phys, 1, 4 * kD, offset, dy, 1);
  const Detachments all = measure_detachments(profile, phys, {l.phi_up}, search_from(10 * kD));
  const struct {
    FrontDefinition definition;
    double edge;
  } expected[] = {{FrontDefinition::temperature_jump, kTemperatureJump},
                  {FrontDefinition::density_threshold, kDensityJump},
                  {FrontDefinition::density_max_gradient, kDensityJump},
                  {FrontDefinition::sonic_line, kSonic}};
  for (const auto& e : expected) {
    const Detachment& d = of(all, e.definition);
    ASSERT_TRUE(d.found) << name(e.definition) << ": " << d.reason;
    EXPECT_NEAR(d.surface, kSurface, 1e-12);
    // Interpolating between bin centres across a step lands within half a row of it.
    EXPECT_NEAR(d.y_shock, e.edge, 0.5 * dy) << name(e.definition);
    EXPECT_NEAR(d.delta_over_d, (kSurface - d.y_shock) / (12 * kD), 1e-12);
  }
  if (offset == 0) {
    // A step on a row edge between two plateaus: the half-rise of T and the crossing of
    // Ma = 1 (1.5 on one side, 0.5 on the other) lie exactly on it.
    EXPECT_NEAR(of(all, FrontDefinition::temperature_jump).y_shock, kTemperatureJump, 1e-9 * kD);
    EXPECT_NEAR(of(all, FrontDefinition::sonic_line).y_shock, kSonic, 1e-9 * kD);
  }
  // The definitions keep their order along the line: hot edge, sonic point, dense cap.
  EXPECT_GT(of(all, FrontDefinition::temperature_jump).delta,
            of(all, FrontDefinition::sonic_line).delta);
  EXPECT_GT(of(all, FrontDefinition::sonic_line).delta,
            of(all, FrontDefinition::density_threshold).delta);
}

INSTANTIATE_TEST_SUITE_P(RowOffsets, FrontDefinitions, ::testing::Values(0.0, 0.3, 0.7));

TEST(FrontDefinitions, SayWhyTheyFindNoFront) {
  const FieldPhysics phys = test::physics_of(kScene);
  const Layers l = layers(phys);
  // Search from inside the subsonic layer: the T and Ma searches start past their edges.
  const BinSums profile = layered_profile(phys, 1, 4 * kD, 0, 0.5 * kD, 1);
  const Detachments all =
      measure_detachments(profile, phys, {l.phi_up}, search_from(kSonic + 0.5 * kD));
  EXPECT_FALSE(of(all, FrontDefinition::sonic_line).found);
  EXPECT_NE(of(all, FrontDefinition::sonic_line).reason.find("already subsonic"), std::string::npos)
      << of(all, FrontDefinition::sonic_line).reason;
  EXPECT_FALSE(of(all, FrontDefinition::temperature_jump).found);
  EXPECT_NE(of(all, FrontDefinition::temperature_jump).reason.find("T nowhere rises"),
            std::string::npos)
      << of(all, FrontDefinition::temperature_jump).reason;
  EXPECT_TRUE(of(all, FrontDefinition::density_threshold).found);
}

// The paper's slow inflow (Ma_inf = 2.64): the gas past the insertion strip is warmer than
// the shock will make it, and cools on its way to the front. Ahead of the layers lies a warm
// layer 1.2 times as hot as the hot layer behind the jump: the largest T on the line is not
// the shock's, and the shock's peak is below 1.5 T_up. The front is the half-rise from the
// cooled gas to the hot layer, on the jump.
TEST_P(FrontDefinitions, TemperatureRisesFromTheCooledGasNotTheWarmInlet) {
  const FieldPhysics phys = test::physics_of(kScene);
  const Layers l = layers(phys);
  const double t_hot = test::temperature_for_mach(phys, 0.15, 0.9, 1.5);
  const test::BinState warm = test::mixture_state(phys, 0.1, 1.2 * t_hot, 0, 1.0);
  const double dy = 0.5 * kD, offset = GetParam() * dy;
  const BinSums profile = profile_of_layers(phys,
                                            {{20 * kD, &warm},
                                             {kTemperatureJump, &l.cold},
                                             {kSonic, &l.hot},
                                             {kDensityJump, &l.subsonic},
                                             {kSurface, &l.dense}},
                                            1, 4 * kD, offset, dy, 1, {});
  const Detachments all = measure_detachments(profile, phys, {l.phi_up}, search_from(10 * kD));
  const Detachment& d = of(all, kPrimaryFront);
  ASSERT_TRUE(d.found) << d.reason;
  EXPECT_NEAR(d.y_shock, kTemperatureJump, 0.5 * dy);
  if (offset == 0) {
    EXPECT_NEAR(d.y_shock, kTemperatureJump, 1e-9 * kD);
  }
  EXPECT_LT(d.peak, 1.5 * 1.2 * t_hot);  // measured from the inlet's T there were no front
}

// The largest rise on plain lines of bins (analysis/front_crossing.hpp).
TEST(LargestRise, HalfRiseOfTheLargestRiseSearchedFromItsStart) {
  const std::vector<double> y = {0, 1, 2, 3, 4, 5, 6, 7, 8};
  const ThresholdRule rule;
  // Warm start, cooling, a bump above the threshold (6 at y = 3) upstream of the coldest
  // point, then the jump from 1 to 9: threshold 5, crossed between y = 6 (3) and 7 (9).
  const std::vector<double> t = {8, 6, 2, 6, 1, 1, 3, 9, 7};
  const FrontCrossing c = find_largest_rise(t, y, 0, 9, rule);
  ASSERT_TRUE(c.found) << describe(c.why, c, 0, rule, "T");
  EXPECT_EQ(c.base, 1);
  EXPECT_EQ(c.phi_peak, 9);
  EXPECT_EQ(c.peak_index, 7);
  EXPECT_DOUBLE_EQ(c.threshold, 5);
  EXPECT_DOUBLE_EQ(c.y_threshold, 6 + 2.0 / 6);
  // A plateau above the threshold ahead of the peak belongs to the front's run.
  const FrontCrossing plateau =
      find_largest_rise({8, 1, 1, 6, 6, 9, 2}, {0, 1, 2, 3, 4, 5, 6}, 0, 7, rule);
  ASSERT_TRUE(plateau.found);
  EXPECT_DOUBLE_EQ(plateau.y_threshold, 2 + 4.0 / 5);
  // A dip below the threshold inside the hot layer (4 at y = 4) does not move the front to
  // the dip's downstream side.
  const FrontCrossing dip =
      find_largest_rise({8, 1, 1, 7, 4, 9, 2}, {0, 1, 2, 3, 4, 5, 6}, 0, 7, rule);
  ASSERT_TRUE(dip.found);
  EXPECT_DOUBLE_EQ(dip.y_threshold, 2 + 4.0 / 6);
}

TEST(LargestRise, SaysWhyThereIsNone) {
  const std::vector<double> y = {0, 1, 2, 3, 4};
  const ThresholdRule rule;
  const double nan = std::nan("");
  const FrontCrossing falling = find_largest_rise({5, 4, 3, 2, 1}, y, 0, 5, rule);
  EXPECT_FALSE(falling.found);
  EXPECT_EQ(falling.why, NoFront::no_rise);
  EXPECT_EQ(describe(falling.why, falling, 0, rule, "T"),
            "T nowhere rises along the searched bins");
  const FrontCrossing small = find_largest_rise({5, 4, 3, 4, 1}, y, 0, 5, rule);
  EXPECT_EQ(small.why, NoFront::rise_too_small);
  EXPECT_EQ(describe(small.why, small, 0, rule, "T"),
            "T rises at most from 3 to 4, less than 1.5-fold");
  const FrontCrossing masked = find_largest_rise({5, 1, nan, 4, 1}, y, 0, 5, rule);
  EXPECT_EQ(masked.why, NoFront::masked_before_peak);
  // A NaN ahead of the rise's base does not matter.
  EXPECT_TRUE(find_largest_rise({nan, 1, 2, 4, 1}, y, 0, 5, rule).found);
  EXPECT_EQ(find_largest_rise({nan, nan, nan, nan, nan}, y, 0, 5, rule).why, NoFront::all_masked);
  // Only bins in [begin, end) count: the rise from 1 to 9 lies outside.
  EXPECT_EQ(find_largest_rise({1, 9, 5, 4, 3}, y, 2, 5, rule).why, NoFront::no_rise);
}

// Error bars: blocks whose fronts move independently against blocks that move in pairs
// (neighbouring blocks correlated, as when the dense cap drifts slowly). The single-block
// error assumes independence and misses the correlation; the merged pairs see it, and the
// reported error follows them.
TEST(FrontDefinitions, CorrelatedNeighbouringBlocksRaiseTheError) {
  const FieldPhysics phys = test::physics_of(kScene);
  const Layers l = layers(phys);
  const std::vector<double> independent = {0.6 * kD, -0.9 * kD, 0.3 * kD, -0.3 * kD,
                                           0.9 * kD, -0.6 * kD, 0.0,      0.45 * kD};
  std::vector<double> paired;
  for (std::size_t b = 0; b < independent.size(); ++b) paired.push_back(independent[b / 2 * 2]);
  auto measure = [&](const std::vector<double>& shifts) {
    return of(measure_detachments(layered_profile(phys, 1, 4 * kD, 0, 0.5 * kD, 8, shifts), phys,
                                  {l.phi_up}, search_from(10 * kD)),
              kPrimaryFront);
  };
  const Detachment free = measure(independent), pairs = measure(paired);
  ASSERT_TRUE(free.found && pairs.found);
  EXPECT_EQ(pairs.blocks_used, 8);
  // Paired blocks: 4 distinct values seen as 8 independent ones, an error sqrt(7/3) = 1.53
  // times too small; merging pairs recovers it.
  EXPECT_GT(pairs.err_merged_pairs, 1.3 * pairs.err_blocks)
      << pairs.err_merged_pairs / kD << " d vs " << pairs.err_blocks / kD << " d";
  EXPECT_GE(pairs.delta_err, pairs.err_merged_pairs);
  // The bootstrap resamples the 8 blocks as if independent: it sees the single-block spread
  // (up to the estimator's shape: the half-rise of pooled, shifted steps behaves like a
  // median of the shifts, whose spread exceeds the mean's), not the pairs'.
  EXPECT_GT(pairs.err_bootstrap, 0.5 * pairs.err_blocks);
  EXPECT_LT(pairs.err_bootstrap, 2.0 * pairs.err_blocks);
  EXPECT_EQ(pairs.bootstrap_found, pairs.bootstrap_resamples);
  // Independent blocks: merging does not raise the error beyond its own noise.
  EXPECT_LT(free.err_merged_pairs, 1.3 * free.err_blocks);
}

// The whole analysis on a layered profile of 12 columns of 0.5 d (as runs sample it): the
// convergence table holds every choice, and the primary definition agrees with itself when
// the rows resolve the layers.
TEST(FrontDefinitions, ConvergenceTableCoversEveryChoice) {
  const FieldPhysics phys = test::physics_of(kScene);
  const test::BowShockSums bow = test::bow_shock_sums(phys, 12, 4, 250);
  const BinSums profile =
      layered_profile(phys, 12, 0.5 * kD, 0, 0.5 * kD, 4, {0.1 * kD, -0.1 * kD});
  const FieldAnalysis a = analyse_fields(parse_scene(kScene).scene, bow.grid, profile);
  EXPECT_NEAR(a.strip_width, 4 * kD, 1e-12);
  std::vector<std::string> labels;
  for (const ConvergenceChoice& c : a.convergence.choices) labels.push_back(c.label);
  const std::vector<std::string> expected = {"rows 0.5 d, strip 4 d",
                                             "rows 1 d, strip 4 d",
                                             "rows 1.5 d, strip 4 d",
                                             "rows 2 d, strip 4 d",
                                             "rows 3 d, strip 4 d",
                                             "strip 1 d",
                                             "strip 2 d",
                                             "strip 4 d",
                                             "strip 6 d",
                                             "grid column 3 d",
                                             "first half of the window",
                                             "second half of the window"};
  EXPECT_EQ(labels, expected);
  // The reference cut is the first row of the table.
  EXPECT_EQ(a.convergence.choices[0].result[0].delta, a.detachments[0].delta);
  // Strips of any width see the same plane layers; the density threshold on 1.5-3 d rows
  // merged from the face keeps the dense cap's edge (3.5 d from the face) within a row.
  for (const ConvergenceChoice& c : a.convergence.choices) {
    const Detachment& density = of(c.result, FrontDefinition::density_threshold);
    if (c.kind == "strip" || c.kind == "window") {
      EXPECT_NEAR(density.delta, kSurface - kDensityJump, 0.6 * kD) << c.label;
    }
  }
  EXPECT_EQ(a.convergence.verdicts.size(), kFrontDefinitions.size());
  EXPECT_FALSE(a.convergence.of(kPrimaryFront).text.empty());
  // A cut without a front is named in the verdict with the reason its definition gave.
  int without_front = 0;
  for (std::size_t k = 0; k < kFrontDefinitions.size(); ++k) {
    const ConvergenceVerdict& v = a.convergence.of(kFrontDefinitions[k]);
    if (!v.applicable) continue;
    for (const ConvergenceChoice& c : a.convergence.choices) {
      const Detachment& r = c.result[k];
      if (r.found) continue;
      ++without_front;
      ASSERT_FALSE(r.reason.empty()) << c.label;
      EXPECT_NE(v.text.find(c.label + ": no front (" + r.reason + ")"), std::string::npos)
          << v.text;
    }
  }
  EXPECT_GT(without_front, 0);  // the fits find none on the coarsest rows of this profile
  const std::string csv = convergence_csv(a);
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 13);
  EXPECT_EQ(csv.rfind("choice,kind,size_d,temperature_jump,temperature_jump_err,", 0), 0u);
}

// One block: no delta carries an error, so a cut that moves delta cannot be judged by
// two errors. The verdict says "n/a", never "two errors: nan d".
TEST(FrontDefinitions, AVerdictWithoutErrorsSaysNotApplicable) {
  const FieldPhysics phys = test::physics_of(kScene);
  const test::BowShockSums bow = test::bow_shock_sums(phys, 12, 1, 1000);
  const BinSums profile = layered_profile(phys, 12, 0.5 * kD, 0, 0.5 * kD, 1, {0.1 * kD});
  const FieldAnalysis a = analyse_fields(parse_scene(kScene).scene, bow.grid, profile);
  ASSERT_TRUE(a.detachment.found) << a.detachment.reason;
  EXPECT_TRUE(std::isnan(a.detachment.delta_err));
  int judged_without_errors = 0;
  for (const ConvergenceVerdict& v : a.convergence.verdicts) {
    EXPECT_EQ(v.text.find("nan"), std::string::npos) << v.text;
    if (v.text.find("(two errors: n/a)") != std::string::npos) ++judged_without_errors;
  }
  EXPECT_GT(judged_without_errors, 0);  // the grid column's delta differs from the strip's
}

}  // namespace

namespace {

// The paper's claims as numbers (analysis/flow_features.hpp) on the synthetic bow shock of
// synthetic_run.hpp: uniform inflow at Ma 6 and phi 0.1 ahead of a V-shaped front, phi 0.4
// at Ma 0.5 behind it, everywhere behind, the wake included.
TEST(FlowFeatures, SyntheticBowShock) {
  const FieldPhysics phys = test::physics_of(kScene);
  const test::BowShockSums bow = test::bow_shock_sums(phys, 12, 4, 250);
  const FieldAnalysis a = analyse_fields(parse_scene(kScene).scene, bow.grid, bow.profile);
  const FlowFeatures& f = a.features;
  // Between the front's upstream edge (the primary definition finds the apex, 6 d from the
  // surface) and the surface the 3 d strip holds phi 0.4, except over the 1.5 d cot(50 deg)
  // = 1.26 d the V front takes to cross it, where phi rises from 0.1 to 0.4 (0.25 on
  // average): 0.4 - 0.15 * 1.26 / 6 = 0.369.
  EXPECT_NEAR(f.shock_layer_phi_mean, 0.369, 0.01) << f.shock_layer_reason;
  // The inflow does not cool here: the largest Ma ahead of the front is Ma_inf itself.
  EXPECT_NEAR(f.upstream_ma_peak, 6.0, 0.05) << f.upstream_ma_reason;
  EXPECT_NEAR(f.upstream_ma_peak_over_inf, 1.0, 0.01);
  // The synthetic "wake" holds the post-shock state: phi 0.4 = 4 phi_up.
  EXPECT_NEAR(f.wake_phi_over_phi_up, 4.0, 0.05) << f.wake_reason;
}

// The hot region on the layers (rows of 0.5 d on the layers' edges): the hot layer behind
// the temperature jump is the only one above the threshold, and it is supersonic (Ma 1.5),
// so none of its bins is subsonic; each of its 5 rows on the strip is counted. The shock
// layer's mean phi is that of the hot, subsonic and dense layers by their lengths.
TEST(FlowFeatures, HotRegionOfTheLayers) {
  const FieldPhysics phys = test::physics_of(kScene);
  const BinSums grid = layered_profile(phys, 20, 3 * kD, 0, 0.5 * kD, 4);
  const BinSums profile = layered_profile(phys, 12, 0.5 * kD, 0, 0.5 * kD, 4);
  const FieldAnalysis a = analyse_fields(parse_scene(kScene).scene, grid, profile);
  ASSERT_TRUE(a.detachment.found) << a.detachment.reason;
  EXPECT_EQ(a.features.hot_bins, 5);  // 2.5 d of 0.5 d rows
  EXPECT_EQ(a.features.hot_subsonic_fraction, 0.0) << a.features.hot_reason;
  EXPECT_NEAR(a.features.shock_layer_phi_mean, (2.5 * 0.15 + 3 * 0.2 + 3.5 * 0.45) / 9, 1e-9);
  // No grid rows behind the cylinder: the wake is undetermined, and says why.
  EXPECT_TRUE(std::isnan(a.features.wake_phi_over_phi_up));
  EXPECT_NE(a.features.wake_reason.find("behind the obstacle"), std::string::npos);
}

TEST(FlowFeatures, UndeterminedWithoutAFront) {
  const FieldPhysics phys = test::physics_of(kScene);
  // The front's apex moved 1 m upstream: no shock at all.
  const test::BowShockSums bow = test::bow_shock_sums(phys, 12, 4, 250, 0.1, 1.0);
  const FieldAnalysis a = analyse_fields(parse_scene(kScene).scene, bow.grid, bow.profile);
  EXPECT_TRUE(std::isnan(a.features.shock_layer_phi_mean));
  EXPECT_EQ(a.features.shock_layer_reason.rfind("no delta/D, so no front to measure from: no shock "
                                                "front on the stagnation line: ",
                                                0),
            0u)
      << a.features.shock_layer_reason;
  EXPECT_TRUE(std::isnan(a.features.hot_subsonic_fraction));
  EXPECT_NEAR(a.features.wake_phi_over_phi_up, 1.0, 0.01);
}

}  // namespace
