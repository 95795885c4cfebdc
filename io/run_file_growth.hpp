// Upper bounds on how far one change to run.h5 can move HDF5's end of allocation (where
// the file ends once written), from its datasets' chunking as the file holds it and HDF5's
// rules for file space. RunFile reserves this much on disk before it changes the file
// (io/file_room.hpp, docs/output_format.md "A full disk"); tests/io/test_run_file_room.cpp
// checks them with file-size limits met at every stage of a run's appends.
#pragma once

#include <cstdint>
#include <vector>

namespace granshock::run_growth {

// A per-particle dataset of the snapshots (frame x particle [x components]), chunked by
// one frame of `chunk_particles`.
struct ParticleArray {
  std::uintmax_t chunk_particles = 0;
  std::uintmax_t bytes_per_particle = 0;
};

// The particle rows of a snapshot frame appended after `frames` frames to every array,
// the particle extent growing from `capacity` to `new_capacity` (every earlier frame gains
// the new columns of chunks too).
std::uintmax_t snapshot_rows(long frames, long capacity, long new_capacity,
                             const std::vector<ParticleArray>& arrays);

// A 1-D time series (step, time, or a scalar's value), chunked by `chunk_entries`.
struct SeriesArray {
  std::uintmax_t chunk_entries = 0;
  std::uintmax_t bytes_per_entry = 0;
};

// One entry appended to each of `series`, which hold `index` entries.
std::uintmax_t series_entries(long index, const std::vector<SeriesArray>& series);

// The views that make `frames` snapshot frames readable by XDMF readers
// (io/frame_views.hpp): a group of `views_per_frame` virtual datasets per frame, and the
// vertex index grown from `vertices` to `new_vertices` entries of int32 in chunks of
// `vertex_chunk`.
std::uintmax_t frame_views(long frames, std::uintmax_t views_per_frame, long vertices,
                           long new_vertices, std::uintmax_t vertex_chunk);

// A dataset of `bytes` written whole, replacing one of that name.
std::uintmax_t whole_dataset(std::uintmax_t bytes);

// An attribute of `bytes` written or replaced.
std::uintmax_t attribute(std::uintmax_t bytes);

// Cutting the time series back to a checkpoint's step (RunFile::open_for_resume), which
// rewrites metadata in place and frees chunks.
std::uintmax_t truncation();

}  // namespace granshock::run_growth
