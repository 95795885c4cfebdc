// docs/fields.md: `granshock fields` on small synthetic run
// directories writes fields.h5, a fields.xmf whose every data item points at an existing
// dataset of the declared shape, the figures (PNG) and the summary keys; several
// directories also give the detachment table and figure (the paper's Fig. 6); bad input
// ends in one UserError and a missing matplotlib costs only the figures.
#include <gtest/gtest.h>
#include <hdf5.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <map>
#include <nlohmann/json.hpp>
#include <regex>
#include <sstream>

#include "analysis/fields_command.hpp"
#include "analysis/figures.hpp"
#include "analysis/run_analysis.hpp"
#include "core/user_error.hpp"
#include "io/fields_directory.hpp"
#include "synthetic_run.hpp"

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

// `granshock run` ends with the analysis library's analyse_finished_run, not the fields
// command: both write the same summary keys (and the same warnings) for the same run.
TEST(FieldsCommand, FinishedRunAnalysisWritesWhatTheCommandWrites) {
  test::ScratchDir tmp;
  const fs::path by_command = tmp.path() / "command", by_library = tmp.path() / "library";
  make_run(by_command, 12);
  make_run(by_library, 12);
  ASSERT_EQ(fields_command({by_command}, {}, FieldsCommandOptions{false, true}), 0);
  std::vector<std::string> said;
  const AnalysedRun done = analyse_finished_run(
      by_library, false, [&](const std::string& line) { said.push_back(line); });

  EXPECT_EQ(done.dest, by_library);
  EXPECT_TRUE(fs::exists(by_library / "fields.h5"));
  EXPECT_TRUE(fs::exists(by_library / "fields.xmf"));
  EXPECT_FALSE(fs::exists(by_library / "figures" / "mach.png"));  // figures not asked for
  nlohmann::json command = nlohmann::json::parse(read_text(by_command / "summary.json"));
  nlohmann::json library = nlohmann::json::parse(read_text(by_library / "summary.json"));
  ASSERT_TRUE(library.contains("delta_over_D"));
  // The warnings name their run's directory; the rest is the same, key for key.
  EXPECT_EQ(command["warnings"].size(), library["warnings"].size());
  EXPECT_EQ(said.size(), done.data_warnings().size());
  command.erase("warnings");
  library.erase("warnings");
  EXPECT_EQ(command, library);
  EXPECT_NE(done.result_line().find("delta/D = "), std::string::npos);
}

