#include "io/run_file.hpp"

#include <fmt/format.h>
#include <sys/stat.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <optional>
#include <random>
#include <stdexcept>
#include <system_error>
#include <type_traits>
#include <utility>

#include "core/failure_agreement.hpp"
#include "core/user_error.hpp"
#include "io/file_room.hpp"
#include "io/hdf5_helpers.hpp"
#include "io/marked_directory.hpp"
#include "io/regular_file.hpp"
#include "io/run_file_growth.hpp"
#include "version.hpp"

namespace granshock {

namespace {

namespace fs = std::filesystem;
using h5::Handle;

constexpr const char* kParticles = "/particles/all";
constexpr const char* kObservables = "/observables";
constexpr const char* kFileKind = "run";
// 2: snapshots add radius and, with friction, angular_velocity (docs/output_format.md).
constexpr int kFormatVersion = 2;
constexpr const char* kSpeciesRadius = "/parameters/species_radius";
constexpr const char* kRunIdAttribute = "run_id";
constexpr std::uintmax_t kMostPromised = std::uintmax_t(1) << 20;

// Time-indexed 1-D datasets grow by this many entries per chunk (2 KiB of int64).
constexpr hsize_t kSeriesChunk = 256;
// Snapshot chunks hold one frame of this many particles: a frame is written (and read
// by a viewer) as a whole, so chunks never span frames. 16384 particles x 2 doubles is
// 256 KiB, large enough for fast sequential I/O.
constexpr hsize_t kParticleChunk = 16384;
// Snapshots are stored byte-shuffled and gzip level 1 (0 = uncompressed): a third smaller
// for a few times the write time (docs/output_format.md, "Storage"). Compression also
// keeps small runs small: a frame's last chunk is padded with fill values up to the
// chunk size, and the padding compresses to almost nothing.
constexpr unsigned kSnapshotDeflate = 1;

constexpr double kFloatFill = std::numeric_limits<double>::quiet_NaN();
constexpr int kIntFill = -1;

std::string element_path(const std::string& group, const char* name) {
  return group + "/" + name;
}

// Creates GROUP/{step,time,value} for a time-indexed quantity, H5MD style. `tail` is
// the shape of one entry of value: {} for a scalar series, {0} for one scalar per
// particle, {0, dim} for one vector per particle (0 = extendible particle dimension).
void create_time_element(hid_t file, const std::string& group_path, hid_t stored_type,
                         const std::vector<hsize_t>& tail, const void* fill, hid_t fill_type,
                         const char* unit) {
  Handle group = h5::require_group(file, group_path);
  const bool per_particle = !tail.empty();

  auto create_series = [&](const char* name, hid_t type) {
    const hsize_t dims[1] = {0};
    const hsize_t max_dims[1] = {H5S_UNLIMITED};
    const hsize_t chunk[1] = {kSeriesChunk};
    Handle space = h5::dataspace(H5Screate_simple(1, dims, max_dims), "creating a dataspace");
    Handle props = h5::plist(H5Pcreate(H5P_DATASET_CREATE), "creating dataset properties");
    h5::check(H5Pset_chunk(props.get(), 1, chunk), "setting the chunk shape");
    h5::add_checksum(props.get());
    return h5::dataset(
        H5Dcreate2(group.get(), name, type, space.get(), H5P_DEFAULT, props.get(), H5P_DEFAULT),
        "creating '" + group_path + "/" + name + "'");
  };
  create_series("step", H5T_STD_I64LE);
  Handle time = create_series("time", H5T_IEEE_F64LE);
  h5::write_attribute(time.get(), "unit", "s");

  std::vector<hsize_t> dims{0};
  std::vector<hsize_t> max_dims{H5S_UNLIMITED};
  std::vector<hsize_t> chunk{per_particle ? 1 : kSeriesChunk};
  for (std::size_t i = 0; i < tail.size(); ++i) {
    dims.push_back(tail[i]);
    max_dims.push_back(i == 0 ? H5S_UNLIMITED : tail[i]);
    chunk.push_back(i == 0 ? kParticleChunk : tail[i]);
  }
  Handle space =
      h5::dataspace(H5Screate_simple(static_cast<int>(dims.size()), dims.data(), max_dims.data()),
                    "creating a dataspace");
  Handle props = h5::plist(H5Pcreate(H5P_DATASET_CREATE), "creating dataset properties");
  h5::check(H5Pset_chunk(props.get(), static_cast<int>(chunk.size()), chunk.data()),
            "setting the chunk shape");
  if (fill != nullptr)
    h5::check(H5Pset_fill_value(props.get(), fill_type, fill), "setting a fill value");
  // Parallel HDF5 writes only to chunks that exist: each frame's are made (filled) when
  // the dataset grows to hold it, before any process writes its rows.
  if (per_particle)
    h5::check(H5Pset_alloc_time(props.get(), H5D_ALLOC_TIME_EARLY), "setting the allocation");
  if (per_particle && kSnapshotDeflate > 0 && H5Zfilter_avail(H5Z_FILTER_DEFLATE) > 0) {
    // Shuffling groups the bytes of equal significance (sign and exponent bytes of
    // nearby values agree), which gzip then compresses: 3.0 instead of 3.4 MB.
    h5::check(H5Pset_shuffle(props.get()), "enabling shuffle");
    h5::check(H5Pset_deflate(props.get(), kSnapshotDeflate), "enabling gzip");
  }
  // Last in the pipeline: the checksum is of the bytes stored, so a damaged chunk fails to
  // read before gzip or shuffle see it (docs/output_format.md, "Checksums").
  h5::add_checksum(props.get());
  Handle value = h5::dataset(H5Dcreate2(group.get(), "value", stored_type, space.get(), H5P_DEFAULT,
                                        props.get(), H5P_DEFAULT),
                             "creating '" + group_path + "/value'");
  if (unit != nullptr) h5::write_attribute(value.get(), "unit", unit);
}

// Grows `dataset` to `new_dims` and writes `data` (contiguous, `count` shaped) at `start`.
void extend_and_write(hid_t dataset, const std::vector<hsize_t>& new_dims,
                      const std::vector<hsize_t>& start, const std::vector<hsize_t>& count,
                      hid_t memory_type, const void* data) {
  h5::check(H5Dset_extent(dataset, new_dims.data()), "extending a dataset");
  hsize_t elements = 1;
  for (hsize_t c : count) elements *= c;
  if (elements == 0) return;
  Handle file_space = h5::dataspace(H5Dget_space(dataset), "reading a dataspace");
  h5::check(H5Sselect_hyperslab(file_space.get(), H5S_SELECT_SET, start.data(), nullptr,
                                count.data(), nullptr),
            "selecting a hyperslab");
  Handle memory_space =
      h5::dataspace(H5Screate_simple(static_cast<int>(count.size()), count.data(), nullptr),
                    "creating a dataspace");
  h5::check(H5Dwrite(dataset, memory_type, memory_space.get(), file_space.get(), H5P_DEFAULT, data),
            "writing a dataset");
}

// Writes one frame of a per-particle dataset (frame x capacity [x width]) after growing it
// to `new_dims`: the local rows `data` to the file rows `rows`, in order. `transfer`:
// H5P_DEFAULT for one process alone, or a collective transfer on a file every process
// opened (open_collectively), where a process with no rows still takes part.
void write_frame_rows(hid_t dataset, const std::vector<hsize_t>& new_dims, hsize_t frame,
                      const std::vector<FileRows>& rows, hid_t memory_type, const void* data,
                      hid_t transfer) {
  h5::check(H5Dset_extent(dataset, new_dims.data()), "extending a dataset");
  const hsize_t width = new_dims.size() == 3 ? new_dims[2] : 1;
  Handle file_space = h5::dataspace(H5Dget_space(dataset), "reading a dataspace");
  h5::check(H5Sselect_none(file_space.get()), "clearing a selection");
  hsize_t local = 0;
  for (const FileRows& r : rows) {
    const hsize_t start[3] = {frame, hsize_t(r.first), 0};
    const hsize_t count[3] = {1, hsize_t(r.count), width};
    h5::check(H5Sselect_hyperslab(file_space.get(), local == 0 ? H5S_SELECT_SET : H5S_SELECT_OR,
                                  start, nullptr, count, nullptr),
              "selecting a hyperslab");
    local += hsize_t(r.count);
  }
  if (local == 0 && transfer == H5P_DEFAULT) return;
  const hsize_t memory_dims[2] = {std::max<hsize_t>(local, 1), width};
  Handle memory_space = h5::dataspace(H5Screate_simple(width > 1 ? 2 : 1, memory_dims, nullptr),
                                      "creating a dataspace");
  if (local == 0) h5::check(H5Sselect_none(memory_space.get()), "clearing a selection");
  h5::check(H5Dwrite(dataset, memory_type, memory_space.get(), file_space.get(), transfer, data),
            "writing a dataset");
}

// The number of entries in GROUP/step and the last step (or none).
struct SeriesEnd {
  hsize_t entries = 0;
  bool any = false;
  long last_step = 0;
};

SeriesEnd series_end(hid_t file, const std::string& group_path) {
  Handle step = h5::open_dataset(file, group_path + "/step");
  SeriesEnd end;
  end.entries = h5::shape_of(step.get()).at(0);
  if (end.entries == 0) return end;
  Handle file_space = h5::dataspace(H5Dget_space(step.get()), "reading a dataspace");
  const hsize_t start[1] = {end.entries - 1};
  const hsize_t count[1] = {1};
  h5::check(H5Sselect_hyperslab(file_space.get(), H5S_SELECT_SET, start, nullptr, count, nullptr),
            "selecting the last step");
  Handle memory_space = h5::dataspace(H5Screate_simple(1, count, nullptr), "creating a dataspace");
  h5::check(H5Dread(step.get(), H5T_NATIVE_LONG, memory_space.get(), file_space.get(), H5P_DEFAULT,
                    &end.last_step),
            "reading the last step");
  end.any = true;
  return end;
}

void require_increasing(const SeriesEnd& end, long step, const std::string& what) {
  if (end.any && step <= end.last_step) {
    throw std::invalid_argument(what + " at step " + std::to_string(step) +
                                " does not follow the last one, at step " +
                                std::to_string(end.last_step));
  }
}

// Appends (step, time) to GROUP/step and GROUP/time, entry `index`. Written after the
// value: an entry counts as present once its step is there.
void append_step_time(hid_t file, const std::string& group_path, hsize_t index, long step,
                      double time) {
  Handle time_set = h5::open_dataset(file, group_path + "/time");
  extend_and_write(time_set.get(), {index + 1}, {index}, {1}, H5T_NATIVE_DOUBLE, &time);
  Handle step_set = h5::open_dataset(file, group_path + "/step");
  extend_and_write(step_set.get(), {index + 1}, {index}, {1}, H5T_NATIVE_LONG, &step);
}

// Appends one scalar entry to a time series group.
template <class T>
void append_scalar(hid_t file, const std::string& group_path, hsize_t index, long step, double time,
                   T value) {
  Handle value_set = h5::open_dataset(file, group_path + "/value");
  extend_and_write(value_set.get(), {index + 1}, {index}, {1}, h5::TypeOf<T>::memory(), &value);
  append_step_time(file, group_path, index, step, time);
}

// Collects the groups below the root that hold a "step" dataset: every time-indexed
// quantity, including any added to the layout later.
herr_t collect_step_groups(hid_t, const char* name, const H5L_info_t*, void* data) {
  const std::string path(name);
  const std::string suffix = "/step";
  if (path.size() > suffix.size() &&
      path.compare(path.size() - suffix.size(), suffix.size(), suffix) == 0) {
    static_cast<std::vector<std::string>*>(data)->push_back(
        "/" + path.substr(0, path.size() - suffix.size()));
  }
  return 0;
}

// Drops the entries of GROUP/{step,time,value} after checkpoint_step. Steps increase
// along the series, so the kept entries are a prefix.
void truncate_after(hid_t file, const std::string& group_path, long checkpoint_step) {
  const std::vector<long> steps = h5::read_dataset<long>(file, group_path + "/step");
  hsize_t keep = 0;
  while (keep < steps.size() && steps[keep] <= checkpoint_step) ++keep;
  for (const char* name : {"step", "time", "value"}) {
    const std::string path = element_path(group_path, name);
    if (!h5::exists(file, path)) continue;
    Handle set = h5::open_dataset(file, path);
    std::vector<hsize_t> dims = h5::shape_of(set.get());
    if (dims.empty() || dims[0] <= keep) continue;
    dims[0] = keep;
    h5::check(H5Dset_extent(set.get(), dims.data()), "truncating '" + path + "'");
  }
}

Handle open_existing(const fs::path& path, unsigned flags, const char* doing) {
  h5::silence_error_printing();
  std::error_code ec;
  if (!fs::exists(path, ec)) {
    throw UserError(std::string("cannot ") + doing + " '" + path.string() + "': no such file");
  }
  require_regular_file(path, "run file");  // HDF5 would block on a FIFO
  // Written in place: a second name would see the change (io/marked_directory.hpp).
  if (flags & H5F_ACC_RDWR) {
    struct stat st {};
    if (::lstat(path.c_str(), &st) == 0 && st.st_nlink > 1) refuse_hard_link(path, st.st_nlink);
  }
  const hid_t id = H5Fopen(path.c_str(), flags, H5P_DEFAULT);
  if (id < 0) {
    throw UserError(std::string("cannot ") + doing + " '" + path.string() +
                    "': " + h5::take_error_message());
  }
  Handle file(id, H5Fclose);
  bool ours = false;
  try {
    ours = h5::has_attribute(file.get(), "granshock_file") &&
           h5::read_string_attribute(file.get(), "granshock_file") == kFileKind &&
           h5::exists(file.get(), kParticles);
  } catch (const h5::Hdf5Error&) {
    ours = false;
  }
  if (!ours) {
    throw UserError(std::string("cannot ") + doing + " '" + path.string() +
                    "': not a granshock run file");
  }
  const int version = h5::naming_file_in_errors(path, "reading", [&] {
    return h5::read_attribute<int>(file.get(), "granshock_format_version");
  });
  if (version > kFormatVersion) {
    throw UserError(std::string("cannot ") + doing + " '" + path.string() +
                    "': it is a run file of format " + std::to_string(version) +
                    ", written by a newer granshock (this one reads formats 1 to " +
                    std::to_string(kFormatVersion) + ")");
  }
  return file;
}

// Whether the snapshot datasets make a frame's chunks when they grow to it, as parallel
// HDF5 needs (create_time_element); files from before collective output do not.
bool snapshot_chunks_made_early(hid_t file) {
  Handle set = h5::open_dataset(file, std::string(kParticles) + "/position/value");
  Handle props = h5::plist(H5Dget_create_plist(set.get()), "reading dataset properties");
  H5D_alloc_time_t when = H5D_ALLOC_TIME_DEFAULT;
  h5::check(H5Pget_alloc_time(props.get(), &when), "reading the allocation time");
  return when == H5D_ALLOC_TIME_EARLY;
}

int read_dim(hid_t file) {
  Handle box = h5::open_group(file, std::string(kParticles) + "/box");
  return h5::read_attribute<int>(box.get(), "dimension");
}

// The /observables series, one per TimeSeriesRow field (core/time_series.hpp): calls
// visit(name, value, unit) for each, "particles" last (its step marks a row as complete:
// series_end reads it). The one list of them, for creating and for appending.
template <class Visit>
void for_each_observable(const TimeSeriesRow& row, Visit&& visit) {
  visit("kinetic_energy", row.kinetic_energy, "J");
  visit("temperature", row.temperature, "J");
  visit("contacts", row.contacts, nullptr);
  visit("inserted", row.inserted, nullptr);
  visit("deleted_outlet", row.deleted_outlet, nullptr);
  visit("deleted_inlet", row.deleted_inlet, nullptr);
  visit("particles", row.particles, nullptr);
}

// Opens the object at `path` (group or dataset) for attributes, creating a group when
// nothing is there yet.
Handle attribute_target(hid_t file, const std::string& path) {
  if (path.empty() || path == "/" || !h5::exists(file, path)) return h5::require_group(file, path);
  return h5::object(H5Oopen(file, path.c_str(), H5P_DEFAULT), "opening '" + path + "'");
}

Handle attribute_source(hid_t file, const std::string& path) {
  const std::string where = path.empty() ? "/" : path;
  return h5::object(H5Oopen(file, where.c_str(), H5P_DEFAULT), "opening '" + where + "'");
}

// A random identity for a new run, written into run.h5 and every checkpoint of the run so
// that a resume never joins files of two runs (docs/output_format.md).
std::string new_run_id() {
  std::random_device random;
  std::string id;
  for (int k = 0; k < 4; ++k) id += fmt::format("{:08x}", std::uint32_t(random()));
  return id;
}

std::string read_run_id(hid_t file) {
  return h5::has_attribute(file, kRunIdAttribute) ? h5::read_string_attribute(file, kRunIdAttribute)
                                                  : std::string();
}

// The entries of GROUP/step at or before `step`.
struct Entries {
  long up_to = 0;
  long last_step = -1;  // the last of them; -1: none
};

Entries entries_up_to(hid_t file, const std::string& group_path, long step) {
  const std::vector<long> steps = h5::read_dataset<long>(file, group_path + "/step");
  Entries e;
  for (long s : steps) {
    if (s > step) break;
    ++e.up_to;
    e.last_step = s;
  }
  return e;
}

// A resume joins run.h5 to the checkpoint only when the checkpoint was written with this
// file: the same run id, and the frames and rows it recorded, at or before its step.
void check_against_checkpoint(hid_t file, const fs::path& path, long step,
                              const RunFileRecord& checkpoint) {
  // A checkpoint from before the record cannot be checked (and a resume that stopped
  // before writing a checkpoint with a record must be able to start again from it).
  if (checkpoint.run_id.empty()) return;
  const std::string id = read_run_id(file);
  if (checkpoint.run_id != id)
    throw UserError(fmt::format(
        "--resume: '{}' belongs to another run than the checkpoint.h5 beside it (run id "
        "{}, the checkpoint's '{}'); put back the run.h5 of the checkpoint's run, or start "
        "again with --overwrite",
        path.string(), id.empty() ? std::string("none: it is older than run ids") : "'" + id + "'",
        checkpoint.run_id));
  const Entries frames = entries_up_to(file, std::string(kParticles) + "/count", step);
  const Entries rows = entries_up_to(file, std::string(kObservables) + "/particles", step);
  if (frames.up_to == checkpoint.frames && rows.up_to == checkpoint.rows) return;
  const long last = std::max(frames.last_step, rows.last_step);
  throw UserError(fmt::format(
      "--resume: '{}' holds {} snapshot{} and {} time-series row{} up to step {}{}, but the "
      "checkpoint.h5 beside it (step {}) was written when it held {} and {}; it is not the "
      "run.h5 that checkpoint was written with: put that one back, or start again with "
      "--overwrite",
      path.string(), frames.up_to, frames.up_to == 1 ? "" : "s", rows.up_to,
      rows.up_to == 1 ? "" : "s", step,
      last >= 0 ? fmt::format(" (its last at step {})", last) : std::string(), step,
      checkpoint.frames, checkpoint.rows));
}

// What one more entry adds to below `group` (/particles/all or /observables), as the file
// holds it: the 1-D series of every time-indexed element (step, time, a scalar's value)
// and the per-particle arrays (frame x particle [x components]), with their chunking, so
// that the bounds of run_file_growth.hpp follow the layout.
struct EntryLayout {
  std::vector<run_growth::SeriesArray> series;
  std::vector<run_growth::ParticleArray> particles;
};

EntryLayout entry_layout(hid_t file, const std::string& group) {
  EntryLayout layout;
  auto add = [&](const std::string& path) {
    if (!h5::exists(file, path)) return;
    Handle set = h5::open_dataset(file, path);
    const std::vector<hsize_t> shape = h5::shape_of(set.get());
    Handle props = h5::plist(H5Dget_create_plist(set.get()), "reading dataset properties");
    std::vector<hsize_t> chunk(shape.size(), 0);
    if (H5Pget_layout(props.get()) == H5D_CHUNKED)
      h5::check(H5Pget_chunk(props.get(), int(chunk.size()), chunk.data()), "reading the chunks");
    Handle type = h5::datatype(H5Dget_type(set.get()), "reading the type");
    std::uintmax_t bytes = H5Tget_size(type.get());
    if (shape.size() == 1) {
      layout.series.push_back({chunk[0], bytes});
      return;
    }
    for (std::size_t k = 2; k < shape.size(); ++k) bytes *= shape[k];
    layout.particles.push_back({chunk.size() > 1 ? chunk[1] : 0, bytes});
  };
  Handle g = h5::open_group(file, group);
  H5G_info_t info{};
  h5::check(H5Gget_info(g.get(), &info), "listing '" + group + "'");
  for (hsize_t k = 0; k < info.nlinks; ++k) {
    const ssize_t length =
        H5Lget_name_by_idx(g.get(), ".", H5_INDEX_NAME, H5_ITER_INC, k, nullptr, 0, H5P_DEFAULT);
    h5::check(herr_t(length < 0 ? -1 : 0), "listing '" + group + "'");
    std::string name(std::size_t(length) + 1, '\0');
    H5Lget_name_by_idx(g.get(), ".", H5_INDEX_NAME, H5_ITER_INC, k, name.data(), name.size(),
                       H5P_DEFAULT);
    name.resize(std::size_t(length));
    const std::string element = group + "/" + name;
    if (!h5::exists(file, element + "/step")) continue;
    for (const char* part : {"step", "time", "value"}) add(element + "/" + part);
  }
  return layout;
}

// The groups, header and empty time-indexed datasets of a new run file.
void write_layout(hid_t f, const std::string& scene_toml_as_given,
                  const std::string& scene_toml_resolved, int dim, const SnapshotContents& contents,
                  const std::string& build) {
  h5::write_attribute(f, "granshock_file", kFileKind);
  h5::write_attribute(f, "granshock_format_version", kFormatVersion);
  h5::write_attribute(f, kRunIdAttribute, new_run_id());

  Handle h5md = h5::require_group(f, "/h5md");
  h5::write_attribute(h5md.get(), "version", std::vector<int>{1, 1});
  Handle creator = h5::require_group(f, "/h5md/creator");
  h5::write_attribute(creator.get(), "name", "granshock");
  h5::write_attribute(creator.get(), "version", GRANSHOCK_VERSION_STRING);
  if (!build.empty()) h5::write_attribute(creator.get(), "build", build);
  Handle author = h5::require_group(f, "/h5md/author");
  h5::write_attribute(author.get(), "name", "granshock");

  h5::write_string_dataset(f, "/scene/as_given", scene_toml_as_given);
  h5::write_string_dataset(f, "/scene/resolved", scene_toml_resolved);

  // H5MD requires a box; the domain itself (walls, inflow, obstacle) is in the scene.
  Handle box = h5::require_group(f, std::string(kParticles) + "/box");
  h5::write_attribute(box.get(), "dimension", dim);

  const std::string all = kParticles;
  const hsize_t d = static_cast<hsize_t>(dim);
  create_time_element(f, all + "/position", H5T_IEEE_F64LE, {0, d}, &kFloatFill, H5T_NATIVE_DOUBLE,
                      "m");
  create_time_element(f, all + "/velocity", H5T_IEEE_F64LE, {0, d}, &kFloatFill, H5T_NATIVE_DOUBLE,
                      "m s-1");
  create_time_element(f, all + "/species", H5T_STD_I32LE, {0}, &kIntFill, H5T_NATIVE_INT, nullptr);
  create_time_element(f, all + "/id", H5T_STD_I32LE, {0}, &kIntFill, H5T_NATIVE_INT, nullptr);
  if (!contents.species_radius.empty()) {
    create_time_element(f, all + "/radius", H5T_IEEE_F64LE, {0}, &kFloatFill, H5T_NATIVE_DOUBLE,
                        "m");
    h5::write_dataset(f, kSpeciesRadius, contents.species_radius,
                      {hsize_t(contents.species_radius.size())}, h5::Checksum::fletcher32);
    h5::write_attribute(h5::open_dataset(f, kSpeciesRadius).get(), "unit", "m");
  }
  if (contents.angular_velocity) {
    create_time_element(f, all + "/angular_velocity", H5T_IEEE_F64LE, {0}, &kFloatFill,
                        H5T_NATIVE_DOUBLE, "rad s-1");
  }
  create_time_element(f, all + "/count", H5T_STD_I64LE, {}, nullptr, H5T_NATIVE_LONG, nullptr);

  for_each_observable(TimeSeriesRow{}, [&](const char* name, auto value, const char* unit) {
    const bool integer = std::is_integral_v<decltype(value)>;
    create_time_element(f, std::string(kObservables) + "/" + name,
                        integer ? H5T_STD_I64LE : H5T_IEEE_F64LE, {}, nullptr, H5T_NATIVE_DOUBLE,
                        unit);
  });
  h5::check(H5Fflush(f, H5F_SCOPE_GLOBAL), "flushing");
}

}  // namespace

namespace {

// What the snapshots of `file` hold: the elements it was created with.
SnapshotContents read_contents(hid_t file) {
  SnapshotContents contents;
  const std::string all = kParticles;
  if (h5::exists(file, all + "/radius"))
    contents.species_radius = h5::read_dataset<double>(file, kSpeciesRadius);
  contents.angular_velocity = h5::exists(file, all + "/angular_velocity");
  return contents;
}

}  // namespace

RunFile::RunFile(fs::path path, h5::Handle file, int dim)
    : path_(std::move(path)), file_(std::move(file)), dim_(dim) {
  contents_ =
      h5::naming_file_in_errors(path_, "reading", [&] { return read_contents(file_.get()); });
  settle();
}

void RunFile::settle() {
  // HDF5's end of allocation, or the file's size when that is larger (H5Fget_eoa would
  // be exact, but parallel HDF5's driver does not answer it).
  hsize_t end = 0;
  h5::naming_file_in_errors(path_, "reading", [&] {
    h5::check(H5Fget_filesize(file_.get(), &end), "reading the end of allocation");
  });
  settled_ = end;
  promised_ = 0;
  // Bytes past the end are room reserved before and not used (allocated on disk).
  reserved_ = std::max<std::uintmax_t>(end, file_bytes(path_));
}

int RunFile::try_make_room(std::uintmax_t growth) {
  // The bounds of the changes since the last flush add up: past 1 MiB the file is flushed
  // first (the rows of a time series, 16 KiB each, take a few bytes), so that the room
  // reserved never runs far ahead of the file.
  if (promised_ > 0 && promised_ + growth > kMostPromised) flush();
  const std::uintmax_t end = settled_ + promised_ + growth;
  if (end > reserved_) {
    // In steps of 256 KiB: one reservation serves many rows of a time series.
    const std::uintmax_t step = std::uintmax_t(1) << 18;
    const std::uintmax_t until = (end + step - 1) / step * step;
    if (const int refused = reserve_file_bytes(path_, reserved_, until); refused != 0)
      return refused;
    reserved_ = until;
  }
  promised_ += growth;
  return 0;
}

void RunFile::make_room(std::uintmax_t growth, const std::string& what) {
  if (const int refused = try_make_room(growth); refused != 0)
    throw UserError(
        fmt::format("writing '{}' failed: no room for {} ({:.2f} MB reserved before writing): {}",
                    path_.string(), what, double(growth) / 1e6, std::strerror(refused)));
}

const RunFile::GrowthLayout& RunFile::growth_layout() const {
  if (!growth_layout_) {
    h5::naming_file_in_errors(path_, "reading", [&] {
      EntryLayout frame = entry_layout(file_.get(), kParticles);
      GrowthLayout layout;
      layout.frame_series = std::move(frame.series);
      layout.particles = std::move(frame.particles);
      layout.row_series = entry_layout(file_.get(), kObservables).series;
      growth_layout_ = std::move(layout);
    });
  }
  return *growth_layout_;
}

std::uintmax_t RunFile::snapshot_growth(long total) const {
  const long frames = long(h5::naming_file_in_errors(path_, "reading", [&] {
    return series_end(file_.get(), std::string(kParticles) + "/count").entries;
  }));
  const long capacity = particle_capacity();
  return run_growth::snapshot_rows(frames, capacity, std::max(capacity, total),
                                   growth_layout().particles);
}

std::uintmax_t RunFile::completion_growth(long total) const {
  return h5::naming_file_in_errors(path_, "reading", [&] {
    const hid_t f = file_.get();
    const long frames = long(series_end(f, std::string(kParticles) + "/count").entries);
    // The new frame's views, and those of earlier frames without any (a file from before
    // views, resumed).
    long without_views = 1;
    for (long k = 0; k < frames; ++k) without_views += h5::exists(f, frame_view_group(k)) ? 0 : 1;
    const long vertices = vertex_index_length(f);
    return run_growth::series_entries(frames, growth_layout().frame_series) +
           run_growth::frame_views(without_views, frame_view_arrays().size() + 2, vertices,
                                   std::max({vertices, total, particle_capacity()}),
                                   kVertexIndexChunk);
  });
}

RunFile RunFile::create(const fs::path& path, const std::string& scene_toml_as_given,
                        const std::string& scene_toml_resolved, int dim,
                        const SnapshotContents& contents, const std::string& build) {
  if (dim != 2 && dim != 3) throw std::invalid_argument("RunFile: dim must be 2 or 3");
  h5::silence_error_printing();
  const hid_t id = H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
  if (id < 0) {
    throw UserError("cannot create '" + path.string() + "': " + h5::take_error_message());
  }
  Handle file(id, H5Fclose);
  try {
    h5::naming_file_in_errors(path, "creating", [&] {
      write_layout(file.get(), scene_toml_as_given, scene_toml_resolved, dim, contents, build);
    });
  } catch (...) {
    // No half-made run file left behind.
    file.close();
    std::error_code ignored;
    fs::remove(path, ignored);
    throw;
  }
  return RunFile(path, std::move(file), dim);
}

RunFile RunFile::open_for_resume(const fs::path& path, long checkpoint_step,
                                 const RunFileRecord& checkpoint) {
  Handle file = open_existing(path, H5F_ACC_RDWR, "resume");
  h5::naming_file_in_errors(path, "resuming", [&] {
    check_against_checkpoint(file.get(), path, checkpoint_step, checkpoint);
  });
  const int dim = h5::naming_file_in_errors(path, "resuming", [&] { return read_dim(file.get()); });
  RunFile run(path, std::move(file), dim);
  run.make_room(run_growth::truncation() + run_growth::attribute(64), "resuming");
  h5::naming_file_in_errors(path, "resuming", [&] {
    const hid_t f = run.file_.get();
    std::vector<std::string> groups;
    h5::check(H5Lvisit(f, H5_INDEX_NAME, H5_ITER_INC, collect_step_groups, &groups),
              "listing the time series");
    for (const std::string& group : groups) truncate_after(f, group, checkpoint_step);
    // A run from before the record: from now on its checkpoints record this file.
    if (read_run_id(f).empty()) h5::write_attribute(f, kRunIdAttribute, new_run_id());
  });
  run.flush();
  return run;
}

void RunFile::check_resumable(const fs::path& path, long checkpoint_step,
                              const RunFileRecord& checkpoint) {
  Handle file = open_existing(path, H5F_ACC_RDONLY, "resume");
  h5::naming_file_in_errors(path, "resuming", [&] {
    check_against_checkpoint(file.get(), path, checkpoint_step, checkpoint);
  });
}

RunFile RunFile::open_for_append(const fs::path& path) {
  Handle file = open_existing(path, H5F_ACC_RDWR, "write");
  const int dim = h5::naming_file_in_errors(path, "opening", [&] { return read_dim(file.get()); });
  return RunFile(path, std::move(file), dim);
}

RunFile RunFile::open_collectively(const fs::path& path, MPI_Comm comm) {
  h5::silence_error_printing();
  return h5::naming_file_in_errors(path, "opening (parallel HDF5)", [&] {
    Handle access = h5::plist(H5Pcreate(H5P_FILE_ACCESS), "creating file access properties");
    h5::check(H5Pset_fapl_mpio(access.get(), comm, MPI_INFO_NULL), "choosing MPI-IO");
    Handle file = h5::file(H5Fopen(path.c_str(), H5F_ACC_RDWR, access.get()), "H5Fopen");
    // Every process sees the same file, so all refuse alike.
    if (!snapshot_chunks_made_early(file.get()))
      throw UserError("'" + path.string() +
                      "' was written by an earlier granshock, whose snapshots parallel HDF5 "
                      "cannot append to: resume this run on one process");
    const int dim = read_dim(file.get());
    RunFile shared(path, std::move(file), dim);
    shared.transfer_ = h5::plist(H5Pcreate(H5P_DATASET_XFER), "creating transfer properties");
    h5::check(H5Pset_dxpl_mpio(shared.transfer_.get(), H5FD_MPIO_COLLECTIVE),
              "choosing collective transfers");
    return shared;
  });
}

RunFile RunFile::open_read_only(const fs::path& path) {
  Handle file = open_existing(path, H5F_ACC_RDONLY, "read");
  const int dim = h5::naming_file_in_errors(path, "reading", [&] { return read_dim(file.get()); });
  return RunFile(path, std::move(file), dim);
}

void RunFile::append_snapshot(long step, double time, const HostParticles& p) {
  const long n = long(p.size());
  make_room(snapshot_growth(n) + completion_growth(n), "the next snapshot");
  const long frame = write_snapshot_rows(
      step, p, n > 0 ? std::vector<FileRows>{{0, n}} : std::vector<FileRows>{}, n);
  complete_snapshot(frame, step, time, n);
  // Settled at once: the next append reserves room past this one's actual end, not past
  // its bound (which deflate's worst case makes several times a small frame's size).
  flush();
}

long RunFile::write_snapshot_rows(long step, const HostParticles& p,
                                  const std::vector<FileRows>& rows, long total) {
  const std::size_t n = p.size();
  if (p.velocity.size() != n || p.species.size() != n || p.id.size() != n) {
    throw std::invalid_argument("RunFile: snapshot particle arrays differ in length");
  }
  long covered = 0;
  for (const FileRows& r : rows) {
    if (r.first < 0 || r.count <= 0 || r.first + r.count > total)
      throw std::invalid_argument("RunFile: snapshot rows outside the frame");
    covered += r.count;
  }
  if (covered != long(n))
    throw std::invalid_argument("RunFile: snapshot rows do not cover the particles");
  // Checked before anything is written: under parallel HDF5 every process must write.
  std::vector<double> radius;
  if (!contents_.species_radius.empty()) {
    for (int s : p.species) {
      if (s < 0 || std::size_t(s) >= contents_.species_radius.size())
        throw std::invalid_argument("RunFile: species " + std::to_string(s) + " has no radius");
      radius.push_back(contents_.species_radius[std::size_t(s)]);
    }
  }
  std::vector<double> spin = p.angular_velocity;
  if (spin.empty()) spin.assign(n, 0.0);
  if (spin.size() != n)
    throw std::invalid_argument("RunFile: snapshot particle arrays differ in length");
  return h5::naming_file_in_errors(path_, "writing", [&] {
    const hid_t f = file_.get();
    const std::string all = kParticles;
    const SeriesEnd end = series_end(f, all + "/count");
    require_increasing(end, step, "snapshot");
    const hsize_t frame = end.entries;
    const hsize_t capacity =
        std::max(static_cast<hsize_t>(particle_capacity()), static_cast<hsize_t>(total));
    const hsize_t d = static_cast<hsize_t>(dim_);
    const hid_t transfer = transfer_.valid() ? transfer_.get() : H5P_DEFAULT;

    // Quasi-2-D stores x, y only: copy the first dim components into one block.
    std::vector<double> block(n * static_cast<std::size_t>(dim_));
    auto write_vectors = [&](const char* name, const std::vector<std::array<double, 3>>& v) {
      const std::size_t width = static_cast<std::size_t>(dim_);
      for (std::size_t i = 0; i < n; ++i) {
        for (std::size_t c = 0; c < width; ++c) block[i * width + c] = v[i][c];
      }
      Handle set = h5::open_dataset(f, all + "/" + name + "/value");
      write_frame_rows(set.get(), {frame + 1, capacity, d}, frame, rows, H5T_NATIVE_DOUBLE,
                       block.data(), transfer);
    };
    auto write_scalars = [&](const char* name, const std::vector<int>& v) {
      Handle set = h5::open_dataset(f, all + "/" + name + "/value");
      write_frame_rows(set.get(), {frame + 1, capacity}, frame, rows, H5T_NATIVE_INT, v.data(),
                       transfer);
    };
    write_vectors("position", p.position);
    write_vectors("velocity", p.velocity);
    write_scalars("species", p.species);
    write_scalars("id", p.id);
    auto write_doubles = [&](const char* name, const std::vector<double>& v) {
      Handle set = h5::open_dataset(f, all + "/" + name + "/value");
      write_frame_rows(set.get(), {frame + 1, capacity}, frame, rows, H5T_NATIVE_DOUBLE, v.data(),
                       transfer);
    };
    if (!contents_.species_radius.empty()) write_doubles("radius", radius);
    if (contents_.angular_velocity) write_doubles("angular_velocity", spin);
    return long(frame);
  });
}

void RunFile::complete_snapshot(long frame, long step, double time, long total) {
  if (transfer_.valid()) throw std::logic_error("RunFile: a snapshot is completed by one process");
  h5::naming_file_in_errors(path_, "writing", [&] {
    const hid_t f = file_.get();
    const std::string all = kParticles;
    const SeriesEnd end = series_end(f, all + "/count");
    if (hsize_t(frame) != end.entries)
      throw std::logic_error("RunFile: the snapshot completed is not the next frame");
    require_increasing(end, step, "snapshot");
    const hsize_t index = hsize_t(frame);
    for (const char* name : {"position", "velocity", "species", "id"})
      append_step_time(f, all + "/" + name, index, step, time);
    if (!contents_.species_radius.empty()) append_step_time(f, all + "/radius", index, step, time);
    if (contents_.angular_velocity)
      append_step_time(f, all + "/angular_velocity", index, step, time);
    // The frame's views for XDMF readers (docs/output_format.md, "run.xmf").
    std::vector<long> counts = h5::read_dataset<long>(f, all + "/count/value");
    counts.resize(index);
    counts.push_back(total);
    update_frame_views(f, dim_, counts);
    // count last: frames() lists a frame once all of its data is there.
    append_scalar<long>(f, all + "/count", index, step, time, total);
  });
}

// docs/scaling.md, "Output: gathered or collective": from one and a half chunks on, the
// second chunk is large enough for the processes to share the compression: writing
// collectively then breaks even with gathering to rank 0, and wins above.
bool RunFile::collective_pays(long total) {
  return total >= long(3 * kParticleChunk / 2);
}

void RunFile::append_snapshot_collectively(const std::filesystem::path& path, MPI_Comm comm,
                                           long step, double time, const SnapshotPart& part,
                                           std::optional<RunFile>& root_file) {
  int rank = 0;
  MPI_Comm_rank(comm, &rank);
  if ((rank == 0) != root_file.has_value())
    throw std::logic_error("RunFile: rank 0 alone holds the run file between snapshots");
  // Parallel HDF5 opens the file on every process: rank 0's own handle closes first.
  root_file.reset();
  long frame = 0;
  {
    RunFile shared = open_collectively(path, comm);
    // Room for the frame before any process writes, reserved by rank 0 and known to all:
    // refused, every process leaves the file as it was (docs/parallel.md, "Errors").
    // Every process reads the layout: datasets opened by rank 0 alone left the processes'
    // metadata caches disagreeing, and the frame's chunks damaged ("inflate() failed").
    const std::uintmax_t growth = shared.snapshot_growth(part.total);
    int refused = rank == 0 ? shared.try_make_room(growth) : 0;
    MPI_Bcast(&refused, 1, MPI_INT, 0, comm);
    if (refused != 0) {
      failure_agreed() = true;
      if (rank != 0) throw PeerFailed(0);
      throw UserError(fmt::format(
          "writing '{}' failed: no room for the next snapshot ({:.2f} MB reserved before "
          "writing): {}",
          path.string(), double(growth) / 1e6, std::strerror(refused)));
    }
    try {
      frame = shared.write_snapshot_rows(step, part.particles, part.rows, part.total);
    } catch (...) {
      // The others may wait in a collective write: closing would wait for them forever.
      // The failure ends the job (apps/granshock/main.cpp).
      shared.file_.abandon();
      throw;
    }
  }  // closed (collective) before rank 0 reopens it
  if (rank != 0) return;
  root_file.emplace(open_for_append(path));
  root_file->make_room(root_file->completion_growth(part.total), "the next snapshot");
  root_file->complete_snapshot(frame, step, time, part.total);
  root_file->flush();
}

void RunFile::append_time_series(const TimeSeriesRow& row) {
  const long rows = long(h5::naming_file_in_errors(path_, "reading", [&] {
    return series_end(file_.get(), std::string(kObservables) + "/particles").entries;
  }));
  make_room(run_growth::series_entries(rows, growth_layout().row_series),
            "the next time-series row");
  h5::naming_file_in_errors(path_, "writing", [&] {
    const hid_t f = file_.get();
    const std::string root = kObservables;
    const SeriesEnd end = series_end(f, root + "/particles");
    require_increasing(end, row.step, "time-series row");
    const hsize_t index = end.entries;
    for_each_observable(row, [&](const char* name, auto value, const char*) {
      append_scalar<decltype(value)>(f, root + "/" + name, index, row.step, row.time, value);
    });
  });
}

std::vector<SnapshotFrame> RunFile::frames() const {
  return h5::naming_file_in_errors(path_, "reading", [&] {
    const std::string count = std::string(kParticles) + "/count";
    const std::vector<long> steps = h5::read_dataset<long>(file_.get(), count + "/step");
    const std::vector<double> times = h5::read_dataset<double>(file_.get(), count + "/time");
    const std::vector<long> counts = h5::read_dataset<long>(file_.get(), count + "/value");
    std::vector<SnapshotFrame> result(std::min({steps.size(), times.size(), counts.size()}));
    for (std::size_t i = 0; i < result.size(); ++i) result[i] = {steps[i], times[i], counts[i]};
    return result;
  });
}

namespace {

// Rows [0, count) of frame `frame` of the per-particle dataset GROUP/value: `width`
// components a row (0: one scalar), into `out`.
template <class T>
void read_frame_rows(hid_t file, const std::string& group, long frame, long count, hsize_t width,
                     std::vector<T>& out) {
  Handle set = h5::open_dataset(file, group + "/value");
  Handle file_space = h5::dataspace(H5Dget_space(set.get()), "reading a dataspace");
  const hsize_t start[3] = {hsize_t(frame), 0, 0};
  const hsize_t rows[3] = {1, hsize_t(count), std::max<hsize_t>(width, 1)};
  const int rank = width > 0 ? 3 : 2;
  h5::check(H5Sselect_hyperslab(file_space.get(), H5S_SELECT_SET, start, nullptr, rows, nullptr),
            "selecting a frame's rows of '" + group + "'");
  out.resize(std::size_t(count) * std::max<hsize_t>(width, 1));
  Handle memory_space =
      h5::dataspace(H5Screate_simple(rank, rows, nullptr), "creating a dataspace");
  if (count > 0)
    h5::check(H5Dread(set.get(), h5::TypeOf<T>::memory(), memory_space.get(), file_space.get(),
                      H5P_DEFAULT, out.data()),
              "reading a frame of '" + group + "'");
}

}  // namespace

HostParticles RunFile::read_snapshot(long frame) const {
  return h5::naming_file_in_errors(path_, "reading", [&] {
    const std::vector<SnapshotFrame> all = frames();
    if (frame < 0 || std::size_t(frame) >= all.size())
      throw UserError(fmt::format("'{}' has {} snapshots; there is no snapshot {}", path_.string(),
                                  all.size(), frame));
    const long n = all[std::size_t(frame)].count;
    const std::string base = kParticles;
    std::vector<double> x, v;
    read_frame_rows(file_.get(), base + "/position", frame, n, hsize_t(dim_), x);
    read_frame_rows(file_.get(), base + "/velocity", frame, n, hsize_t(dim_), v);
    HostParticles p;
    read_frame_rows(file_.get(), base + "/species", frame, n, 0, p.species);
    read_frame_rows(file_.get(), base + "/id", frame, n, 0, p.id);
    if (contents_.angular_velocity)
      read_frame_rows(file_.get(), base + "/angular_velocity", frame, n, 0, p.angular_velocity);
    for (long i = 0; i < n; ++i) {
      std::array<double, 3> xi{0, 0, 0}, vi{0, 0, 0};
      for (int k = 0; k < dim_; ++k) {
        xi[std::size_t(k)] = x[std::size_t(i * dim_ + k)];
        vi[std::size_t(k)] = v[std::size_t(i * dim_ + k)];
      }
      p.position.push_back(xi);
      p.velocity.push_back(vi);
    }
    return p;
  });
}

RunFileRecord RunFile::record() const {
  return h5::naming_file_in_errors(path_, "reading", [&] {
    RunFileRecord r;
    r.run_id = read_run_id(file_.get());
    r.frames = long(series_end(file_.get(), std::string(kParticles) + "/count").entries);
    r.rows = long(series_end(file_.get(), std::string(kObservables) + "/particles").entries);
    return r;
  });
}

long RunFile::particle_capacity() const {
  return h5::naming_file_in_errors(path_, "reading", [&] {
    Handle set = h5::open_dataset(file_.get(), std::string(kParticles) + "/position/value");
    return static_cast<long>(h5::shape_of(set.get()).at(1));
  });
}

std::vector<FrameViewArray> RunFile::frame_view_arrays() const {
  return h5::naming_file_in_errors(path_, "reading",
                                   [&] { return granshock::frame_view_arrays(file_.get()); });
}

std::string RunFile::scene_as_given() const {
  return h5::naming_file_in_errors(
      path_, "reading", [&] { return h5::read_string_dataset(file_.get(), "/scene/as_given"); });
}

std::string RunFile::scene_resolved() const {
  return h5::naming_file_in_errors(
      path_, "reading", [&] { return h5::read_string_dataset(file_.get(), "/scene/resolved"); });
}

void RunFile::replace_scene(const std::string& scene_toml_as_given,
                            const std::string& scene_toml_resolved) {
  make_room(run_growth::whole_dataset(scene_toml_as_given.size()) +
                run_growth::whole_dataset(scene_toml_resolved.size()),
            "the scene");
  h5::naming_file_in_errors(path_, "writing", [&] {
    h5::write_string_dataset(file_.get(), "/scene/as_given", scene_toml_as_given);
    h5::write_string_dataset(file_.get(), "/scene/resolved", scene_toml_resolved);
  });
}

bool RunFile::has(const std::string& path) const {
  return h5::naming_file_in_errors(path_, "reading", [&] { return h5::exists(file_.get(), path); });
}

void RunFile::write_attribute(const std::string& object, const std::string& name, double value) {
  make_room(run_growth::attribute(sizeof value), "an attribute");
  h5::naming_file_in_errors(path_, "writing", [&] {
    h5::write_attribute(attribute_target(file_.get(), object).get(), name, value);
  });
}

void RunFile::write_attribute(const std::string& object, const std::string& name, long value) {
  make_room(run_growth::attribute(sizeof value), "an attribute");
  h5::naming_file_in_errors(path_, "writing", [&] {
    h5::write_attribute(attribute_target(file_.get(), object).get(), name, value);
  });
}

void RunFile::write_attribute(const std::string& object, const std::string& name,
                              const std::string& value) {
  make_room(run_growth::attribute(value.size()), "an attribute");
  h5::naming_file_in_errors(path_, "writing", [&] {
    h5::write_attribute(attribute_target(file_.get(), object).get(), name, value);
  });
}

double RunFile::read_attribute_double(const std::string& object, const std::string& name) const {
  return h5::naming_file_in_errors(path_, "reading", [&] {
    return h5::read_attribute<double>(attribute_source(file_.get(), object).get(), name);
  });
}

long RunFile::read_attribute_long(const std::string& object, const std::string& name) const {
  return h5::naming_file_in_errors(path_, "reading", [&] {
    return h5::read_attribute<long>(attribute_source(file_.get(), object).get(), name);
  });
}

std::string RunFile::read_attribute_string(const std::string& object,
                                           const std::string& name) const {
  return h5::naming_file_in_errors(path_, "reading", [&] {
    return h5::read_string_attribute(attribute_source(file_.get(), object).get(), name);
  });
}

void RunFile::write_array(const std::string& dataset, const std::vector<double>& values,
                          const std::vector<long>& shape) {
  std::vector<hsize_t> dims;
  std::size_t elements = 1;
  for (long extent : shape) {
    if (extent < 0) throw std::invalid_argument("RunFile::write_array: negative extent");
    dims.push_back(static_cast<hsize_t>(extent));
    elements *= static_cast<std::size_t>(extent);
  }
  if (elements != values.size()) {
    throw std::invalid_argument("RunFile::write_array: shape does not match the value count");
  }
  make_room(run_growth::whole_dataset(values.size() * sizeof(double)), "'" + dataset + "'");
  h5::naming_file_in_errors(path_, "writing", [&] {
    h5::write_dataset(file_.get(), dataset, values, dims, h5::Checksum::fletcher32);
  });
}

std::vector<double> RunFile::read_array(const std::string& dataset,
                                        std::vector<long>* shape) const {
  return h5::naming_file_in_errors(path_, "reading", [&] {
    std::vector<hsize_t> dims;
    std::vector<double> values = h5::read_dataset<double>(file_.get(), dataset, &dims);
    if (shape != nullptr) shape->assign(dims.begin(), dims.end());
    return values;
  });
}

void RunFile::flush() {
  h5::naming_file_in_errors(
      path_, "flushing", [&] { h5::check(H5Fflush(file_.get(), H5F_SCOPE_GLOBAL), "H5Fflush"); });
  // Everything is written: the room reserved past HDF5's end is given back.
  haddr_t end = 0;
  h5::naming_file_in_errors(path_, "flushing", [&] {
    h5::check(H5Fget_eoa(file_.get(), &end), "reading the end of allocation");
  });
  trim_file(path_, end);
  settle();
}

}  // namespace granshock
