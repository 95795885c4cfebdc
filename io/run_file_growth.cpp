#include "io/run_file_growth.hpp"

#include <algorithm>
#include <cstdint>

namespace granshock::run_growth {

namespace {

constexpr std::uintmax_t KiB = 1024;
// HDF5 serves small requests (metadata, raw data under 2 KiB) from aggregator blocks of
// 2 KiB; a request that does not fit the current block starts another at the end of the
// file, so each allocation can move the end by one block more than it asks for.
constexpr std::uintmax_t kPerAllocation = 4 * KiB;
// A node of the version-1 B-tree that indexes a dataset's chunks: 64 children and 65 keys
// of (rank + 1) offsets, 3.1 KiB at rank 3.
constexpr std::uintmax_t kIndexNode = 4 * KiB;
// Whatever else a change makes: object header messages (dataspaces, layouts) are rewritten
// in place at their size; the rest is margin.
constexpr std::uintmax_t kPerChange = 16 * KiB;

// zlib's compressBound: deflate never makes n bytes longer than this (and HDF5 stores a
// chunk that the optional deflate filter cannot shrink as it is). Shuffling keeps the size.
std::uintmax_t deflated(std::uintmax_t n) {
  return n + (n >> 12) + (n >> 14) + (n >> 25) + 13;
}

// A chunk of fill values (NaN, -1), made for every chunk of a frame when the frame is
// allocated (H5D_ALLOC_TIME_EARLY) and replaced by the written chunk: each byte plane is
// constant after the shuffle, and deflates to less than a hundredth of its size (an empty
// frame of two chunks per dataset, 1.3 MB of fill values in 2-D, grew run.h5 by 5.9 kB).
std::uintmax_t fill_chunk(std::uintmax_t n) {
  return n / 32 + KiB;
}

// Nodes a chunk index can gain while `count` chunks are added to the `first` it holds:
// its root with the first chunk; then a node splits (one new node, two at the root) at
// most once per half node (32) of entries added to it, at every level (at most 6 levels
// for 2^30 chunks).
std::uintmax_t index_nodes(std::uintmax_t first, std::uintmax_t count) {
  if (count == 0) return 0;
  return first + count <= 32 ? 1 : count / 16 + 8;
}

std::uintmax_t chunks_for(long particles, std::uintmax_t per_chunk) {
  const std::uintmax_t n = particles > 0 ? std::uintmax_t(particles) : 0;
  return per_chunk == 0 ? 0 : (n + per_chunk - 1) / per_chunk;
}

}  // namespace

std::uintmax_t snapshot_rows(long frames, long capacity, long new_capacity,
                             const std::vector<ParticleArray>& arrays) {
  const std::uintmax_t before = std::uintmax_t(frames > 0 ? frames : 0);
  std::uintmax_t bytes = kPerChange;
  for (const ParticleArray& a : arrays) {
    const std::uintmax_t old_columns = chunks_for(capacity, a.chunk_particles);
    const std::uintmax_t columns =
        std::max(old_columns, chunks_for(new_capacity, a.chunk_particles));
    const std::uintmax_t raw = a.chunk_particles * a.bytes_per_particle;
    // The new frame: every chunk filled, then written; and what else a frame's metadata
    // takes besides the chunk index.
    bytes += columns * (fill_chunk(raw) + deflated(raw) + 2 * kPerAllocation) + kPerAllocation;
    // Earlier frames gain the new columns, filled.
    const std::uintmax_t added = before * (columns - old_columns);
    bytes += added * (fill_chunk(raw) + kPerAllocation);
    bytes += index_nodes(before * old_columns, added + columns) * (kIndexNode + kPerAllocation);
  }
  return bytes;
}

std::uintmax_t series_entries(long index, const std::vector<SeriesArray>& series) {
  const std::uintmax_t i = std::uintmax_t(index > 0 ? index : 0);
  std::uintmax_t bytes = kPerChange;
  for (const SeriesArray& a : series) {
    // The entry opens a chunk (allocated when written), and a node of the chunk index.
    if (a.chunk_entries == 0 || i % a.chunk_entries != 0) continue;
    const std::uintmax_t nodes = index_nodes(i / a.chunk_entries, 1);
    bytes += a.chunk_entries * a.bytes_per_entry + kPerAllocation +
             nodes * (kIndexNode + kPerAllocation);
  }
  return bytes;
}

std::uintmax_t frame_views(long frames, std::uintmax_t views_per_frame, long vertices,
                           long new_vertices, std::uintmax_t vertex_chunk) {
  const std::uintmax_t n = std::uintmax_t(frames > 0 ? frames : 0);
  // A view: its object header, and its mapping in a global heap collection (at least 4 KiB
  // each). A frame's group: its symbol table, name heap and its link in /xdmf.
  const std::uintmax_t per_frame = kPerChange + kIndexNode + views_per_frame * 3 * kPerAllocation;
  std::uintmax_t bytes = n * per_frame;
  const std::uintmax_t old_chunks = chunks_for(vertices, vertex_chunk);
  const std::uintmax_t chunks = std::max(old_chunks, chunks_for(new_vertices, vertex_chunk));
  if (chunks > old_chunks) {
    const std::uintmax_t raw = vertex_chunk * sizeof(std::int32_t);
    bytes += (chunks - old_chunks) * (fill_chunk(raw) + deflated(raw) + 2 * kPerAllocation) +
             index_nodes(old_chunks, chunks - old_chunks) * (kIndexNode + kPerAllocation);
  }
  return bytes;
}

std::uintmax_t whole_dataset(std::uintmax_t bytes) {
  // Its object header and its link: the group's symbol table node and name heap; stored
  // checksummed (h5::Checksum::fletcher32), in chunks of at most 1 GiB, each 4 bytes
  // longer, under one index node.
  const std::uintmax_t chunks = bytes / (KiB * KiB * KiB) + 1;
  return bytes + 4 * kPerChange + kIndexNode + chunks * kPerAllocation;
}

std::uintmax_t attribute(std::uintmax_t bytes) {
  // In the object header, or a continuation block that holds it.
  return 2 * bytes + kPerChange;
}

std::uintmax_t truncation() {
  return 4 * kPerChange;
}

}  // namespace granshock::run_growth
