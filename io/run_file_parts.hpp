// What the parts of RunFile (io/run_file.cpp, run_file_series.cpp, run_file_snapshots.cpp,
// run_file_resume.cpp) share: run.h5's layout names, opening it, and its time series.
#pragma once

#include <hdf5.h>

#include <filesystem>
#include <string>
#include <vector>

#include "io/hdf5_handle.hpp"
#include "io/hdf5_helpers.hpp"

namespace granshock::run_file_detail {

inline constexpr const char* kParticles = "/particles/all";
inline constexpr const char* kObservables = "/observables";
inline constexpr const char* kRunIdAttribute = "run_id";

// Snapshot chunks hold one frame of this many particles: a frame is written (and read
// by a viewer) as a whole, so chunks never span frames. 16384 particles x 2 doubles is
// 256 KiB, large enough for fast sequential I/O.
inline constexpr hsize_t kParticleChunk = 16384;

// --- run_file.cpp ----------------------------------------------------------------------
// Opens an existing run file with `flags`: a UserError "cannot DOING 'PATH': ..." when it
// is missing, not a regular file, a second name of one written in place, not a granshock
// run file, or of a newer format.
h5::Handle open_existing(const std::filesystem::path& path, unsigned flags, const char* doing);
int read_dim(hid_t file);
// A random identity for a new run, written into run.h5 and every checkpoint of the run so
// that a resume never joins files of two runs (docs/output_format.md).
std::string new_run_id();
// Empty: a file without one (format 1, or 2 written before run ids).
std::string read_run_id(hid_t file);
// The file's @granshock_format_version.
int read_format_version(hid_t file);

// --- run_file_series.cpp: time-indexed elements, H5MD style ------------------------------
// Creates GROUP/{step,time,value} for a time-indexed quantity, H5MD style. `tail` is
// the shape of one entry of value: {} for a scalar series, {0} for one scalar per
// particle, {0, dim} for one vector per particle (0 = extendible particle dimension).
void create_time_element(hid_t file, const std::string& group_path, hid_t stored_type,
                         const std::vector<hsize_t>& tail, const void* fill, hid_t fill_type,
                         const char* unit);
// The /observables series, one per TimeSeriesRow field (core/time_series.hpp).
void create_observables(hid_t file);

// Grows `dataset` to `new_dims` and writes `data` (contiguous, `count` shaped) at `start`.
void extend_and_write(hid_t dataset, const std::vector<hsize_t>& new_dims,
                      const std::vector<hsize_t>& start, const std::vector<hsize_t>& count,
                      hid_t memory_type, const void* data);

// The number of entries in GROUP/step and the last step (or none).
struct SeriesEnd {
  hsize_t entries = 0;
  bool any = false;
  long last_step = 0;
};

SeriesEnd series_end(hid_t file, const std::string& group_path);
// Throws std::invalid_argument when `step` does not follow the last entry (what: "snapshot").
void require_increasing(const SeriesEnd& end, long step, const std::string& what);

// Appends (step, time) to GROUP/step and GROUP/time, entry `index`. Written after the
// value: an entry counts as present once its step is there.
void append_step_time(hid_t file, const std::string& group_path, hsize_t index, long step,
                      double time);

// Appends one scalar entry to a time series group.
template <class T>
void append_scalar(hid_t file, const std::string& group_path, hsize_t index, long step, double time,
                   T value) {
  h5::Handle value_set = h5::open_dataset(file, group_path + "/value");
  extend_and_write(value_set.get(), {index + 1}, {index}, {1}, h5::TypeOf<T>::memory(), &value);
  append_step_time(file, group_path, index, step, time);
}

}  // namespace granshock::run_file_detail
