// The XDMF (version 2) description of run.h5's particle snapshots, so that ParaView or
// VisIt open them as a time series of point clouds without copying any data: each frame
// is a Polyvertex grid whose arrays are hyperslabs of the snapshot datasets.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "snapshot_frame.hpp"

namespace granshock {

// Writes xmf_path atomically. h5_filename_relative is the run file's name as seen from
// the XMF's directory (normally "run.h5"); dim (2 or 3) and capacity (the particle
// extent of the snapshot datasets) come from RunFile::dim() and particle_capacity().
// Frames with no particles are left out (viewers reject empty hyperslabs). In 2-D the
// velocity is given as two scalars vx, vy: XDMF readers take a "Vector" as exactly three
// components, so an (n, 2) array would be misread. Throws std::invalid_argument when a
// frame's count exceeds capacity, UserError when the file cannot be written.
void write_particles_xdmf(const std::filesystem::path& xmf_path,
                          const std::string& h5_filename_relative,
                          const std::vector<SnapshotFrame>& frames, int dim, long capacity);

}  // namespace granshock
