// Up-front checks of a scene's field sampling (docs/fields.md, "Up-front checks"): each
// refusal is one line naming the scene key and the limit; the shipped scenes pass.
#include <gtest/gtest.h>

#include <filesystem>

#include "analysis/bin_fields.hpp"
#include "analysis/field_sampling_check.hpp"
#include "core/user_error.hpp"
#include "io/scene_file.hpp"
#include "synthetic_run.hpp"

using namespace granshock;
namespace fs = std::filesystem;

namespace {

const fs::path kScenes = fs::path(GRANSHOCK_SOURCE_DIR) / "scenes";

Scene default_scene(const std::vector<std::string>& sets = {}) {
  return load_scene_file(kScenes / "default.toml", sets).scene;
}

// The message of the refusal, or "accepted".
std::string refusal(const Scene& s) {
  try {
    validate_field_sampling(s);
  } catch (const UserError& e) {
    return e.what();
  }
  return "accepted";
}

void expect_refused(const std::vector<std::string>& sets, const std::vector<std::string>& parts) {
  const std::string message = refusal(default_scene(sets));
  for (const std::string& part : parts)
    EXPECT_NE(message.find(part), std::string::npos) << "'" << part << "' not in: " << message;
  EXPECT_EQ(message.find('\n'), std::string::npos) << "one line: " << message;
}

}  // namespace

TEST(FieldSamplingCheck, ShippedScenesPass) {
  EXPECT_EQ(refusal(default_scene()), "accepted");
  int paper = 0;
  for (const auto& entry : fs::directory_iterator(kScenes / "paper")) {
    EXPECT_EQ(refusal(load_scene_file(entry.path(), {}).scene), "accepted") << entry.path();
    ++paper;
  }
  EXPECT_EQ(paper, 9);
}

TEST(FieldSamplingCheck, ProductionSamples) {
  // 0.2 s of production at 50 steps of 2e-7 s: 20 000 samples.
  EXPECT_EQ(production_samples(default_scene()), 20000);
  EXPECT_EQ(production_samples(default_scene({"output.sample_every=1000000000"})), 1);
  EXPECT_EQ(production_samples(default_scene({"output.sample_every=30000"})), 34);  // ceil(1e6/3e4)
}

TEST(FieldSamplingCheck, BinsSmallerThanAParticle) {
  expect_refused({"numerics.bin_size=0.001 d"},
                 {"numerics.bin_size = 0.001 d", "smaller than the particle diameter 1 d"});
  EXPECT_EQ(refusal(default_scene({"numerics.bin_size=1 d"})), "accepted");
}

TEST(FieldSamplingCheck, TooFewBinsAcrossTheDomainOrTheObstacle) {
  // One bin of 1000 d (docs/fields.md, the sampling check).
  expect_refused({"numerics.bin_size=1000 d"},
                 {"numerics.bin_size = 1000 d", "bins across the domain", "domain.width = 150 d",
                  "at least 3", "numerics.bin_size <= 50 d"});
  // 8 d bins: 2.5 across the 20 d cylinder.
  expect_refused({"numerics.bin_size=8 d"},
                 {"numerics.bin_size = 8 d", "2.5 bins across the obstacle",
                  "obstacle.diameter = 20 d", "at least 3", "numerics.bin_size <= 6.667 d"});
  EXPECT_EQ(refusal(default_scene({"numerics.bin_size=6.6 d"})), "accepted");
}

TEST(FieldSamplingCheck, TooFewRowsBetweenTheStripAndTheObstacle) {
  // Cylinder surface at 20 d, strip 2 d: 18 d = 4.5 bins of 4 d.
  expect_refused({"obstacle.centre=[\"75 d\", \"30 d\"]", "numerics.bin_size=4 d"},
                 {"numerics.bin_size = 4 d", "4.5 bins between the insertion strip",
                  "inflow.strip = 2 d", "at least 5", "numerics.bin_size <= 3.6 d"});
  // Without an obstacle: 12 d channel, 10 d beyond the strip = 3.3 bins of 3 d.
  const std::string message =
      refusal(parse_scene(test::bow_shock_scene(0), {"domain.length=12 d"}).scene);
  EXPECT_NE(message.find("and the outlet (domain.length = 12 d)"), std::string::npos) << message;
  EXPECT_NE(message.find("at least 4"), std::string::npos) << message;
}

// Exactly at a limit is enough: 5 d between the strip and a surface at 19 d - 12 d, in
// bins of 1 d, is 0.005 / 0.001 m = 4.999... in binary and was refused (found by the
// inflow tests).
TEST(FieldSamplingCheck, ALimitMetExactlyInUnitsOfDPasses) {
  EXPECT_EQ(refusal(default_scene({"obstacle.centre=[\"75 d\", \"19 d\"]", "obstacle.diameter=24 d",
                                   "numerics.bin_size=1 d"})),
            "accepted");
}

TEST(FieldSamplingCheck, BinSumsBeyondTheMemoryCap) {
  // The parser caps blocks at 10 000 (io/scene_file.cpp); that many still exceed the cap.
  expect_refused({"output.blocks=10000", "output.sample_every=1"},
                 {"output.blocks = 10000", "GiB of field sums", "the limit is 1 GiB"});
  // 20 000 d x 20 000 d in 1 d bins: 4e8 bins.
  expect_refused({"domain.width=20000 d", "domain.length=20000 d", "numerics.bin_size=1 d"},
                 {"numerics.bin_size = 1 d", "GiB of field sums"});
}

TEST(FieldSamplingCheck, TooFewSamplesInTheProductionWindow) {
  // One sample in the window (docs/fields.md, the sampling check).
  expect_refused({"output.sample_every=1000000000"},
                 {"output.sample_every = 1000000000", "[time.production_start, time.duration]",
                  "holds 1 field samples", "output.blocks = 10 need at least 100 (10 per block)",
                  "output.sample_every <= 10000"});
  expect_refused({"output.blocks=2001"}, {"output.blocks = 2001 need at least 20010"});
  // 1 d bins at phi 0.1 count 0.127 particles per sample: 200 samples give 25 per bin.
  expect_refused({"numerics.bin_size=1 d", "output.sample_every=5000"},
                 {"holds 200 field samples", "would count 25.5 particles", "40 are needed",
                  "output.sample_every <= 3183"});
  EXPECT_EQ(refusal(default_scene({"numerics.bin_size=1 d", "output.sample_every=3000"})),
            "accepted");
}

TEST(FieldSamplingCheck, LimitsFollowTheAnalysisRules) {
  // The expected upstream count is twice the count that unmasks a bin.
  EXPECT_DOUBLE_EQ(FieldSamplingLimits::upstream_particle_samples,
                   2 * MaskRule{}.min_particle_samples);
}
