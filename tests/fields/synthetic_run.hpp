// Synthetic field sums for the tests of `granshock fields`: bins filled with the exact
// moments of known states (per species a Maxwellian of temperature T_a about a common mean
// velocity u, and an isotropic collisional pressure), a small bow-shock scene, and run.h5
// files written the way `granshock run` stores its sums (RunFile::write_array and
// write_attribute, layout of core/bin_layout.hpp).
#pragma once

#include <stdlib.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>
#include <vector>

#include "analysis/field_physics.hpp"
#include "core/bin_sums.hpp"
#include "core/kinetic_theory.hpp"
#include "io/field_sums_file.hpp"
#include "io/run_directory.hpp"
#include "io/run_file.hpp"
#include "io/scene_file.hpp"
#include "scene/scene_fixtures.hpp"

namespace granshock::test {

// A channel 60 d wide and 90 d long, the paper's mixture (steel and aluminium, d = 1 mm,
// e = 0.5, equimolar), U = 1 m/s at Ma_inf 5.9 and phi_inf = area_fraction, a cylinder of
// `diameter_d` d at (30 d, 60 d) (none when diameter_d = 0).
inline std::string bow_shock_scene(double diameter_d = 12, double mach = 5.9,
                                   double area_fraction = 0.1) {
  const std::string obstacle = diameter_d > 0
                                   ? "[obstacle]\ndiameter = \"" + std::to_string(diameter_d) +
                                         " d\"\ncentre = [\"30 d\", \"60 d\"]\n"
                                   : "";
  return obstacle + R"(
[scene]
name = "synthetic"
)" + granshock::testing::kPaperMixture +
         R"(
[contact]
restitution = 0.5
[domain]
width = "60 d"
length = "90 d"
[inflow]
area_fraction = )" +
         std::to_string(area_fraction) + R"(
velocity = 1.0
mach = )" +
         std::to_string(mach) + R"(
[time]
dt = 2e-7
duration = 0.01
production_start = 0.005
)";
}

inline FieldPhysics physics_of(const std::string& toml) {
  return field_physics_from_scene(parse_scene(toml).scene);
}

// The time-averaged state of a bin: per species number density (1/m^2) and temperature
// (J), the common mean velocity, and the collisional pressure (isotropic, N/m).
struct BinState {
  std::vector<double> n, temperature;
  double ux = 0, uy = 0;
  double p_col = 0;
};

inline BinSums empty_sums(int nx, int ny, int blocks, double x0, double y0, double dx, double dy,
                          int n_species = 2) {
  BinSums s;
  s.n_species = n_species;
  s.nx = nx;
  s.ny = ny;
  s.blocks = blocks;
  s.x0 = x0;
  s.y0 = y0;
  s.dx = dx;
  s.dy = dy;
  s.production_start = 0.005;
  s.production_end = 0.01;
  s.sums.assign(static_cast<std::size_t>(blocks) * nx * ny * s.quantities(), 0.0);
  s.samples.assign(static_cast<std::size_t>(blocks), 0.0);
  return s;
}

