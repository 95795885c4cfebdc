// One process's part of a particle snapshot written collectively (docs/parallel.md,
// "Output"): its particles in its own cell order, and the rows of the file they fill, so
// that the file holds one process's order whatever the number of processes.
#pragma once

#include <vector>

#include "core/communicator.hpp"
#include "core/host_particles.hpp"

namespace granshock {

// A run of consecutive file rows: the next `count` local particles go to rows
// [first, first + count).
struct FileRows {
  long first = 0;
  long count = 0;
  bool operator==(const FileRows& o) const { return first == o.first && count == o.count; }
};

struct SnapshotPart {
  HostParticles particles;     // this process's, in the order of `rows`
  std::vector<FileRows> rows;  // increasing, covering particles.size() rows
  long total = 0;              // every process's particles: the frame's row count
};

// The file rows of `rank`'s particles when the one-process order is the order of the flat
// cell index and every process owns, in each layer of that index, one contiguous range of
// cells, the ranges in rank order within a layer (slabs: docs/parallel.md). A layer is the
// stretch of the flat index across which the slabs are cut: the whole grid for slabs of
// the outermost axis, one grid row for slabs along x. `counts` holds the particles per
// layer of every rank, rank-major (ranks x layers). Runs that touch are merged; empty
// layers give none.
std::vector<FileRows> file_rows_by_layer(const std::vector<long>& counts, int layers, int rank);

// Where each of a frame's `total` rows comes from: its index in the parts of every rank
// concatenated in rank order (`parts` particles), given their runs of rows concatenated
// the same way. Throws std::logic_error when the runs do not fill the frame once each.
std::vector<int> row_sources(const std::vector<FileRows>& rows, long total, std::size_t parts);

// Collective: every process's part at its rows, the whole frame, on rank 0 (empty
// elsewhere; one process: its own). Throws as row_sources.
HostParticles gather_snapshot(const Communicator& comm, const SnapshotPart& part);

}  // namespace granshock
