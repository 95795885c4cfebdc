// Test (5) of the field-analysis issue: `granshock fields` on small synthetic run
// directories writes fields.h5, a fields.xmf whose every data item points at an existing
// dataset of the declared shape, the figures (PNG) and the summary keys; several
// directories also give the detachment table and figure (the paper's Fig. 6); bad input
// ends in one UserError and a missing matplotlib costs only the figures.
#include <gtest/gtest.h>
#include <hdf5.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <nlohmann/json.hpp>
#include <regex>
#include <sstream>

#include "fields_command.hpp"
#include "synthetic_run.hpp"
#include "user_error.hpp"

using namespace granshock;
namespace fs = std::filesystem;

namespace {

constexpr double kD = 1e-3;

std::string read_text(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// A run directory whose sums hold a bow shock in front of a cylinder of diameter_d d at
// (30 d, 60 d): upstream phi 0.1 at Ma 6, behind a V-shaped front (apex D/2 ahead of the
// surface, flanks at 50 deg) phi 0.4 at Ma 0.5; 4 blocks whose fronts differ by a few
// tenths of d. Also a summary.json as `granshock run` leaves it.
void make_run(const fs::path& dir, double diameter_d) {
  const std::string scene = test::bow_shock_scene(diameter_d);
  const FieldPhysics phys = test::physics_of(scene);
  const double surface = 60 * kD - 0.5 * diameter_d * kD, apex = surface - 0.5 * diameter_d * kD;
  const double cot_beta = 1.0 / std::tan(50.0 * M_PI / 180.0);
  const std::vector<double> shifts{0.2 * kD, -0.3 * kD, 0.1 * kD, -0.1 * kD};
  auto behind = [&](double x, double y, int b) {
    return y > apex + shifts[static_cast<std::size_t>(b)] + std::abs(x - 30 * kD) * cot_beta;
  };
  const test::BinState pre =
      test::mixture_state(phys, 0.1, test::temperature_for_mach(phys, 0.1, 1.0, 6.0), 0, 1.0);
  const test::BinState post =
      test::mixture_state(phys, 0.4, test::temperature_for_mach(phys, 0.4, 0.2, 0.5), 0.02, 0.2);
  BinSums grid = test::empty_sums(20, 30, 4, 0, 0, 3 * kD, 3 * kD);
  test::fill_with_front(grid, phys, pre, post, behind, 250, 6);
  BinSums profile = test::empty_sums(1, 180, 4, 28.5 * kD, 0, 3 * kD, 0.5 * kD);
  test::fill_with_front(profile, phys, pre, post, behind, 250, 6);
  test::write_run_file(dir, scene, grid, &profile);
  std::ofstream(dir / "summary.json")
      << R"({"scene": "synthetic", "steps": 123, "ma_inf_target": 5.9})";
}

struct DataItem {
  std::string dimensions, path;
};

// Every HDF DataItem of an XDMF file: its declared Dimensions and dataset path.
std::vector<DataItem> hdf_items(const std::string& xmf) {
  std::vector<DataItem> items;
  const std::regex item(
      R"re(<DataItem Dimensions="([0-9 ]+)"[^>]*Format="HDF">fields\.h5:([^<]+)</DataItem>)re");
  for (auto it = std::sregex_iterator(xmf.begin(), xmf.end(), item); it != std::sregex_iterator();
       ++it)
    items.push_back({(*it)[1].str(), (*it)[2].str()});
  return items;
}

std::string dataset_dimensions(const fs::path& h5, const std::string& dataset) {
  const hid_t f = H5Fopen(h5.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  if (f < 0) return "no file";
  std::string out = "missing";
  if (H5Lexists(f, dataset.c_str(), H5P_DEFAULT) > 0) {
    const hid_t d = H5Dopen2(f, dataset.c_str(), H5P_DEFAULT);
    const hid_t space = H5Dget_space(d);
    std::vector<hsize_t> shape(static_cast<std::size_t>(H5Sget_simple_extent_ndims(space)));
    H5Sget_simple_extent_dims(space, shape.data(), nullptr);
    out.clear();
    for (hsize_t e : shape) out += (out.empty() ? "" : " ") + std::to_string(e);
    H5Sclose(space);
    H5Dclose(d);
  }
  H5Fclose(f);
  return out;
}

bool is_png(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  char head[8] = {};
  in.read(head, 8);
  return in && std::string(head + 1, 3) == "PNG" && fs::file_size(p) > 5000;
}

bool python_with_h5py() {
  return std::system("/usr/bin/python3 -c 'import h5py' >/dev/null 2>&1") == 0;
}

// Sets an environment variable for one scope.
class ScopedEnv {
 public:
  ScopedEnv(const char* name, const char* value) : name_(name) {
    if (const char* old = std::getenv(name)) old_ = old, had_ = true;
    setenv(name, value, 1);
  }
  ~ScopedEnv() {
    if (had_)
      setenv(name_.c_str(), old_.c_str(), 1);
    else
      unsetenv(name_.c_str());
  }

 private:
  std::string name_, old_;
  bool had_ = false;
};

}  // namespace

TEST(FieldsCommand, OneRunWritesFieldsXdmfFiguresAndSummary) {
  test::ScratchDir tmp;
  const fs::path run = tmp.path() / "run";
  make_run(run, 12);
  ASSERT_TRUE(run_has_field_sums(run));
  ASSERT_EQ(fields_command({run}, {}, FieldsCommandOptions{true, true}), 0);

  for (const char* png :
       {"solid_fraction.png", "temperature.png", "mach.png", "stagnation_profiles.png"})
    EXPECT_TRUE(is_png(run / "figures" / png)) << png;

  // fields.xmf: every data item is a dataset of fields.h5 with the declared shape.
  const std::string xmf = read_text(run / "fields.xmf");
  const std::vector<DataItem> items = hdf_items(xmf);
  ASSERT_GE(items.size(), 25u);
  for (const DataItem& item : items)
    EXPECT_EQ(dataset_dimensions(run / "fields.h5", item.path), item.dimensions) << item.path;
  EXPECT_NE(xmf.find("TopologyType=\"2DSMesh\" Dimensions=\"31 21\""), std::string::npos);
  for (const char* name :
       {"\"phi\"", "\"T_norm\"", "\"Ma\"", "\"masked\"", "\"P_col_xx\"", "\"T_steel\""})
    EXPECT_NE(xmf.find(std::string("Attribute Name=") + name), std::string::npos) << name;
  if (python_with_h5py()) {
    const std::string check = "/usr/bin/python3 " GRANSHOCK_TEST_FIELDS_DIR
                              "/check_fields_xdmf.py '" +
                              (run / "fields.xmf").string() + "'";
    EXPECT_EQ(std::system(check.c_str()), 0) << check;
  }
  for (const char* dataset : {"/lines/sonic/points", "/lines/shock_threshold/offsets",
                              "/profile/phi", "/front/y_threshold", "/grid/x", "/grid/y"})
    EXPECT_NE(dataset_dimensions(run / "fields.h5", dataset), "missing") << dataset;

  // summary.json: the run's keys kept, the fields' keys added.
  const nlohmann::json j = nlohmann::json::parse(read_text(run / "summary.json"));
  EXPECT_EQ(j["steps"], 123);
  EXPECT_EQ(j["scene"], "synthetic");
  for (const char* key :
       {"ma_inf_target", "ma_inf_measured", "ma_inf_measured_downstream", "phi_inf_measured",
        "delta_over_D", "delta_over_D_err", "phi_peak", "shock_angle_deg", "eos_deviation_dilute",
        "eos_deviation_dense", "mass_definition"})
    EXPECT_TRUE(j.contains(key)) << key;
  EXPECT_DOUBLE_EQ(j["ma_inf_target"].get<double>(), 5.9);
  EXPECT_NEAR(j["ma_inf_measured"].get<double>(), 6.0, 1e-6);
  EXPECT_NEAR(j["ma_inf_measured_downstream"].get<double>(), 6.0, 1e-6);
  EXPECT_NEAR(j["phi_inf_measured"].get<double>(), 0.1, 1e-9);
  EXPECT_NEAR(j["phi_peak"].get<double>(), 0.4, 1e-9);
  // The V front's apex lies D/2 = 6 d upstream of the surface. The primary definition, the
  // temperature's half-rise, finds its upstream edge (a bin that holds a little of the slow,
  // dense state already has a high T); the density threshold finds the front smeared across
  // the 3 d strip (0.63 d further on): 5.37 d.
  EXPECT_EQ(j["delta_definition"], "temperature_jump");
  EXPECT_NEAR(j["delta_over_D"].get<double>(), 6.0 / 12.0, 0.5 / 12.0);
  EXPECT_NEAR(j["detachment"]["density_threshold"]["delta_over_D"].get<double>(),
              (6.0 - 0.63) / 12.0, 0.5 / 12.0);
  EXPECT_GT(j["delta_over_D_err"].get<double>(), 0.0);
  EXPECT_LT(j["delta_over_D_err"].get<double>(), 0.02);
  EXPECT_NEAR(j["shock_angle_deg"].get<double>(), 50.0, 3.0);
  // Both states obey the equation of state; only bins cut by the front mix them (and
  // their velocities, which adds temperature), so the means stay near 0.
  EXPECT_NEAR(j["eos_deviation_dilute"].get<double>(), 0.0, 0.02);
  EXPECT_NEAR(j["eos_deviation_dense"].get<double>(), 0.0, 0.05);
  EXPECT_GT(j["eos_bins_dense"].get<int>(), 10);
  EXPECT_EQ(j["mass_definition"], "mixture_mean");
}

TEST(FieldsCommand, SeveralRunsGiveTheDetachmentTableAndFigure) {
  test::ScratchDir tmp;
  make_run(tmp.path() / "d12", 12);
  make_run(tmp.path() / "d18", 18);
  const fs::path out = tmp.path() / "comparison";
  ASSERT_EQ(fields_command({tmp.path() / "d12", tmp.path() / "d18"}, out,
                           FieldsCommandOptions{true, true}),
            0);
  EXPECT_TRUE(is_png(out / "figures" / "detachment_length.png"));
  EXPECT_TRUE(is_png(tmp.path() / "d18" / "figures" / "mach.png"));
  const nlohmann::json table = nlohmann::json::parse(read_text(out / "detachment.json"));
  ASSERT_EQ(table.size(), 2u);
  EXPECT_DOUBLE_EQ(table[0]["D_over_d"].get<double>(), 12.0);
  EXPECT_DOUBLE_EQ(table[1]["D_over_d"].get<double>(), 18.0);
  for (const auto& row : table) {
    EXPECT_DOUBLE_EQ(row["ma_inf_target"].get<double>(), 5.9);
    EXPECT_NEAR(row["delta_over_D"].get<double>(), 0.45, 0.06);
  }
  const std::string csv = read_text(out / "detachment.csv");
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 3);
  EXPECT_EQ(csv.rfind("run,D_over_d,ma_inf_target,", 0), 0u);
}

TEST(FieldsCommand, RunWithoutObstacleHasNoDetachmentButFigures) {
  test::ScratchDir tmp;
  const fs::path run = tmp.path() / "free";
  const std::string scene = test::bow_shock_scene(0);
  const FieldPhysics phys = test::physics_of(scene);
  ASSERT_FALSE(phys.obstacle.has_value());
  BinSums grid = test::empty_sums(20, 30, 2, 0, 0, 3 * kD, 3 * kD);
  const test::BinState flow =
      test::mixture_state(phys, 0.1, test::temperature_for_mach(phys, 0.1, 1.0, 6.0), 0, 1.0);
  test::fill_with_front(
      grid, phys, flow, flow, [](double, double, int) { return false; }, 100, 2);
  test::write_run_file(run, scene, grid, nullptr);  // no profile: the axis column stands in
  ASSERT_EQ(fields_command({run}, {}, FieldsCommandOptions{true, true}), 0);
  EXPECT_TRUE(is_png(run / "figures" / "stagnation_profiles.png"));
  const nlohmann::json j = nlohmann::json::parse(read_text(run / "summary.json"));
  EXPECT_TRUE(j["delta_over_D"].is_null());
  EXPECT_TRUE(j["shock_angle_deg"].is_null());
  EXPECT_NEAR(j["ma_inf_measured"].get<double>(), 6.0, 1e-6);
  EXPECT_NEAR(j["ma_inf_target"].get<double>(), 5.9, 1e-9);  // from the inflow's sigma
}

TEST(FieldsCommand, BadInputEndsInOneUserError) {
  test::ScratchDir tmp;
  EXPECT_THROW(fields_command({}, {}), UserError);
  try {
    fields_command({tmp.path() / "nowhere"}, {});
    ADD_FAILURE() << "no run.h5 must be refused";
  } catch (const UserError& e) {
    EXPECT_NE(std::string(e.what()).find("run.h5"), std::string::npos) << e.what();
  }
  // A run file without field sums (a run that ended before its production window).
  const fs::path bare = tmp.path() / "bare";
  fs::create_directories(bare);
  const std::string scene = test::bow_shock_scene();
  RunFile::create(bare / "run.h5", scene, parse_scene(scene).resolved, 2);
  try {
    fields_command({bare}, {});
    ADD_FAILURE() << "a run without sums must be refused";
  } catch (const UserError& e) {
    EXPECT_NE(std::string(e.what()).find("no usable field sums at /fields/grid"), std::string::npos)
        << e.what();
  }
  EXPECT_FALSE(fs::exists(bare / "fields.h5"));
  EXPECT_FALSE(run_has_field_sums(bare));
  EXPECT_FALSE(run_has_field_sums(tmp.path() / "nowhere"));
  EXPECT_THROW(fields_command({bare, bare}, {}), UserError);  // several runs need --out
}

TEST(FieldsCommand, MissingMatplotlibCostsOnlyTheFigures) {
  test::ScratchDir tmp;
  const fs::path run = tmp.path() / "run";
  make_run(run, 12);
  ScopedEnv python("GRANSHOCK_PYTHON", "/nonexistent/python3");
  try {
    fields_command({run}, {}, FieldsCommandOptions{true, true});
    ADD_FAILURE() << "a missing interpreter must be reported";
  } catch (const UserError& e) {
    EXPECT_NE(std::string(e.what()).find("matplotlib"), std::string::npos) << e.what();
  }
  EXPECT_TRUE(fs::exists(run / "fields.h5"));
  EXPECT_TRUE(fs::exists(run / "fields.xmf"));
  EXPECT_FALSE(fs::exists(run / "figures" / "mach.png"));
  const nlohmann::json j = nlohmann::json::parse(read_text(run / "summary.json"));
  EXPECT_TRUE(j.contains("delta_over_D"));
}