// Adds `weight` times the sums that `samples` samples of `state` give to bin (iy, ix) of
// `block` (a weight below 1: the state fills that fraction of the bin; sums are linear).
// N_a = n_a V S, sum c = N_a u, sum c_i c_j = N_a (u_i u_j + delta_ij T_a / m_a),
// W = p_col V S (identity), so that p_col = <W> / V.
inline void add_state(BinSums& s, int block, int iy, int ix, const BinState& st,
                      const FieldPhysics& phys, double samples, double weight = 1.0) {
  const BinLayout l = s.layout();
  auto at = [&](int q) -> double& {
    return s.sums[static_cast<std::size_t>(l.offset(block, iy, ix, q))];
  };
  const double volume = s.bin_area(iy) * samples * weight;
  for (int a = 0; a < s.n_species; ++a) {
    const double n = st.n[static_cast<std::size_t>(a)] * volume;
    const double c2 =
        st.temperature[static_cast<std::size_t>(a)] / phys.mass[static_cast<std::size_t>(a)];
    at(l.species_index(a, BinLayout::count)) += n;
    at(l.species_index(a, BinLayout::sum_vx)) += n * st.ux;
    at(l.species_index(a, BinLayout::sum_vy)) += n * st.uy;
    at(l.species_index(a, BinLayout::sum_vxvx)) += n * (st.ux * st.ux + c2);
    at(l.species_index(a, BinLayout::sum_vxvy)) += n * st.ux * st.uy;
    at(l.species_index(a, BinLayout::sum_vyvy)) += n * (st.uy * st.uy + c2);
  }
  at(l.virial_index(BinLayout::w_xx)) += st.p_col * volume;
  at(l.virial_index(BinLayout::w_yy)) += st.p_col * volume;
}

// An equimolar state of area fraction phi (diameters from the scene), both species at the
// same temperature T, obeying the equation of state p = n T F(phi) when eos is set.
inline BinState mixture_state(const FieldPhysics& phys, double phi, double temperature, double ux,
                              double uy, bool eos = true) {
  BinState st;
  double disk = 0;
  for (double d : phys.diameter) disk += 0.5 * M_PI * d * d / 4;
  const double n_total = phi / disk;
  st.n = {0.5 * n_total, 0.5 * n_total};
  st.temperature = {temperature, temperature};
  st.ux = ux;
  st.uy = uy;
  if (eos)
    st.p_col = n_total * temperature * (pressure_factor(phi, phys.restitution, phys.dim) - 1);
  return st;
}

// The temperature that gives Mach number `mach` at speed u in an equimolar state of area
// fraction phi (mixture-mean mass).
inline double temperature_for_mach(const FieldPhysics& phys, double phi, double speed,
                                   double mach) {
  const double m = 0.5 * (phys.mass[0] + phys.mass[1]);
  const double a = speed / mach;
  return a * a * m / sound_speed_factor(phi, phys.restitution, phys.dim);
}

// Fills every bin of every block with a mixture of two states split by a front: the
// fraction of the bin (sampled on sub x sub points) where behind(x, y, block) holds gets
// `post`, the rest `pre`; points inside the cylinder get nothing. samples_per_block for
// every block.
inline void fill_with_front(BinSums& s, const FieldPhysics& phys, const BinState& pre,
                            const BinState& post,
                            const std::function<bool(double, double, int)>& behind,
                            double samples_per_block, int sub = 8) {
  for (int b = 0; b < s.blocks; ++b) {
    s.samples[static_cast<std::size_t>(b)] = samples_per_block;
    for (int iy = 0; iy < s.ny; ++iy) {
      for (int ix = 0; ix < s.nx; ++ix) {
        double f_pre = 0, f_post = 0;
        for (int j = 0; j < sub; ++j) {
          for (int i = 0; i < sub; ++i) {
            const double x = s.x0 + (ix + (i + 0.5) / sub) * s.dx,
                         y = s.y0 + (iy + (j + 0.5) / sub) * s.dy;
            if (phys.obstacle && std::hypot(x - phys.obstacle->xc, y - phys.obstacle->yc) <
                                     0.5 * phys.obstacle->width)
              continue;
            (behind(x, y, b) ? f_post : f_pre) += 1.0 / (sub * sub);
          }
        }
        if (f_pre > 0) add_state(s, b, iy, ix, pre, phys, samples_per_block, f_pre);
        if (f_post > 0) add_state(s, b, iy, ix, post, phys, samples_per_block, f_post);
      }
    }
  }
}