TEST(FieldsCommand, OneRunWritesFieldsXdmfFiguresAndSummary) {
  test::ScratchDir tmp;
  const fs::path run = tmp.path() / "run";
  make_run(run, 12);
  ASSERT_TRUE(run_has_field_sums(run));
  ASSERT_EQ(fields_command({run}, {}, FieldsCommandOptions{true, true}), 0);

  for (const char* png :
       {"solid_fraction.png", "temperature.png", "mach.png", "stagnation_profiles.png"})
    EXPECT_TRUE(is_png(run / "figures" / png)) << png;
  // What the figures say: each front named by its definition, the primary one drawn, a
  // colour-bar tick at Ma = 1, no note over the x label, the profile's fronts in view.
  if (python_with_h5py()) {
    const std::string check = "/usr/bin/python3 " GRANSHOCK_TEST_FIELDS_DIR
                              "/check_figure_content.py '" +
                              (run / "fields.h5").string() + "' " GRANSHOCK_SOURCE_DIR "/analysis";
    EXPECT_EQ(std::system(check.c_str()), 0) << check;
  }

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
  for (const char* dataset :
       {"/lines/sonic/points", "/lines/shock_threshold/offsets", "/lines/shock_temperature/points",
        "/front/y_temperature", "/profile/phi", "/front/y_threshold", "/grid/x", "/grid/y"})
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
  // Each run's figures, both drawn by one call of plot_fields.py.
  for (const char* run : {"d12", "d18"})
    for (const char* png :
         {"solid_fraction.png", "temperature.png", "mach.png", "stagnation_profiles.png"})
      EXPECT_TRUE(is_png(tmp.path() / run / "figures" / png)) << run << "/" << png;
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
  test::mark_run_directory(bare);
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

// ---- Directories (docs/output_format.md, "The run directory", "The fields directory"):
// `fields` writes only into a run directory granshock marked, under its lock, or into an
// --out that is new, empty or its own; never through a symbolic link; and it refuses
// before writing anything.

namespace {

// Every entry below `dir` (not following links) with its content, or "->target" for links.
std::map<std::string, std::string> tree(const fs::path& dir) {
  std::map<std::string, std::string> out;
  for (auto it = fs::recursive_directory_iterator(dir); it != fs::recursive_directory_iterator();
       ++it) {
    const std::string rel = fs::relative(it->path(), dir).string();
    if (it->is_symlink())
      out[rel] = "->" + fs::read_symlink(it->path()).string();
    else if (it->is_regular_file())
      out[rel] = read_text(it->path());
    else
      out[rel] = "(dir)";
  }
  return out;
}

std::string refusal(const std::function<void()>& f) {
  try {
    f();
  } catch (const UserError& e) {
    return e.what();
  }
  return "(accepted)";
}

const FieldsCommandOptions kNoFigures{false, true};

}  // namespace

TEST(FieldsCommandOut, RefusesADirectoryThatIsNotItsOwnAndLeavesItUntouched) {
  test::ScratchDir tmp;
  const fs::path run = tmp.path() / "run";
  make_run(run, 12);
  // A home directory with files of the names `fields` writes.
  const fs::path home = tmp.path() / "home";
  fs::create_directories(home / "figures");
  for (const char* name :
       {"fields.h5", "figures/mach.png", "detachment_convergence.csv", "summary.json", "notes.txt"})
    std::ofstream(home / name) << "the user's " << name;
  const auto before = tree(home);
  std::string why = refusal([&] { fields_command({run}, home, kNoFigures); });
  EXPECT_NE(why.find("is not empty and was not written by granshock fields"), std::string::npos)
      << why;
  EXPECT_EQ(tree(home), before);
  // Nor the comparison of several runs.
  make_run(tmp.path() / "run2", 18);
  why = refusal([&] { fields_command({run, tmp.path() / "run2"}, home, kNoFigures); });
  EXPECT_NE(why.find("is not empty and was not written by granshock fields"), std::string::npos)
      << why;
  EXPECT_EQ(tree(home), before);
  // Another run's directory is that run's: its fields are its own.
  const auto other = tree(tmp.path() / "run2");
  why = refusal([&] { fields_command({run}, tmp.path() / "run2", kNoFigures); });
  EXPECT_NE(why.find("is a granshock run directory"), std::string::npos) << why;
  EXPECT_EQ(tree(tmp.path() / "run2"), other);
  // A study directory takes a comparison, not one run's analysis.
  fs::create_directories(tmp.path() / "study");
  std::ofstream(tmp.path() / "study" / kStudyMarker) << "format = 1\nstudy = s\n";
  why = refusal([&] { fields_command({run}, tmp.path() / "study", kNoFigures); });
  EXPECT_NE(why.find("is a granshock study directory"), std::string::npos) << why;
  EXPECT_EQ(refusal([&] {
              fields_command({run, tmp.path() / "run2"}, tmp.path() / "study", kNoFigures);
            }),
            "(accepted)");
  EXPECT_TRUE(fs::exists(tmp.path() / "study" / "detachment.csv"));
}

TEST(FieldsCommandOut, MarksANewDirectoryAndStartsItsSummaryFromTheRuns) {
  test::ScratchDir tmp;
  const fs::path run = tmp.path() / "run";
  make_run(run, 12);
  const auto run_before = tree(run);
  const fs::path out = tmp.path() / "out";
  ASSERT_EQ(fields_command({run}, out, kNoFigures), 0);
  EXPECT_NE(read_text(out / kFieldsMarker).find("format = 1"), std::string::npos);
  EXPECT_EQ(tree(run), run_before) << "the run directory is only read";
  nlohmann::json j = nlohmann::json::parse(read_text(out / "summary.json"));
  EXPECT_EQ(j["steps"], 123);
  EXPECT_TRUE(j.contains("delta_over_D"));
  // Again into its own directory, with a user's file beside: replaced, the file kept;
  // the summary is the run's again, not the previous one's.
  std::ofstream(out / "notes.txt") << "mine";
  std::ofstream(out / "summary.json") << R"({"stale": 1})";
  ASSERT_EQ(fields_command({run}, out, kNoFigures), 0);
  EXPECT_EQ(read_text(out / "notes.txt"), "mine");
  j = nlohmann::json::parse(read_text(out / "summary.json"));
  EXPECT_FALSE(j.contains("stale"));
  EXPECT_EQ(j["steps"], 123);
  // --out naming the run directory itself is `granshock fields DIR`.
  EXPECT_EQ(refusal([&] { fields_command({run}, run, kNoFigures); }), "(accepted)");
  EXPECT_FALSE(fs::exists(run / kFieldsMarker));
}

TEST(FieldsCommandRefuses, ARunDirectoryWithoutItsMarker) {
  test::ScratchDir tmp;
  const fs::path run = tmp.path() / "run";
  make_run(run, 12);
  fs::remove(run / kRunMarker);
  const auto before = tree(run);
  const std::string why = refusal([&] { fields_command({run}, {}, kNoFigures); });
  EXPECT_NE(why.find("is not a granshock run directory"), std::string::npos) << why;
  EXPECT_NE(why.find("--out"), std::string::npos) << why;
  EXPECT_EQ(tree(run), before);
  // Read from there, written elsewhere: fine.
  EXPECT_EQ(refusal([&] { fields_command({run}, tmp.path() / "out", kNoFigures); }), "(accepted)");
  EXPECT_EQ(tree(run), before);
}

// `fields DIR` read run.h5 before it took the lock, and `run --overwrite` started meanwhile
// replaced the run under it: both exited 0 and DIR held the new run with the old fields.
// The lock is held from before the first read, exclusively in place, shared for --out.
TEST(FieldsCommandHolds, TheRunDirectoryFromBeforeItsFirstRead) {
  test::ScratchDir tmp;
  const fs::path run = tmp.path() / "run", other = tmp.path() / "other";
  make_run(run, 12);
  make_run(other, 12);
  std::vector<std::string> seen;
  FieldsCommandOptions o = kNoFigures;
  o.before_read = [&](const fs::path& dir) {
    // A run started now, as another process: refused, and with it its --overwrite.
    try {
      RunDirectory::check(dir, DirectoryMode::overwrite);
      seen.push_back("(a run was accepted)");
    } catch (const UserError& e) {
      seen.push_back(e.what());
    }
  };
  ASSERT_EQ(fields_command({run}, {}, o), 0);
  ASSERT_EQ(fields_command({run}, tmp.path() / "out", o), 0);
  ASSERT_EQ(fields_command({run, other}, tmp.path() / "both", o), 0);
  ASSERT_EQ(seen.size(), 4u);
  for (const std::string& why : seen)
    EXPECT_NE(why.find("is in use by another granshock run or fields command"), std::string::npos)
        << why;
  // Readers share: a second `fields RUN --out` reads while the first does.
  const DirectoryLock reading = DirectoryLock::hold(run, kRunMarker, LockKind::shared);
  EXPECT_EQ(refusal([&] { fields_command({run}, tmp.path() / "out2", kNoFigures); }), "(accepted)");
  const std::string why = refusal([&] { fields_command({run}, {}, kNoFigures); });
  EXPECT_NE(why.find("is in use by another granshock"), std::string::npos) << why;
}

TEST(FieldsCommandRefuses, ADirectoryAnotherGranshockHolds) {
  test::ScratchDir tmp;
  const fs::path run = tmp.path() / "run";
  make_run(run, 12);
  const fs::path out = tmp.path() / "out";
  ASSERT_EQ(fields_command({run}, out, kNoFigures), 0);
  const auto run_before = tree(run);
  const auto out_before = tree(out);
  {
    // A run in progress (its lock is per open file, so a claim in this process stands
    // for another one): neither analysed in place nor read for --out.
    const RunDirectory running = RunDirectory::claim(run, DirectoryMode::fields);
    std::string why = refusal([&] { fields_command({run}, {}, kNoFigures); });
    EXPECT_NE(why.find("is in use by another granshock"), std::string::npos) << why;
    why = refusal([&] { fields_command({run}, out, kNoFigures); });
    EXPECT_NE(why.find("is in use by another granshock run"), std::string::npos) << why;
    auto after = tree(run);
    after.erase(kRunMarker);  // names the last claimant's pid
    auto expected = run_before;
    expected.erase(kRunMarker);
    EXPECT_EQ(after, expected);
    EXPECT_EQ(tree(out), out_before);
    // The run itself analyses its own directory under its own lock (analyse_finished_run,
    // which takes no lock: the caller holds it).
    EXPECT_EQ(refusal([&] { analyse_finished_run(run, false, [](const std::string&) {}); }),
              "(accepted)");
    EXPECT_TRUE(fs::exists(run / "fields.h5"));
  }
  {
    // Another `granshock fields` writing the same --out.
    const FieldsDirectory writing = FieldsDirectory::claim(out, FieldsOutput::one_run);
    const std::string why = refusal([&] { fields_command({run}, out, kNoFigures); });
    EXPECT_NE(why.find("is in use by another granshock"), std::string::npos) << why;
    auto out_now = tree(out);
    out_now.erase(kFieldsMarker);
    auto out_expected = out_before;
    out_expected.erase(kFieldsMarker);
    EXPECT_EQ(out_now, out_expected);
  }
  EXPECT_EQ(refusal([&] { fields_command({run}, out, kNoFigures); }), "(accepted)");
}

TEST(FieldsCommandRefuses, EveryOutputNamePlantedAsASymbolicLink) {
  test::ScratchDir tmp;
  const fs::path outside = tmp.path() / "outside.txt";
  std::ofstream(outside) << "the user's file";
  const fs::path user_dir = tmp.path() / "user";
  fs::create_directories(user_dir);
  std::ofstream(user_dir / "mach.png") << "the user's figure";
  const auto user_before = tree(user_dir);
  make_run(tmp.path() / "run", 12);
  make_run(tmp.path() / "run2", 18);
  const fs::path out = tmp.path() / "out";
  const fs::path comparison = tmp.path() / "comparison";
  ASSERT_EQ(fields_command({tmp.path() / "run"}, out, kNoFigures), 0);
  ASSERT_EQ(fields_command({tmp.path() / "run", tmp.path() / "run2"}, comparison, kNoFigures), 0);
  // Where each list is written: the run directory itself, --out for one run, --out for
  // a comparison.
  struct Case {
    fs::path dir;
    std::vector<std::string> names;
    std::function<void()> command;
  };
  const std::vector<Case> cases = {
      {tmp.path() / "run", fields_outputs(),
       [&] { fields_command({tmp.path() / "run"}, {}, kNoFigures); }},
      {out, fields_outputs(), [&] { fields_command({tmp.path() / "run"}, out, kNoFigures); }},
      {comparison, comparison_outputs(), [&] {
         fields_command({tmp.path() / "run", tmp.path() / "run2"}, comparison, kNoFigures);
       }}};
  for (const Case& c : cases) {
    std::vector<std::string> names = c.names;
    names.push_back("figures");
    for (const std::string& name : names) {
      const fs::path planted = c.dir / name;
      const fs::path saved = tmp.path() / "saved";
      fs::remove_all(saved);
      if (fs::exists(fs::symlink_status(planted))) fs::rename(planted, saved);
      fs::create_directories(planted.parent_path());
      fs::create_symlink(name == "figures" ? user_dir : outside, planted);
      const std::string why = refusal(c.command);
      EXPECT_NE(why.find("'" + planted.string() + "' is a symbolic link"), std::string::npos)
          << planted << ": " << why;
      EXPECT_EQ(read_text(outside), "the user's file") << planted;
      EXPECT_EQ(tree(user_dir), user_before) << planted;
      fs::remove(planted);
      if (fs::exists(fs::symlink_status(saved))) fs::rename(saved, planted);
    }
    EXPECT_EQ(refusal(c.command), "(accepted)") << c.dir;
  }
}

TEST(FieldsCommandRefuses, ASummaryThatIsNotJsonBeforeWritingAnything) {
  test::ScratchDir tmp;
  const fs::path run = tmp.path() / "run";
  make_run(run, 12);
  ASSERT_EQ(fields_command({run}, {}, kNoFigures), 0);
  std::ofstream(run / "summary.json") << "nope{";
  const auto before = tree(run);
  std::string why = refusal([&] { fields_command({run}, {}, kNoFigures); });
  EXPECT_NE(why.find("summary.json' is not valid JSON"), std::string::npos) << why;
  EXPECT_EQ(tree(run), before) << "fields.h5, fields.xmf or the CSV was rewritten";
  why = refusal([&] { fields_command({run}, tmp.path() / "out", kNoFigures); });
  EXPECT_NE(why.find("summary.json' is not valid JSON"), std::string::npos) << why;
  EXPECT_FALSE(fs::exists(tmp.path() / "out"));
  std::ofstream(run / "summary.json", std::ios::trunc) << "[1, 2]";
  why = refusal([&] { fields_command({run}, {}, kNoFigures); });
  EXPECT_NE(why.find("does not hold a JSON object"), std::string::npos) << why;
}

// plot_fields.py on its own (as an installed script is run by hand, or if a link appears
// after granshock looked): it never writes through a link either.
TEST(FigureFiles, ThePlottingScriptNeverWritesThroughALink) {
  if (!python_with_h5py()) GTEST_SKIP() << "no /usr/bin/python3 with h5py";
  test::ScratchDir tmp;
  const fs::path run = tmp.path() / "run";
  make_run(run, 12);
  ASSERT_EQ(fields_command({run}, {}, kNoFigures), 0);
  const fs::path outside = tmp.path() / "outside.txt";
  std::ofstream(outside) << "the user's file";
  const fs::path user_dir = tmp.path() / "user";
  fs::create_directories(user_dir);
  const auto plot = [&](const fs::path& figures) {
    const std::string command = "/usr/bin/python3 '" + figure_script("plot_fields.py").string() +
                                "' '" + (run / "fields.h5").string() + "' '" + figures.string() +
                                "' 2>/dev/null";
    return std::system(command.c_str());
  };
  // The figures directory is a link: refused, nothing written there.
  fs::create_symlink(user_dir, run / "linked");
  EXPECT_NE(plot(run / "linked"), 0);
  EXPECT_TRUE(fs::is_empty(user_dir));
  // A link as a temporary: refused, its target unchanged.
  fs::create_directories(run / "figures");
  fs::create_symlink(outside, run / "figures" / "mach.png.tmp");
  EXPECT_NE(plot(run / "figures"), 0);
  EXPECT_EQ(read_text(outside), "the user's file");
  // A link as the figure: replaced by the figure, its target unchanged; a stale
  // temporary that is a file is replaced.
  fs::remove(run / "figures" / "mach.png.tmp");
  std::ofstream(run / "figures" / "temperature.png.tmp") << "left by a killed run";
  fs::create_symlink(outside, run / "figures" / "mach.png");
  EXPECT_EQ(plot(run / "figures"), 0);
  EXPECT_EQ(read_text(outside), "the user's file");
  EXPECT_TRUE(is_png(run / "figures" / "mach.png"));
  EXPECT_FALSE(fs::is_symlink(run / "figures" / "mach.png"));
  EXPECT_TRUE(is_png(run / "figures" / "temperature.png"));
  EXPECT_FALSE(fs::exists(run / "figures" / "temperature.png.tmp"));
}
