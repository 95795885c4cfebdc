// The field analysis never publishes a number from fields that hold no information
// (docs/fields.md, "When a number cannot be determined"): such a number is null in
// summary.json with KEY_reason next to it, NaN in fields.h5, an empty cell / null in the
// detachment table and "n/a" on the result line, and the figures are still drawn.
// Reported defects: every bin masked (output.sample_every = 10^9) still gave delta/D and a
// shock angle; one bin across the whole domain (numerics.bin_size = 1000 d) still gave
// delta/D.
#include <gtest/gtest.h>
#include <hdf5.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "analysis/field_analysis.hpp"
#include "analysis/fields_command.hpp"
#include "analysis/fields_output.hpp"
#include "synthetic_run.hpp"

using namespace granshock;
namespace fs = std::filesystem;

namespace {

constexpr double kD = 1e-3;

nlohmann::json read_json(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return nlohmann::json::parse(s.str());
}

std::string read_text(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

bool contains(const nlohmann::json& j, const std::string& key, const std::string& part) {
  return j.contains(key) && j[key].is_string() &&
         j[key].get<std::string>().find(part) != std::string::npos;
}

// Every number of the analysis that is null has KEY_reason, a non-empty string, and every
// KEY_reason is null when KEY is a number.
void expect_reasons_match(const nlohmann::json& j) {
  const std::string suffix = "_reason";
  for (const auto& [key, value] : j.items()) {
    if (key.size() > suffix.size() &&
        key.compare(key.size() - suffix.size(), suffix.size(), suffix) == 0) {
      const std::string base = key.substr(0, key.size() - suffix.size());
      ASSERT_TRUE(j.contains(base)) << key;
      if (j[base].is_null())
        EXPECT_TRUE(value.is_string() && !value.get<std::string>().empty()) << key;
      else
        EXPECT_TRUE(value.is_null()) << key << " = " << value << " next to " << j[base];
    } else if (value.is_null() && key != "inflow_warning") {
      EXPECT_TRUE(j.contains(key + suffix)) << key << " is null without a reason";
    }
  }
}

bool is_png(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  char head[8] = {};
  in.read(head, 8);
  return in && std::string(head + 1, 3) == "PNG";
}

double h5_attribute(const fs::path& file, const std::string& object, const std::string& name) {
  const hid_t f = H5Fopen(file.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  const hid_t a = H5Aopen_by_name(f, object.c_str(), name.c_str(), H5P_DEFAULT, H5P_DEFAULT);
  double v = 0;
  H5Aread(a, H5T_NATIVE_DOUBLE, &v);
  H5Aclose(a);
  H5Fclose(f);
  return v;
}

bool h5_has_attribute(const fs::path& file, const std::string& object, const std::string& name) {
  const hid_t f = H5Fopen(file.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  const bool has = H5Aexists_by_name(f, object.c_str(), name.c_str(), H5P_DEFAULT) > 0;
  H5Fclose(f);
  return has;
}

Scene scene_of(const std::string& toml) {
  return parse_scene(toml).scene;
}

// The figure script draws every masked bin blank, phi included (check_figure_masking.py).
void expect_masked_bins_blank(const fs::path& fields_h5) {
  if (std::system("/usr/bin/python3 -c 'import h5py, matplotlib' >/dev/null 2>&1") != 0)
    return;  // no figures without them (FieldsCommand.MissingMatplotlibCostsOnlyTheFigures)
  const std::string check = "/usr/bin/python3 " GRANSHOCK_TEST_FIELDS_DIR
                            "/check_figure_masking.py '" +
                            fields_h5.string() + "' " GRANSHOCK_SOURCE_DIR "/analysis";
  EXPECT_EQ(std::system(check.c_str()), 0) << check;
}

// Runs `granshock fields` on one synthetic run directory and returns its stdout.
std::string fields_on(const fs::path& run, const std::string& scene, const BinSums& grid,
                      const BinSums* profile) {
  test::write_run_file(run, scene, grid, profile);
  std::ofstream(run / "summary.json") << R"({"scene": "synthetic", "ma_inf_target": 5.9})";
  ::testing::internal::CaptureStdout();
  fields_command({run}, {}, FieldsCommandOptions{true, false});
  return ::testing::internal::GetCapturedStdout();
}

}  // namespace

// Defect 1: one sample per block (output.sample_every = 10^9 samples the window once), so
// every bin is masked. The scene's phi_inf used to stand in for the unmeasured phi_up, and
// the front search ran on phi from a handful of particles.
TEST(Undeterminable, EveryBinMaskedPublishesNoHeadlineNumber) {
  test::ScratchDir tmp;
  const std::string scene = test::bow_shock_scene(12);
  const test::BowShockSums sums = test::bow_shock_sums(test::physics_of(scene), 12, 4, 1);
  const fs::path run = tmp.path() / "run";
  const std::string line = fields_on(run, scene, sums.grid, &sums.profile);

  const nlohmann::json j = read_json(run / "summary.json");
  ASSERT_EQ(j["fields_masked_bins"], j["fields_bins"]) << "the test needs every bin masked";
  for (const char* key :
       {"delta_over_D", "delta_over_D_err", "detachment_length_m", "shock_angle_deg",
        "shock_angle_deg_left", "shock_angle_deg_right", "ma_inf_measured",
        "ma_inf_measured_downstream", "phi_inf_measured", "phi_inf_measured_downstream", "phi_peak",
        "eos_deviation_dilute", "eos_deviation_dense", "phi_inf_deviation", "ma_inf_deviation"})
    EXPECT_TRUE(j[key].is_null()) << key << " = " << j[key];
  EXPECT_TRUE(contains(j, "delta_over_D_reason", "unmasked")) << j["delta_over_D_reason"];
  EXPECT_TRUE(contains(j, "shock_angle_deg_reason", "unmasked")) << j["shock_angle_deg_reason"];
  EXPECT_TRUE(contains(j, "phi_peak_reason", "masked")) << j["phi_peak_reason"];
  EXPECT_TRUE(contains(j, "eos_deviation_dense_reason", "no unmasked bin"));
  EXPECT_EQ(j["detachment_blocks"], 0);
  EXPECT_DOUBLE_EQ(j["ma_inf_target"].get<double>(), 5.9);  // the target is still known
  EXPECT_FALSE(j["inflow_phi_short"].get<bool>()) << "nothing measured, nothing flagged";
  expect_reasons_match(j);

  EXPECT_NE(line.find("delta/D = n/a (no upstream phi beyond the strip"), std::string::npos)
      << line;
  EXPECT_NE(line.find("shock angle n/a deg ("), std::string::npos) << line;
  // fields.h5: NaN numbers, the reasons as text; figures drawn with the bins blank.
  EXPECT_TRUE(std::isnan(h5_attribute(run / "fields.h5", "/profile", "delta_over_D")));
  EXPECT_TRUE(std::isnan(h5_attribute(run / "fields.h5", "/summary", "delta_over_D")));
  EXPECT_TRUE(h5_has_attribute(run / "fields.h5", "/summary", "delta_over_D_reason"));
  EXPECT_TRUE(h5_has_attribute(run / "fields.h5", "/profile", "delta_reason"));
  EXPECT_FALSE(h5_has_attribute(run / "fields.h5", "/summary", "inflow_warning"));
  for (const char* png :
       {"solid_fraction.png", "temperature.png", "mach.png", "stagnation_profiles.png"})
    EXPECT_TRUE(is_png(run / "figures" / png)) << png;
  expect_masked_bins_blank(run / "fields.h5");
}

// Defect 2: one bin of 1000 d covers the whole domain and beyond. The upstream rows beyond
// the strip (rows 2-3) do not exist; the grid's only row was used instead.
TEST(Undeterminable, OneBinAcrossTheDomainGivesNoDetachment) {
  test::ScratchDir tmp;
  const std::string scene = test::bow_shock_scene(12);
  const FieldPhysics phys = test::physics_of(scene);
  const test::BowShockSums sums = test::bow_shock_sums(phys, 12, 4, 250);
  BinSums one = test::empty_sums(1, 1, 4, 0, 0, 1000 * kD, 1000 * kD);
  const test::BinState flow =
      test::mixture_state(phys, 0.1, test::temperature_for_mach(phys, 0.1, 1.0, 6.0), 0, 1.0);
  for (int b = 0; b < 4; ++b) {  // the domain's particles diluted over the bin
    one.samples[static_cast<std::size_t>(b)] = 250;
    test::add_state(one, b, 0, 0, flow, phys, 250, 60.0 * 90.0 / (1000.0 * 1000.0));
  }
  const fs::path run = tmp.path() / "run";
  const std::string line = fields_on(run, scene, one, &sums.profile);
  const nlohmann::json j = read_json(run / "summary.json");
  EXPECT_EQ(j["fields_bins"], 1);
  EXPECT_TRUE(j["delta_over_D"].is_null()) << j["delta_over_D"];
  EXPECT_TRUE(contains(j, "delta_over_D_reason", "rows 2-3 are not all in the grid"))
      << j["delta_over_D_reason"];
  EXPECT_TRUE(j["ma_inf_measured"].is_null()) << "rows 0-1: the grid has one row";
  EXPECT_TRUE(j["phi_inf_measured_downstream"].is_null());
  expect_reasons_match(j);
  EXPECT_NE(line.find("delta/D = n/a ("), std::string::npos) << line;
  EXPECT_TRUE(is_png(run / "figures" / "stagnation_profiles.png"));
}

TEST(Undeterminable, UpstreamRowsMustBeInTheDomainUpstreamAndMostlyUnmasked) {
  const std::string scene = test::bow_shock_scene(12);
  const FieldPhysics phys = test::physics_of(scene);
  const test::BinState flow =
      test::mixture_state(phys, 0.1, test::temperature_for_mach(phys, 0.1, 1.0, 6.0), 0, 1.0);
  auto uniform = [&](int nx, int ny, double bin, double samples) {
    BinSums s = test::empty_sums(nx, ny, 1, 0, 0, bin, bin);
    s.samples = {samples};
    for (int iy = 0; iy < ny; ++iy)
      for (int ix = 0; ix < nx; ++ix) test::add_state(s, 0, iy, ix, flow, phys, samples);
    return s;
  };
  // 3 d bins, 2000 samples: rows 2-3 are a proper upstream state.
  const BinSums good = uniform(20, 30, 3 * kD, 2000);
  const UpstreamState ok = measure_upstream(compute_bin_fields(good, phys), good, phys, 2, 4);
  EXPECT_TRUE(ok.determined()) << ok.reason;
  EXPECT_NEAR(ok.mach, 6.0, 1e-9);
  // Rows 17-18 end at 57 d, past the cylinder's surface at 54 d.
  const UpstreamState past = measure_upstream(compute_bin_fields(good, phys), good, phys, 17, 19);
  EXPECT_FALSE(past.determined());
  EXPECT_NE(past.reason.find("past the obstacle's upstream surface"), std::string::npos)
      << past.reason;
  EXPECT_TRUE(std::isnan(past.phi) && std::isnan(past.mach));
  // 50 d bins: rows 0-1 end at 100 d, beyond the 90 d channel (phi diluted by empty space).
  const BinSums coarse = uniform(2, 2, 50 * kD, 2000);
  const UpstreamState beyond = measure_upstream(compute_bin_fields(coarse, phys), coarse,
                                                test::physics_of(test::bow_shock_scene(0)), 0, 2);
  EXPECT_NE(beyond.reason.find("beyond the domain's end"), std::string::npos) << beyond.reason;
  // 10 samples: 11.5 particle samples per bin, all masked.
  const BinSums sparse = uniform(20, 30, 3 * kD, 10);
  const UpstreamState few = measure_upstream(compute_bin_fields(sparse, phys), sparse, phys, 2, 4);
  EXPECT_NE(few.reason.find("only 0 of the 40 bins of rows 2-3 are unmasked"), std::string::npos)
      << few.reason;
  // Half of the bins unmasked is enough: phi from all, T from the unmasked ones.
  BinSums half = uniform(20, 30, 3 * kD, 2000);
  for (int ix = 0; ix < 10; ++ix)
    for (int iy = 2; iy < 4; ++iy)
      for (int q = 0; q < half.quantities(); ++q)
        half.sums[static_cast<std::size_t>(half.layout().offset(0, iy, ix, q))] *= 0.001;
  const UpstreamState halved = measure_upstream(compute_bin_fields(half, phys), half, phys, 2, 4);
  EXPECT_TRUE(halved.determined()) << halved.reason;
  EXPECT_NEAR(halved.phi, 0.5 * (0.1 + 0.0001), 1e-9);
  EXPECT_NEAR(halved.temperature, ok.temperature, 1e-15);
}

TEST(Undeterminable, DetachmentSaysWhyThereIsNoFront) {
  const std::string toml = test::bow_shock_scene(12);
  const Scene scene = scene_of(toml);
  const FieldPhysics phys = test::physics_of(toml);
  // No shock at all: uniform flow up to the cylinder.
  {
    const test::BowShockSums s = test::bow_shock_sums(phys, 12, 4, 250, 0.1, 1.0);  // apex at 1 m
    const FieldAnalysis a = analyse_fields(scene, s.grid, s.profile);
    EXPECT_TRUE(std::isnan(a.detachment.delta_over_d));
    EXPECT_NE(a.detachment.reason.find("no shock front on the stagnation line: T nowhere rises"),
              std::string::npos)
        << a.detachment.reason;
    EXPECT_NE(a.front.angle_reason.find("columns of the fit region"), std::string::npos)
        << a.front.angle_reason;
    EXPECT_TRUE(a.upstream_downstream.determined());
  }
  // The front reaches into rows 2-3 (6-12 d), which measure phi_up: apex at 10 d.
  {
    const test::BowShockSums s = test::bow_shock_sums(phys, 12, 4, 250, 0.1, -38 * kD);
    const FieldAnalysis a = analyse_fields(scene, s.grid, s.profile);
    EXPECT_TRUE(std::isnan(a.detachment.delta_over_d));
    EXPECT_NE(a.detachment.reason.find("lies within the grid rows that measure the upstream"),
              std::string::npos)
        << a.detachment.reason;
  }
  // A profile bin without particles between the search start and the shock.
  {
    test::BowShockSums s = test::bow_shock_sums(phys, 12, 4, 250);
    for (int b = 0; b < 4; ++b)
      for (int q = 0; q < s.profile.quantities(); ++q)
        s.profile.sums[static_cast<std::size_t>(s.profile.layout().offset(b, 60, 0, q))] = 0;
    const FieldAnalysis a = analyse_fields(scene, s.grid, s.profile);
    EXPECT_TRUE(std::isnan(a.detachment.delta_over_d));
    EXPECT_NE(a.detachment.reason.find("a masked bin"), std::string::npos) << a.detachment.reason;
  }
  // The profile ends 0.5 d past the search start: one bin to search.
  {
    const test::BowShockSums s = test::bow_shock_sums(phys, 12, 4, 250);
    BinSums short_profile = test::empty_sums(1, 13, 4, 28.5 * kD, 0, 3 * kD, 0.5 * kD);
    short_profile.samples = s.profile.samples;
    const std::size_t per_block = static_cast<std::size_t>(s.profile.quantities()) * 13;
    for (int b = 0; b < 4; ++b)
      std::copy_n(s.profile.sums.begin() + static_cast<long>(b * 180 * per_block / 13), per_block,
                  short_profile.sums.begin() + static_cast<long>(b * per_block));
    const FieldAnalysis a = analyse_fields(scene, s.grid, short_profile);
    EXPECT_NE(a.detachment.reason.find("holds 1 bins between the search start"), std::string::npos)
        << a.detachment.reason;
  }
  // No profile in run.h5 and 6 d bins: 2 bins across D = 12 d are too coarse to stand in.
  {
    BinSums grid = test::empty_sums(10, 15, 2, 0, 0, 6 * kD, 6 * kD);
    const test::BinState pre =
        test::mixture_state(phys, 0.1, test::temperature_for_mach(phys, 0.1, 1.0, 6.0), 0, 1.0);
    const test::BinState post =
        test::mixture_state(phys, 0.4, test::temperature_for_mach(phys, 0.4, 0.2, 0.5), 0, 0.2);
    test::fill_with_front(
        grid, phys, pre, post, [](double, double y, int) { return y > 48 * kD; }, 250);
    const FieldAnalysis a = analyse_fields(scene, grid, std::nullopt);
    ASSERT_TRUE(a.profile_from_grid);
    EXPECT_TRUE(std::isnan(a.detachment.delta_over_d));
    EXPECT_NE(a.detachment.reason.find("only 2 bins across the obstacle"), std::string::npos)
        << a.detachment.reason;
  }
}

TEST(Undeterminable, ErrorBarNeedsTwoBlocksWithAFront) {
  const std::string toml = test::bow_shock_scene(12);
  const FieldPhysics phys = test::physics_of(toml);
  // One block: a delta, no spread.
  {
    const test::BowShockSums s = test::bow_shock_sums(phys, 12, 1, 1000);
    const FieldAnalysis a = analyse_fields(scene_of(toml), s.grid, s.profile);
    EXPECT_TRUE(std::isfinite(a.detachment.delta_over_d)) << a.detachment.reason;
    EXPECT_TRUE(std::isnan(a.detachment.delta_over_d_err));
    EXPECT_NE(a.detachment.err_reason.find("only 1 of the 1 blocks"), std::string::npos)
        << a.detachment.err_reason;
  }
  // 4 blocks of 40 samples: the pooled profile bins count 30 particles upstream, each block's
  // only 7.6, below the 20 that unmask a bin.
  {
    const test::BowShockSums s = test::bow_shock_sums(phys, 12, 4, 40);
    const FieldAnalysis a = analyse_fields(scene_of(toml), s.grid, s.profile);
    EXPECT_TRUE(std::isfinite(a.detachment.delta_over_d)) << a.detachment.reason;
    EXPECT_TRUE(std::isnan(a.detachment.delta_over_d_err));
    EXPECT_EQ(a.detachment.blocks_used, 0);
    EXPECT_NE(a.detachment.err_reason.find("only 0 of the 4 blocks"), std::string::npos)
        << a.detachment.err_reason;
    EXPECT_NE(a.detachment.err_reason.find("block 0: "), std::string::npos);
  }
}

TEST(Undeterminable, ShockAngleNeedsAFitRegionWithThreeFronts) {
  // D = 30 d in the 60 d channel: one diameter from the axis lies beyond the line 2 bins
  // short of the midway line (24 d).
  const std::string toml = test::bow_shock_scene(30);
  const test::BowShockSums s = test::bow_shock_sums(test::physics_of(toml), 30, 2, 250);
  const FieldAnalysis a = analyse_fields(scene_of(toml), s.grid, s.profile);
  EXPECT_TRUE(std::isnan(a.front.angle_deg));
  EXPECT_NE(a.front.angle_reason.find("the domain is too narrow"), std::string::npos)
      << a.front.angle_reason;
  EXPECT_EQ(a.front.left.reason, a.front.right.reason);
  EXPECT_TRUE(std::isfinite(a.detachment.delta_over_d)) << a.detachment.reason;
  const nlohmann::json j = summary_keys(a);
  expect_reasons_match(j);
  EXPECT_TRUE(contains(j, "shock_angle_deg_left_reason", "too narrow"));
}

TEST(Undeterminable, DetachmentTableHasEmptyCellsAndReasons) {
  test::ScratchDir tmp;
  const std::string scene = test::bow_shock_scene(12);
  const FieldPhysics phys = test::physics_of(scene);
  const test::BowShockSums good = test::bow_shock_sums(phys, 12, 4, 250);
  const test::BowShockSums masked = test::bow_shock_sums(phys, 12, 4, 1);
  test::write_run_file(tmp.path() / "good", scene, good.grid, &good.profile);
  test::write_run_file(tmp.path() / "masked", scene, masked.grid, &masked.profile);
  const fs::path out = tmp.path() / "table";
  ASSERT_EQ(fields_command({tmp.path() / "good", tmp.path() / "masked"}, out,
                           FieldsCommandOptions{true, true}),
            0);
  EXPECT_TRUE(is_png(out / "figures" / "detachment_length.png"));
  const nlohmann::json table = read_json(out / "detachment.json");
  ASSERT_EQ(table.size(), 2u);
  EXPECT_TRUE(table[0]["delta_over_D"].is_number());
  EXPECT_TRUE(table[0]["delta_over_D_reason"].is_null());
  EXPECT_TRUE(table[1]["delta_over_D"].is_null());
  EXPECT_TRUE(table[1]["shock_angle_deg"].is_null());
  EXPECT_TRUE(contains(table[1], "delta_over_D_reason", "unmasked"));
  // A healthy run masks the cylinder's inside and the empty wake: blank, the rest drawn.
  expect_masked_bins_blank(tmp.path() / "good" / "fields.h5");
  const std::string csv = read_text(out / "detachment.csv");
  const std::string masked_row = csv.substr(csv.find("masked\""));
  // run, D_over_d, ma_inf_target, then ma_inf_measured and everything measured: empty.
  EXPECT_EQ(masked_row.find("masked\",12,5.9,,,,,,,,\"no upstream phi"), 0u) << masked_row;
}
