// Small scenes for the tests of `granshock run`, as TOML text, and helpers to write
// them to a temporary directory.
#pragma once

#include <unistd.h>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>

namespace granshock::testing {

// The paper's mixture as scene TOML: d = 1 mm, steel and aluminium spheres, half each.
inline const std::string kPaperMixture = R"(
[units]
d = 0.001
[[species]]
name = "steel"
material = "steel"
diameter = "1 d"
number_fraction = 0.5
[[species]]
name = "aluminium"
material = "aluminium"
diameter = "1 d"
number_fraction = 0.5
)";

// A channel 40 d wide and 60 d long with the paper's mixture; `obstacle` adds a
// cylinder of 10 d at (20 d, 35 d). Short: 0.01 s at dt = 2e-7 s (50 000 steps).
inline std::string small_scene(bool obstacle = true, double restitution = 0.5) {
  std::string s = R"(
[scene]
name = "small"
seed = 7
)" + kPaperMixture +
                  R"(
[contact]
restitution = )" + std::to_string(restitution) +
                  R"(
[domain]
width = "40 d"
length = "60 d"
[inflow]
area_fraction = 0.1
velocity = 1.0
sigma = 0.1
[time]
dt = 2e-7
duration = 0.01
production_start = 0.005
[output]
snapshot_interval = 0.0025
series_interval = 0.0005
checkpoint_interval = 0.004
progress_interval = 1000.0
)";
  if (obstacle) s += "[obstacle]\ndiameter = \"10 d\"\ncentre = [\"20 d\", \"35 d\"]\n";
  return s;
}

// small_scene without an obstacle whose inflow asks for the paper's Ma 13.7 at the inlet
// rows (inflow.mach_at = "inlet_bins"): a wide, fast inflow that keeps the inlet
// calibration's channel runs short (about 0.08 s simulated each).
inline std::string fast_inlet_scene() {
  std::string text = small_scene(false);
  const auto replace = [&](const std::string& from, const std::string& to) {
    const std::size_t at = text.find(from);
    if (at == std::string::npos) throw std::logic_error("fast_inlet_scene: no " + from);
    text.replace(at, from.size(), to);
  };
  replace("sigma = 0.1", "mach = 13.7\nmach_at = \"inlet_bins\"");
  replace("velocity = 1.0", "velocity = 2.375");
  replace("width = \"40 d\"", "width = \"300 d\"");
  replace("dt = 2e-7", "dt = 4e-7");
  return text + "[numerics]\nmass_definition = \"paper_sum\"\n";
}

// A fresh, empty temporary directory, removed with its contents on destruction.
class TempDir {
 public:
  TempDir() {
    std::string pattern =
        (std::filesystem::temp_directory_path() / "granshock-test-XXXXXX").string();
    path_ = mkdtemp(pattern.data());
  }
  ~TempDir() {
    std::error_code ec;
    std::filesystem::remove_all(path_, ec);
  }
  const std::filesystem::path& path() const { return path_; }
  std::filesystem::path write(const std::string& name, const std::string& text) const {
    const auto p = path_ / name;
    std::ofstream(p) << text;
    return p;
  }

 private:
  std::filesystem::path path_;
};

}  // namespace granshock::testing
