// The storage layout of run.h5's time-indexed datasets (io/run_file.cpp), shared with the
// bounds on how far an append can grow the file (io/run_file_growth.hpp).
#pragma once

#include <hdf5.h>

namespace granshock::run_layout {

// Time-indexed 1-D datasets grow by this many entries per chunk (2 KiB of int64).
constexpr hsize_t kSeriesChunk = 256;
// Snapshot chunks hold one frame of this many particles: a frame is written (and read
// by a viewer) as a whole, so chunks never span frames. 16384 particles x 2 doubles is
// 256 KiB, large enough for fast sequential I/O.
constexpr hsize_t kParticleChunk = 16384;
// Snapshots are stored byte-shuffled and gzip level 1 (0 = uncompressed). Measured for
// 100k particles in 2-D (random positions, thermal velocities; docs/output_format.md):
// none 7 ms and 4.6 MB per snapshot, shuffle+gzip-1 130 ms and 3.0 MB. Compression also
// keeps small runs small: a frame's last chunk is padded with fill values up to the
// chunk size, 0.66 MB for a 1000-particle frame uncompressed, 0.04 MB compressed.
constexpr unsigned kSnapshotDeflate = 1;

// The per-particle datasets of a snapshot and the bytes one particle takes in each:
// position and velocity (dim float64), species and id (int32).
inline hsize_t particle_bytes(int dim) {
  return 2 * hsize_t(dim) * 8 + 2 * 4;
}
// 1-D series appended with every frame: step and time of the four per-particle groups
// and of count, and count's value.
constexpr int kSeriesPerFrame = 11;
// 1-D series appended with every time-series row: step, time and value of the seven
// /observables.
constexpr int kSeriesPerRow = 21;

}  // namespace granshock::run_layout
