// Per-frame views of run.h5's snapshots for XDMF readers (docs/output_format.md, "run.xmf").
// A snapshot dataset holds every frame padded to the largest particle count, so a frame is
// a region of it. ParaView's Xdmf3 readers (its default) cannot read such a region given as
// an XDMF HyperSlab; they read plain datasets. Each frame therefore gets a group of HDF5
// virtual datasets, /xdmf/frame_K/<name>, of exactly its particles: they map the frame's
// rows of the stored datasets and copy no data. Every HDF5 reader since 1.10 resolves them.
#pragma once

#include <hdf5.h>

#include <string>
#include <vector>

namespace granshock {

// A per-particle array as the views show it: the dataset /xdmf/frame_K/<name>, and the
// array of that name in a viewer.
struct FrameViewArray {
  std::string name;
  int components = 1;    // 1, or 3 for a vector (x, y, z; z = 0 in 2-D)
  bool integer = false;  // int32, else float64
  bool operator==(const FrameViewArray& o) const {
    return name == o.name && components == o.components && integer == o.integer;
  }
};

// The vertex index /xdmf/vertex_index is chunked by this many entries.
inline constexpr unsigned long long kVertexIndexChunk = 16384;

// The vertex index's length in `file` (0 before the first view).
long vertex_index_length(hid_t file);

// The group of frame K's views: "/xdmf/frame_000012".
std::string frame_view_group(long frame);

// The arrays the views of run.h5 `file` have besides "position" (x, y or x, y, z: the
// points) and "vertex" (0 .. n-1: one vertex cell per point): the per-particle elements
// of /particles/all that the file holds, vectors as three components.
std::vector<FrameViewArray> frame_view_arrays(hid_t file);

// Brings the views of run.h5 `file` up to date after a frame was written: counts[K] is
// frame K's particle count, the last entry the new frame's. The new frame's views are
// made (replacing any left by a run that was cut back on resume), earlier frames without
// views get theirs (files written before views existed), and views of frames past the
// new one are removed. Throws h5::Hdf5Error.
void update_frame_views(hid_t file, int dim, const std::vector<long>& counts);

}  // namespace granshock
