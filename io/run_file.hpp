// run.h5, the main output of `granshock run` (layout: docs/output_format.md): the scene,
// H5MD-style particle snapshots and the time series. Everything time-indexed is
// appended frame by frame and can be cut back to a checkpoint's step on resume, so a
// resumed run continues the same file as if it had never stopped.
//
// A full disk: HDF5 changes the file in place, and a write that fails half-way can leave
// it unreadable. Every change first reserves on disk the most it can grow the file
// (run_file_growth.hpp); a change that finds no room is refused before anything is
// written, and the file stays as it was after the last one (docs/output_format.md).
#pragma once

#include <mpi.h>

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "core/host_particles.hpp"
#include "core/snapshot_part.hpp"
#include "core/time_series.hpp"
#include "io/frame_views.hpp"
#include "io/hdf5_handle.hpp"
#include "io/run_file_growth.hpp"
#include "io/snapshot_frame.hpp"

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

// What a checkpoint records of the run file beside it (docs/output_format.md, "What a
// resume checks"): the run's identity and the entries run.h5 held when it was written.
// The layout versions of run.h5 (docs/output_format.md, "Format versions"): this granshock
// writes kRunFileFormat and reads formats 1 to it; a resumed run keeps its file's format.
// 2: snapshots add radius and, with friction, angular_velocity.
// 3: a run id, the /xdmf frame views and snapshot chunks made as a frame grows (collective
//    output) always (format-2 files may lack each); a format-3 file without a run id is
//    refused on resume.
inline constexpr int kRunFileFormat = 3;

struct RunFileRecord {
  // Empty: a checkpoint that recorded none (format-3 checkpoints written before run ids,
  // or one written outside a run), which is not checked.
  std::string run_id;
  long frames = -1;  // snapshot frames
  long rows = -1;    // time-series rows
};

class RunFile {
 public:
  // Creates (or replaces) the file, with a new random run id. dim is 2 (positions and
  // velocities store x, y) or 3. `build`: the program's build (JSON text), kept in
  // /h5md/creator@build when not empty. Throws UserError naming the path when it cannot be
  // created.
  static RunFile create(const std::filesystem::path& path, const std::string& scene_toml_as_given,
                        const std::string& scene_toml_resolved, int dim,
                        const SnapshotContents& contents = {}, const std::string& build = {});

  // Reopens an existing run file read-write and drops every time-indexed entry (snapshot
  // frames, time-series rows) whose step is after checkpoint_step. Throws UserError, with
  // the file unchanged, when it is missing, is not a granshock run file, or does not match
  // the checkpoint's record: another run's, or holding other entries up to its step. A
  // checkpoint without a record (RunFileRecord::run_id) is not checked; a file without a
  // run id (run.h5 format 1, or format 2 written before run ids) gets one.
  static RunFile open_for_resume(const std::filesystem::path& path, long checkpoint_step,
                                 const RunFileRecord& checkpoint);

  // Whether open_for_resume would accept the file, changing nothing: throws its UserError
  // when not, or when HDF5 cannot open it.
  static void check_resumable(const std::filesystem::path& path, long checkpoint_step,
                              const RunFileRecord& checkpoint);

  // Opens for reading only (granshock fields, tests).
  static RunFile open_read_only(const std::filesystem::path& path);
  // Reopens an existing run file read-write, as it is.
  static RunFile open_for_append(const std::filesystem::path& path);

  RunFile(RunFile&&) noexcept = default;
  RunFile& operator=(RunFile&&) noexcept = default;
  RunFile(const RunFile&) = delete;
  RunFile& operator=(const RunFile&) = delete;
  ~RunFile() = default;  // the handle closes the file

  // Appends one frame, and flushes. Steps must increase from frame to frame (resume relies
  // on it); throws std::invalid_argument otherwise, when p's arrays differ in length (an
  // empty angular_velocity stands for zeros) or when a species has no radius.
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
  // The particles of frame `frame` (0-based), its `count` rows: positions and velocities
  // with z = 0 in 2-D, species, ids and, where the file has them, spins. Throws UserError
  // for a frame it does not hold.
  HostParticles read_snapshot(long frame) const;
  // The run id and the frames and rows written so far, for a checkpoint to record.
  RunFileRecord record() const;
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
  // A resume that changes the scene (cases/bow_shock/run_extension.hpp): /scene holds the
  // scene the run now runs.
  void replace_scene(const std::string& scene_toml_as_given,
                     const std::string& scene_toml_resolved);
  // Whether the dataset or group at `path` exists.
  bool has(const std::string& path) const;

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
  // appended since, and gives back the room reserved for it that was not used.
  void flush();

 private:
  RunFile(std::filesystem::path path, h5::Handle file, int dim);
  // Room on disk for `growth` more bytes than the changes since the last flush may take
  // (io/file_room.hpp): 0, or the errno that refused it. make_room throws UserError.
  int try_make_room(std::uintmax_t growth);
  void make_room(std::uintmax_t growth, const std::string& what);
  // HDF5's end of allocation now: what the file holds, written, after a flush or open.
  void settle();
  std::uintmax_t snapshot_growth(long total) const;  // the rows of a frame of `total`
  // Its step, time, count and views (io/frame_views.hpp).
  std::uintmax_t completion_growth(long total) const;
  // The datasets those bounds count with, read from the file once (they do not change).
  struct GrowthLayout {
    std::vector<run_growth::SeriesArray> frame_series, row_series;
    std::vector<run_growth::ParticleArray> particles;
  };
  const GrowthLayout& growth_layout() const;
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
  std::uintmax_t settled_ = 0;   // HDF5's end of allocation at the last flush or open
  std::uintmax_t promised_ = 0;  // the most the changes since can have grown it
  std::uintmax_t reserved_ = 0;  // the file's bytes allocated on disk
  mutable std::optional<GrowthLayout> growth_layout_;
};

}  // namespace granshock
