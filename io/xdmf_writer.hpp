// The XDMF (version 2) description of run.h5's particle snapshots, so that ParaView (any
// of its three XDMF readers) or VisIt open them as a time series of point clouds without
// copying any data: each frame is a Polyvertex grid whose arrays are the frame's views in
// run.h5 (frame_views.hpp; docs/output_format.md, "run.xmf").
#pragma once

#include <array>
#include <filesystem>
#include <string>
#include <vector>

#include "io/frame_views.hpp"
#include "io/snapshot_frame.hpp"

namespace granshock {

// Writes xmf_path atomically. h5_filename_relative is the run file's name as seen from
// the XMF's directory (normally "run.h5"); frame K's grid reads the views in its group
// frame_view_group(K): "vertex" (the topology), "position" (XY in 2-D, XYZ in 3-D) and
// one attribute per entry of `arrays` (RunFile::frame_view_arrays()), a Vector where it
// has three components. Frames with no particles are left out (viewers reject empty
// arrays). Throws std::invalid_argument for a negative count, a dim other than 2 or 3 or
// an array of another width, UserError when the file cannot be written.
// `obstacle_outline`: the obstacle's cross-section as a closed polygon (x, y in m; empty for
// none): each frame is then a spatial collection of the particles' grid, "particles", and
// the obstacle's, "obstacle", one Polygon cell whose points the file holds itself, so that
// ParaView shows the obstacle, not a hole.
void write_particles_xdmf(const std::filesystem::path& xmf_path,
                          const std::string& h5_filename_relative,
                          const std::vector<SnapshotFrame>& frames, int dim,
                          const std::vector<FrameViewArray>& arrays,
                          const std::vector<std::array<double, 2>>& obstacle_outline = {});

// That obstacle grid's XML, indented by `indent` spaces (fields.xmf has it too): "" for
// fewer than three points. `arrays`: point arrays it carries as the particles do, all zero
// (integers -1), so that a filter of the particles' arrays passes over it.
std::string obstacle_grid_xml(const std::vector<std::array<double, 2>>& outline, int dim,
                              int indent, const std::vector<FrameViewArray>& arrays = {});

}  // namespace granshock