// The sums of a bow shock in front of the cylinder of bow_shock_scene(diameter_d) at
// (30 d, 60 d): upstream phi_up at Ma 6; behind a V-shaped front (apex D/2 ahead of the
// surface plus apex_shift, flanks at 50 deg to +y) phi 0.4 at Ma 0.5. The grid has 3 d bins
// over the 60 d x 90 d channel, the stagnation-line profile is 3 d wide with 0.5 d bins;
// `blocks` blocks of samples_per_block samples, block b's front shifted by a few tenths of d.
struct BowShockSums {
  BinSums grid, profile;
};
inline BowShockSums bow_shock_sums(const FieldPhysics& phys, double diameter_d, int blocks,
                                   double samples_per_block, double phi_up = 0.1,
                                   double apex_shift = 0) {
  constexpr double d = 1e-3;
  const double surface = 60 * d - 0.5 * diameter_d * d;
  const double apex = surface - 0.5 * diameter_d * d + apex_shift;
  const double cot_beta = 1.0 / std::tan(50.0 * M_PI / 180.0);
  const std::vector<double> shifts{0.2 * d, -0.3 * d, 0.1 * d, -0.1 * d};
  auto behind = [&](double x, double y, int b) {
    return y > apex + shifts[static_cast<std::size_t>(b) % shifts.size()] +
                   std::abs(x - 30 * d) * cot_beta;
  };
  const BinState pre =
      mixture_state(phys, phi_up, temperature_for_mach(phys, phi_up, 1.0, 6.0), 0, 1.0);
  const BinState post =
      mixture_state(phys, 0.4, temperature_for_mach(phys, 0.4, 0.2, 0.5), 0.02, 0.2);
  BowShockSums s{empty_sums(20, 30, blocks, 0, 0, 3 * d, 3 * d),
                 empty_sums(1, 180, blocks, 28.5 * d, 0, 3 * d, 0.5 * d)};
  fill_with_front(s.grid, phys, pre, post, behind, samples_per_block, 6);
  fill_with_front(s.profile, phys, pre, post, behind, samples_per_block, 6);
  return s;
}

// Marks dir as a run directory, as `granshock run` does first (io/run_directory.hpp).
inline void mark_run_directory(const std::filesystem::path& dir) {
  std::filesystem::create_directories(dir);
  std::ofstream(dir / kRunMarker) << "granshock run directory\nformat = " << kRunDirectoryFormat
                                  << "\n";
}

// Writes run.h5 in dir, marked as a run directory, with the scene and the sums, as
// `granshock run` stores them.
inline void write_run_file(const std::filesystem::path& dir, const std::string& scene_toml,
                           const BinSums& grid, const BinSums* profile) {
  mark_run_directory(dir);
  const LoadedScene loaded = parse_scene(scene_toml);
  RunFile run = RunFile::create(dir / "run.h5", scene_toml, loaded.resolved, 2);
  FieldSumsRecord record;
  record.sampling.grid = grid.layout();
  record.grid_sums = grid.sums;
  if (profile != nullptr) {
    record.sampling.profile = profile->layout();
    record.profile_sums = profile->sums;
  }
  for (double n : grid.samples) record.samples.push_back(static_cast<long>(n));
  record.production_start = grid.production_start;
  record.production_end = grid.production_end;
  record.y_end = grid.y_end;
  write_field_sums(run, record);
  run.flush();
}

// A fresh temporary directory, removed with its contents (kept, for a look at the files
// and figures, when GRANSHOCK_KEEP_TEST_DIRS is set).
class ScratchDir {
 public:
  ScratchDir() {
    std::string pattern =
        (std::filesystem::temp_directory_path() / "granshock-fields-XXXXXX").string();
    path_ = mkdtemp(pattern.data());
  }
  ~ScratchDir() {
    if (std::getenv("GRANSHOCK_KEEP_TEST_DIRS") != nullptr) return;
    std::error_code ec;
    std::filesystem::remove_all(path_, ec);
  }
  ScratchDir(const ScratchDir&) = delete;
  ScratchDir& operator=(const ScratchDir&) = delete;
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

}  // namespace granshock::test
