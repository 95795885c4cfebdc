// run.h5, the main output of `granshock run` (layout: docs/output_format.md): the scene,
// H5MD-style particle snapshots and the time series. Everything time-indexed is
// appended frame by frame and can be cut back to a checkpoint's step on resume, so a
// resumed run continues the same file as if it had never stopped.
#pragma once

#include <mpi.h>

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "frame_views.hpp"
#include "hdf5_handle.hpp"
#include "host_particles.hpp"
#include "snapshot_frame.hpp"
#include "snapshot_part.hpp"
#include "time_series.hpp"

namespace granshock {

// What each snapshot holds besides position, velocity, species and id
// (docs/output_format.md, "Particle snapshots").
struct SnapshotContents {
  // The radius of each species (m), by species index: every snapshot then stores each
  // particle's radius. Empty: no radius element.
  std::vector<double> species_radius;
  // Friction (quasi-2-D): every snapshot stores each particle's spin about z (rad/s).
  bool angular_velocity = false;
};

class RunFile {
 public:
  // Creates (or replaces) the file. dim is 2 (positions and velocities store x, y) or 3.
  // Throws UserError naming the path when it cannot be created.
  static RunFile create(const std::filesystem::path& path, const std::string& scene_toml_as_given,
                        const std::string& scene_toml_resolved, int dim,
                        const SnapshotContents& contents = {});

  // Reopens an existing run file read-write and drops every time-indexed entry (snapshot
  // frames, time-series rows) whose step is after checkpoint_step. Throws UserError when
  // the file is missing or is not a granshock run file.
  static RunFile open_for_resume(const std::filesystem::path& path, long checkpoint_step);

  // Opens for reading only (granshock fields, tests).
  static RunFile open_read_only(const std::filesystem::path& path);
  // Reopens an existing run file read-write, as it is.
  static RunFile open_for_append(const std::filesystem::path& path);

  RunFile(RunFile&&) noexcept = default;
  RunFile& operator=(RunFile&&) noexcept = default;
  RunFile(const RunFile&) = delete;
  RunFile& operator=(const RunFile&) = delete;
  ~RunFile() = default;  // the handle closes the file

  // Appends one frame. Steps must increase from frame to frame (resume relies on it);
  // throws std::invalid_argument otherwise, when p's arrays differ in length (an empty
  // angular_velocity stands for zeros) or when a species has no radius.
  void append_snapshot(long step, double time, const HostParticles& p);

  // Several processes (docs/parallel.md, "Output"): appends one frame to the run file at
  // `path` with every process of `comm` writing its part's rows at once (parallel HDF5,
  // collective). Rank 0 holds the file open in `root_file` between snapshots, the others
  // nothing: it is closed for the collective write and reopened after, when rank 0 alone
  // appends the frame's steps, views and count (a frame counts once its count is there).
  static void append_snapshot_collectively(const std::filesystem::path& path, MPI_Comm comm,
                                           long step, double time, const SnapshotPart& part,
                                           std::optional<RunFile>& root_file);
  // Whether a frame of `total` particles is written faster collectively than gathered to
  // rank 0 and appended there: from 24,576 particles (one and a half chunks), whose
  // compression the processes then share (measured on 2 processes, docs/scaling.md).
  static bool collective_pays(long total);

  // Appends one row to every /observables series; the same rule on steps.
  void append_time_series(const TimeSeriesRow& row);

  // The frames written so far, in order.
  std::vector<SnapshotFrame> frames() const;
  // The particle extent of the snapshot datasets (>= every frame's count).
  long particle_capacity() const;
  int dim() const { return dim_; }
  // What the snapshots of this file hold (files of format 1 hold neither radius nor
  // angular velocity: a resumed run keeps writing what its file has).
  const SnapshotContents& contents() const { return contents_; }
  // The arrays every frame's views show (frame_views.hpp), for write_particles_xdmf.
  std::vector<FrameViewArray> frame_view_arrays() const;
  const std::filesystem::path& path() const { return path_; }

  std::string scene_as_given() const;
  std::string scene_resolved() const;

  // Summary values and arrays (e.g. under "/summary", or the field accumulators under
  // "/fields"). The object (a group) is created with its parents when missing; an
  // existing attribute or array of that name is replaced.
  void write_attribute(const std::string& object, const std::string& name, double value);
  void write_attribute(const std::string& object, const std::string& name, long value);
  void write_attribute(const std::string& object, const std::string& name,
                       const std::string& value);
  double read_attribute_double(const std::string& object, const std::string& name) const;
  long read_attribute_long(const std::string& object, const std::string& name) const;
  std::string read_attribute_string(const std::string& object, const std::string& name) const;

  // A row-major array of the given shape (product of shape == values.size()).
  void write_array(const std::string& dataset, const std::vector<double>& values,
                   const std::vector<long>& shape);
  std::vector<double> read_array(const std::string& dataset,
                                 std::vector<long>* shape = nullptr) const;

  // Pushes buffered data to the file (H5Fflush), so that a crash loses at most what was
  // appended since.
  void flush();

 private:
  RunFile(std::filesystem::path path, h5::Handle file, int dim);
  // Every process of `comm` at once, for write_snapshot_rows alone.
  static RunFile open_collectively(const std::filesystem::path& path, MPI_Comm comm);
  // A frame's particle data: `p` to the file `rows` of a frame of `total` rows (the next
  // frame, whose index it returns). complete_snapshot then appends its step, time and count.
  long write_snapshot_rows(long step, const HostParticles& p, const std::vector<FileRows>& rows,
                           long total);
  void complete_snapshot(long frame, long step, double time, long total);

  std::filesystem::path path_;
  h5::Handle file_;
  h5::Handle transfer_;  // collective transfers: a file every process opened; else none
  int dim_ = 2;
  SnapshotContents contents_;
};

}  // namespace granshock
