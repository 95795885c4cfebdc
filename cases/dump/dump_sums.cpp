#include "cases/dump/dump_sums.hpp"

#include <fmt/format.h>

#include <cmath>
#include <sstream>

#include "analysis/field_sampling_check.hpp"
#include "cases/bow_shock/sampling_plan.hpp"
#include "core/available_memory.hpp"
#include "core/user_error.hpp"
#include "kernels/sampling/bin_accumulator.hpp"

namespace granshock {

namespace {

BinSums empty_sums(const BinLayout& l, const Scene& scene) {
  if (scene.setup.dim != 2)
    throw UserError(
        "granshock from-dump: the scene is 3-D; a dump's sums are binned for "
        "quasi-2-D scenes (scene.dim = 2) only");
  BinSums s;
  s.n_species = l.n_species;
  s.nx = l.nx;
  s.ny = l.ny;
  s.blocks = l.blocks;
  s.x0 = l.x0;
  s.y0 = l.y0;
  s.dx = l.dx;
  s.dy = l.dy;
  s.x_period = l.x_period;
  // As a run records its sums (io/field_sums_file.hpp).
  s.y_end = scene.setup.box.hi[1];
  s.production_start = scene.run.production_start_s;
  s.production_end = scene.run.duration_s;
  s.sums.assign(static_cast<std::size_t>(l.blocks) * l.bins() * l.quantities(), 0.0);
  s.samples.assign(static_cast<std::size_t>(l.blocks), 0.0);
  return s;
}

// x wrapped into the periodic domain [lo, hi), as the solver keeps its particles: a dump's
// x may lie a little outside between LAMMPS' re-neighbourings, and xu anywhere.
double wrapped_x(double x, const Box& box) {
  if (!box.periodic[0] || (x >= box.lo[0] && x < box.hi[0])) return x;
  const double w = box.length(0);
  double r = x - w * std::floor((x - box.lo[0]) / w);
  if (r >= box.hi[0]) r = box.lo[0];
  return r;
}

// The moments of one particle of species a into bin `bin` of block `block`
// (SampleContribution::add_to_bin in kernels/sampling/bin_accumulator.hpp).
void add_moments(BinSums& s, int block, int bin, int a, double vx, double vy) {
  const BinLayout l = s.layout();
  const long base = l.offset(block, bin / s.nx, bin % s.nx, l.species_index(a, BinLayout::count));
  double* q = &s.sums[static_cast<std::size_t>(base)];
  q[BinLayout::count] += 1.0;
  q[BinLayout::sum_vx] += vx;
  q[BinLayout::sum_vy] += vy;
  q[BinLayout::sum_vxvx] += vx * vx;
  q[BinLayout::sum_vxvy] += vx * vy;
  q[BinLayout::sum_vyvy] += vy * vy;
}

std::string seconds(double t) {
  std::ostringstream s;
  s.precision(6);
  s << t << " s";
  return s.str();
}

// Particles at more than one z, or moving along z: more than a quasi-2-D layer. A
// spread below a millionth of the box's thickness is round-off of a layer written at z=0.
bool is_three_dimensional(const DumpFrame& f) {
  const double thickness = f.box_hi[2] - f.box_lo[2];
  return (f.has_z && f.z_max - f.z_min > 1e-6 * thickness) || f.vz_max_abs > 0;
}

bool same_box(const DumpFrame& a, const DumpFrame& b) {
  for (int k = 0; k < 3; ++k)
    if (a.box_lo[k] != b.box_lo[k] || a.box_hi[k] != b.box_hi[k]) return false;
  return true;
}

std::string box_text(const DumpFrame& f) {
  std::ostringstream s;
  s.precision(17);
  s << "[" << f.box_lo[0] << ", " << f.box_hi[0] << "] x [" << f.box_lo[1] << ", " << f.box_hi[1]
    << "] x [" << f.box_lo[2] << ", " << f.box_hi[2] << "]";
  return s.str();
}

// The map's domain is the dump's box in x and y: a map of another width would fold x into
// its own period, and a dump in other units (mm) would bin nothing where it should. Checked
// on the first frame; every later frame has its box (sum_dump_frames).
void check_box_against_map(const DumpFrame& f, const Box& box) {
  for (int k = 0; k < 2; ++k) {
    const double length = box.length(k);
    const double tolerance = 1e-6 * length;
    if (std::abs(f.box_lo[k] - box.lo[k]) <= tolerance &&
        std::abs(f.box_hi[k] - box.hi[k]) <= tolerance)
      continue;
    throw UserError(fmt::format(
        "the frame at {} has the box {} = [{:.17g}, {:.17g}] m, the map's scene [{:.17g}, "
        "{:.17g}] m (domain.{}): granshock bins the map's domain, so the dump's box must be it, "
        "in metres (SI units, as LAMMPS' units si writes them)",
        f.where, "xy"[k], f.box_lo[k], f.box_hi[k], box.lo[k], box.hi[k],
        k == 0 ? "width" : "length"));
  }
}

// Called after add_dump_frame, which refuses unknown types.
double kinetic_energy(const DumpFrame& f, const DumpMap& map) {
  double e = 0;
  for (std::size_t i = 0; i < f.size(); ++i) {
    const int a = map.species_of_type.at(f.type[i]);
    const double m = map.scene.scene.setup.species[static_cast<std::size_t>(a)].mass_kg();
    e += 0.5 * m * (f.vx[i] * f.vx[i] + f.vy[i] * f.vy[i]);
  }
  return e;
}

}  // namespace

void add_dump_frame(const DumpFrame& f, const DumpMap& map, int block, BinSums& grid,
                    std::optional<BinSums>& profile) {
  const Box& box = map.scene.scene.setup.box;
  const GridIndex grid_index = GridIndex::of(grid.layout());
  std::optional<GridIndex> profile_index;
  if (profile) profile_index = GridIndex::of(profile->layout());
  for (std::size_t i = 0; i < f.size(); ++i) {
    const auto species = map.species_of_type.find(f.type[i]);
    if (species == map.species_of_type.end())
      throw UserError("the frame at " + f.where + " has atom " + std::to_string(f.id[i]) +
                      " of type " + std::to_string(f.type[i]) +
                      ", which the map's [dump.types] does not name");
    if (block < 0) continue;  // outside the production window: checked only
    const double x = wrapped_x(f.x[i], box), y = f.y[i];
    int row = 0;
    const int bin = grid_index(x, y, row);
    if (bin >= 0) add_moments(grid, block, bin, species->second, f.vx[i], f.vy[i]);
    if (profile_index) {
      const int pbin = (*profile_index)(x, y, row);
      if (pbin >= 0) add_moments(*profile, block, pbin, species->second, f.vx[i], f.vy[i]);
    }
  }
  if (block < 0) return;
  grid.samples[static_cast<std::size_t>(block)] += 1;
  if (profile) profile->samples[static_cast<std::size_t>(block)] += 1;
}

void check_dump_analysis_fits(const Scene& scene) {
  // The map's bins as a run's are checked (at least a particle wide, enough of them across
  // the obstacle, at most 1 GiB of sums), which also keeps every count below an int's range.
  validate_bins(scene);
  // Every block's sums, and the analysis's few copies of them (as a run's final analysis:
  // cases/bow_shock/run_memory.hpp), against what this process may take.
  const FieldSampling layout = SamplingPlan(scene).layout();
  double block = double(layout.grid.bins()) * layout.grid.quantities() * 8;
  if (layout.has_profile()) block += double(layout.profile.bins()) * layout.grid.quantities() * 8;
  const double needed = 5 * block * layout.grid.blocks;
  if (const auto available = available_memory_bytes(); available && needed > *available)
    throw UserError(fmt::format(
        "scene keys 'numerics.bin_size' = {} m x 'output.blocks' = {} of the map: its field "
        "sums and their analysis need about {:.3g} GB, more than the {:.3g} GB available "
        "(MemAvailable, ulimit -v); make the bins larger or the blocks fewer",
        scene.bin_size_m, scene.run.blocks, needed / 1e9, *available / 1e9));
}

DumpSums sum_dump_frames(const DumpMap& map, DumpFormat format,
                         const std::vector<std::filesystem::path>& files) {
  const Scene& scene = map.scene.scene;
  check_dump_analysis_fits(scene);
  const SamplingPlan plan(scene);
  DumpSums out;
  out.grid = empty_sums(plan.layout().grid, scene);
  if (plan.layout().has_profile()) out.profile = empty_sums(plan.layout().profile, scene);
  const long first_step = std::llround(scene.run.production_start_s / scene.setup.dt);
  const long end_step = scene.total_steps();

  const Box& box_of_map = scene.setup.box;
  DumpFrame frame, first;
  std::optional<long> previous_step;
  std::string previous_where;
  bool warned_3d = false;
  for (std::size_t f = 0; f < files.size(); ++f) {
    DumpReader reader(files[f], format);
    for (;;) {
      try {
        if (!reader.next(frame)) break;
      } catch (const TruncatedDump& e) {
        // A dump still being written ends inside its last frame: the frames before it are
        // whole. Inside an earlier file, or with no whole frame at all, it is an error.
        if (f + 1 < files.size() || out.frames_read == 0) throw;
        out.warnings.push_back(std::string(e.what()) + "; its last frame is left out, the " +
                               std::to_string(out.frames_read) + " frames before it are used");
        break;
      }
      if (!warned_3d && is_three_dimensional(frame)) {
        warned_3d = true;
        out.warnings.push_back(fmt::format(
            "the frame at {} is 3-D (z from {:.6g} to {:.6g} m, |vz| up to {:.3g} m/s): granshock "
            "bins its x-y projection, as a quasi-2-D layer (the fields count particles per "
            "area of the layer and leave vz out of the temperature)",
            frame.where, frame.z_min, frame.z_max, frame.vz_max_abs));
      }
      if (previous_step && !(frame.timestep > *previous_step))
        throw UserError("frames out of order: the frame at " + frame.where + " has timestep " +
                        std::to_string(frame.timestep) + ", not after " +
                        std::to_string(*previous_step) + " of the frame at " + previous_where +
                        " (give the files in time order, each frame once)");
      if (out.frames_read == 0) {
        check_box_against_map(frame, box_of_map);
        first = frame;
      } else if (!same_box(frame, first))
        throw UserError("mixed box sizes: the frame at " + frame.where + " has the box " +
                        box_text(frame) + ", the first frame (" + first.where + ") " +
                        box_text(first) + "; granshock bins a fixed domain");
      const double t =
          frame.time ? *frame.time : double(frame.timestep) * map.seconds_per_timestep();
      // Two frames at one time are one sample written twice, not two samples.
      if (out.frames_read > 0 && !(t > out.last_time))
        throw UserError(fmt::format(
            "frames out of order: the frame at {} is at time {:.17g} s, not after {:.17g} s of "
            "the frame at {} (ITEM: TIME must grow from frame to frame; give each frame once)",
            frame.where, t, out.last_time, previous_where));
      // The step of granshock's time grid the frame falls on: the window and its blocks
      // are those of a run of the scene (SamplingPlan).
      const long step = std::llround(t / scene.setup.dt);
      const bool in_window = step >= first_step && step < end_step;
      previous_step = frame.timestep;
      previous_where = frame.where;
      add_dump_frame(frame, map, in_window ? plan.block_of(step) : -1, out.grid, out.profile);
      out.series.time.push_back(t - map.flow_start);
      out.series.particles.push_back(double(frame.size()));
      out.series.kinetic_energy.push_back(kinetic_energy(frame, map));
      if (out.frames_read == 0) out.first_time = t;
      out.last_time = t;
      ++out.frames_read;
      if (in_window) ++out.frames_used;
    }
  }
  if (out.frames_read == 0)
    throw UserError("the " + to_string(format) + " dump file(s) hold no frame");
  if (out.frames_used == 0)
    throw UserError("no dump frame lies in the production window [" +
                    seconds(scene.run.production_start_s) + ", " + seconds(scene.run.duration_s) +
                    ") of the map: the " + std::to_string(out.frames_read) + " frames span " +
                    seconds(out.first_time) + " to " + seconds(out.last_time) +
                    " (set time.production_start and time.duration, or [dump] dt)");
  return out;
}

}  // namespace granshock
