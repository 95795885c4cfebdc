// The field sums of another code's particles (docs/fields.md, "Fields from LAMMPS or
// LIGGGHTS dumps"): every dump frame in the map's production window is one field sample,
// binned on the grid and stagnation-line profile that a granshock run of the map's scene
// samples (cases/bow_shock/sampling_plan.hpp), with the same bin rule as the device
// sampler (kernels/sampling/bin_accumulator.hpp, GridIndex) and the same per-species
// moments (core/bin_layout.hpp). A dump has no contact forces: the virial sums stay zero.
#pragma once

#include <filesystem>
#include <optional>
#include <vector>

#include "analysis/steadiness.hpp"
#include "core/bin_sums.hpp"
#include "io/dump_map.hpp"
#include "io/particle_dump.hpp"

namespace granshock {

struct DumpSums {
  BinSums grid;
  std::optional<BinSums> profile;  // with an obstacle, as in a run
  long frames_read = 0, frames_used = 0;
  double first_time = 0, last_time = 0;  // of the frames read, s
  // Per frame: the time since [dump] flow_start, the particles and their translational
  // kinetic energy sum m (vx^2 + vy^2) / 2 (the steadiness check's series).
  RunSeries series;
  // Said on stderr and kept in summary.json: a truncated last frame left out, a 3-D dump
  // binned as its x-y projection.
  std::vector<std::string> warnings;
};

// Throws UserError naming the keys when the map's bins are not ones a run could sample
// (validate_field_sampling) or their sums would need more memory than there is.
void check_dump_analysis_fits(const Scene& scene);

// Reads every frame of `files`, in order, and sums those in the production window
// [time.production_start, time.duration). Throws UserError (nothing written) for bins that
// do not fit (check_dump_analysis_fits), an atom type the map does not name, frames whose
// timesteps or times do not increase, a first frame whose box is not the map's domain, a
// box that differs from the first frame's, no frame in the window, or any error of
// DumpReader.
DumpSums sum_dump_frames(const DumpMap& map, DumpFormat format,
                         const std::vector<std::filesystem::path>& files);

// Adds one frame's particles to `grid` and `profile` as one sample of block `block`; a
// particle's species is map.species_of_type[type] (throws UserError for an unknown type).
void add_dump_frame(const DumpFrame& frame, const DumpMap& map, int block, BinSums& grid,
                    std::optional<BinSums>& profile);

}  // namespace granshock
