#include "io/checkpoint_file.hpp"

#include <algorithm>
#include <array>
#include <stdexcept>
#include <system_error>

#include "core/checkpoint_checks.hpp"
#include "core/user_error.hpp"
#include "io/checkpoint_seal.hpp"
#include "io/hdf5_helpers.hpp"
#include "io/hdf5_open.hpp"
#include "version.hpp"

namespace granshock {

namespace {

namespace fs = std::filesystem;
using h5::Handle;

constexpr const char* kFileKind = "checkpoint";
// 2: checksum header in a 512-byte user block (io/checkpoint_seal.hpp); 3 and 4:
// io/checkpoint_file.hpp.
constexpr int kFormatVersion = kCheckpointFormat;
// The first format that always holds /state@skin, /state@last_build_step and
// /run@cpu_seconds_so_far: a file of this format or later that lacks one is refused.
constexpr int kFormatWithEveryRecord = 4;

// The stored shape of a per-particle array: [rows, tail...], rows = size / prod(tail).
// Storing the real shape (not a flat list) lets h5py users read it as particles x
// components; the element count still reproduces the vector's length exactly.
std::vector<hsize_t> rows_shape(const char* name, std::size_t size, std::size_t particles,
                                const std::vector<hsize_t>& tail) {
  std::size_t width = 1;
  for (hsize_t extent : tail) width *= static_cast<std::size_t>(extent);
  std::vector<hsize_t> shape;
  if (width == 0) {
    // Zero components per particle (no history slots): nothing can be stored.
    if (size != 0) {
      throw std::invalid_argument(std::string("write_checkpoint: '") + name +
                                  "' has values but zero components per particle");
    }
    shape.push_back(static_cast<hsize_t>(particles));
  } else {
    if (size % width != 0) {
      throw std::invalid_argument(std::string("write_checkpoint: '") + name + "' has " +
                                  std::to_string(size) + " values, not a multiple of " +
                                  std::to_string(width));
    }
    shape.push_back(static_cast<hsize_t>(size / width));
  }
  shape.insert(shape.end(), tail.begin(), tail.end());
  return shape;
}

void write_state(hid_t file, const SolverState& s) {
  Handle state = h5::require_group(file, "/state");
  h5::write_attribute(state.get(), "dim", s.dim);
  h5::write_attribute(state.get(), "step", s.step);
  h5::write_attribute(state.get(), "next_id", s.next_id);
  h5::write_attribute(state.get(), "history_slots", s.history_slots);

  const std::size_t n = s.size();
  const hsize_t dim = static_cast<hsize_t>(s.dim < 0 ? 0 : s.dim);
  const hsize_t slots = static_cast<hsize_t>(s.history_slots < 0 ? 0 : s.history_slots);
  auto put = [&](const char* name, const auto& values, const std::vector<hsize_t>& tail) {
    h5::write_dataset(state.get(), name, values, rows_shape(name, values.size(), n, tail));
  };
  put("position", s.position, {dim});
  put("velocity", s.velocity, {dim});
  put("force", s.force, {dim});
  put("angular_velocity", s.angular_velocity, {});
  put("torque", s.torque, {});
  put("species", s.species, {});
  put("id", s.id, {});
  put("history_partner", s.history_partner, {slots});
  put("history_spring", s.history_spring, {slots, dim});
  put("history_obstacle_spring", s.history_obstacle_spring, {dim});
  // Absent where the solver held none (docs/output_format.md).
  if (!s.contact_virial.empty()) put("contact_virial", s.contact_virial, {dim, dim});

  // The neighbour list: restoring it avoids a rebuild that would change the run.
  put("reference_position", s.reference_position, {dim});
  h5::write_dataset(state.get(), "neighbour_offsets", s.neighbour_offsets,
                    {static_cast<hsize_t>(s.neighbour_offsets.size())});
  h5::write_dataset(state.get(), "neighbours", s.neighbours,
                    {static_cast<hsize_t>(s.neighbours.size())});
  h5::write_attribute(state.get(), "list_builds", s.list_builds);
  h5::write_attribute(state.get(), "skin", s.skin);
  h5::write_attribute(state.get(), "last_build_step", s.last_build_step);
  h5::write_attribute(state.get(), "removed_low",
                      std::vector<long>(s.removed_low.begin(), s.removed_low.end()));
  h5::write_attribute(state.get(), "removed_high",
                      std::vector<long>(s.removed_high.begin(), s.removed_high.end()));
}

// /scene/overrides/K: the K-th --set, each a string of its own (a value may hold any
// character); /run@scene_override_count says how many.
void write_overrides(hid_t file, hid_t run, const std::vector<std::string>& overrides) {
  h5::write_attribute(run, "scene_override_count", long(overrides.size()));
  for (std::size_t k = 0; k < overrides.size(); ++k)
    h5::write_string_dataset(file, "/scene/overrides/" + std::to_string(k), overrides[k]);
}

void write_extras(hid_t file, const CheckpointExtras& e) {
  Handle run = h5::require_group(file, "/run");
  h5::write_attribute(run.get(), "rng_counter", e.rng_counter);
  h5::write_attribute(run.get(), "inserted", e.inserted);
  h5::write_attribute(run.get(), "deleted_outlet", e.deleted_outlet);
  h5::write_attribute(run.get(), "deleted_inlet", e.deleted_inlet);
  h5::write_attribute(run.get(), "insertion_carry", e.insertion_carry);
  h5::write_attribute(run.get(), "wall_seconds_so_far", e.wall_seconds_so_far);
  h5::write_attribute(run.get(), "cpu_seconds_so_far", e.cpu_seconds_so_far);
  h5::write_dataset(run.get(), "bin_sums", e.bin_sums, {static_cast<hsize_t>(e.bin_sums.size())});
  h5::write_dataset(run.get(), "bin_shape", e.bin_shape,
                    {static_cast<hsize_t>(e.bin_shape.size())});
  h5::write_string_dataset(file, "/scene/resolved", e.scene_resolved);
  if (e.scene_overrides) write_overrides(file, run.get(), *e.scene_overrides);
  if (!e.run_id.empty()) {
    h5::write_attribute(run.get(), "run_id", e.run_id);
    h5::write_attribute(run.get(), "run_file_frames", e.run_frames);
    h5::write_attribute(run.get(), "run_file_rows", e.run_rows);
  }
}

// HDF5 converts between numeric types on reading; a checkpoint holds each value in the
// documented type only, so any other (a float where ids belong) is refused, not converted.
void expect_type(hid_t stored, hid_t documented) {
  const htri_t same = H5Tequal(stored, documented);
  h5::check(same, "comparing types");
  if (same == 0) throw h5::Hdf5Error("is not stored as the documented type");
}

// Reads one object of the checkpoint; a failure names it in full ("/state@step",
// "/state/position"). A dataset may not claim more values than the file has bytes: an
// edited file must not make the reader allocate without bound.
class Reader {
 public:
  Reader(hid_t file, std::uintmax_t file_bytes, int format)
      : file_(file), file_bytes_(file_bytes), format_(format) {}

  template <class T>
  T attribute(const char* group, const char* name) const {
    return named(group, "@", name, [&] {
      Handle g = h5::open_group(file_, group);
      expect_attribute_type<T>(g.get(), name);
      return h5::read_attribute<T>(g.get(), name);
    });
  }
  bool has(const std::string& path) const { return h5::exists(file_, path); }
  template <class T>
  T optional_attribute(const char* group, const char* name, T absent) const {
    {
      Handle g = h5::open_group(file_, group);
      if (!h5::has_attribute(g.get(), name)) return absent;
    }
    return attribute<T>(group, name);
  }
  // An attribute every file of format `since` or later holds; older files may lack it.
  template <class T>
  T attribute_since(int since, const char* group, const char* name, T absent) const {
    return format_ >= since ? attribute<T>(group, name)
                            : optional_attribute<T>(group, name, absent);
  }
  template <std::size_t N>
  void axes(const char* group, const char* name, std::array<long, N>& out) const {
    named(group, "@", name, [&] {
      Handle g = h5::open_group(file_, group);
      expect_attribute_type<long>(g.get(), name);
      const std::vector<long> values = h5::read_attribute_vector<long>(g.get(), name);
      if (values.size() != N)
        throw h5::Hdf5Error("has " + std::to_string(values.size()) + " values, not " +
                            std::to_string(N));
      std::copy(values.begin(), values.end(), out.begin());
      return 0;
    });
  }
  template <class T>
  std::vector<T> dataset(const char* group, const char* name) const {
    return named(group, "/", name, [&] {
      const std::string path = std::string(group) + "/" + name;
      Handle set = h5::open_dataset(file_, path);
      Handle type = h5::datatype(H5Dget_type(set.get()), "reading the type");
      expect_type(type.get(), h5::TypeOf<T>::stored());
      std::uintmax_t count = 1;
      for (hsize_t extent : h5::shape_of(set.get())) count *= extent;
      if (count > file_bytes_ / 4)  // every stored value takes at least 4 bytes
        throw h5::Hdf5Error("claims " + std::to_string(count) +
                            " values, more than the file holds");
      return h5::read_dataset<T>(file_, path);
    });
  }

 private:
  template <class T>
  static void expect_attribute_type(hid_t group, const char* name) {
    Handle attr = h5::attribute(H5Aopen(group, name, H5P_DEFAULT), "opening the attribute");
    Handle type = h5::datatype(H5Aget_type(attr.get()), "reading the type");
    expect_type(type.get(), h5::TypeOf<T>::stored());
  }

  template <class F>
  auto named(const char* group, const char* separator, const char* name, F&& read) const {
    try {
      return read();
    } catch (const h5::Hdf5Error& e) {
      throw h5::Hdf5Error(std::string(group) + separator + name + ": " + e.what());
    }
  }

  hid_t file_;
  std::uintmax_t file_bytes_;
  int format_;
};

SolverState read_state(const Reader& in) {
  SolverState s;
  s.dim = in.attribute<int>("/state", "dim");
  s.step = in.attribute<long>("/state", "step");
  s.next_id = in.attribute<int>("/state", "next_id");
  s.history_slots = in.attribute<int>("/state", "history_slots");
  s.position = in.dataset<double>("/state", "position");
  s.velocity = in.dataset<double>("/state", "velocity");
  s.force = in.dataset<double>("/state", "force");
  s.angular_velocity = in.dataset<double>("/state", "angular_velocity");
  s.torque = in.dataset<double>("/state", "torque");
  s.species = in.dataset<int>("/state", "species");
  s.id = in.dataset<int>("/state", "id");
  s.history_partner = in.dataset<int>("/state", "history_partner");
  s.history_spring = in.dataset<double>("/state", "history_spring");
  s.history_obstacle_spring = in.dataset<double>("/state", "history_obstacle_spring");
  // Absent where the solver held none, and in format-3 files written before it was kept:
  // the solver then computes a sample's virial itself.
  if (in.has("/state/contact_virial"))
    s.contact_virial = in.dataset<double>("/state", "contact_virial");
  s.reference_position = in.dataset<double>("/state", "reference_position");
  s.neighbour_offsets = in.dataset<int>("/state", "neighbour_offsets");
  s.neighbours = in.dataset<int>("/state", "neighbours");
  s.list_builds = in.attribute<long>("/state", "list_builds");
  // Format 3 may lack them (written before the adaptive skin): the scene's skin, and no
  // build step recorded.
  s.skin = in.attribute_since<double>(kFormatWithEveryRecord, "/state", "skin", 0.0);
  s.last_build_step =
      in.attribute_since<long>(kFormatWithEveryRecord, "/state", "last_build_step", s.step);
  in.axes("/state", "removed_low", s.removed_low);
  in.axes("/state", "removed_high", s.removed_high);
  return s;
}

std::optional<std::vector<std::string>> read_overrides(const Reader& in, hid_t file) {
  Handle run = h5::open_group(file, "/run");
  if (!h5::has_attribute(run.get(), "scene_override_count")) return std::nullopt;
  const long count = in.attribute<long>("/run", "scene_override_count");
  if (count < 0 || count > kMaxSceneOverrides)
    throw UserError("/run@scene_override_count = " + std::to_string(count) + " is out of range");
  std::vector<std::string> overrides;
  for (long k = 0; k < count; ++k)
    overrides.push_back(h5::read_string_dataset(file, "/scene/overrides/" + std::to_string(k)));
  return overrides;
}

void read_extras(const Reader& in, hid_t file, CheckpointExtras& e) {
  e.rng_counter = in.attribute<std::uint64_t>("/run", "rng_counter");
  e.inserted = in.attribute<long>("/run", "inserted");
  e.deleted_outlet = in.attribute<long>("/run", "deleted_outlet");
  e.deleted_inlet = in.attribute<long>("/run", "deleted_inlet");
  e.insertion_carry = in.attribute<double>("/run", "insertion_carry");
  e.wall_seconds_so_far = in.attribute<double>("/run", "wall_seconds_so_far");
  Handle run = h5::open_group(file, "/run");
  // Format 3 may lack it (written before CPU time was kept): not known.
  e.cpu_seconds_so_far =
      in.attribute_since<double>(kFormatWithEveryRecord, "/run", "cpu_seconds_so_far", -1.0);
  e.bin_sums = in.dataset<double>("/run", "bin_sums");
  e.bin_shape = in.dataset<long>("/run", "bin_shape");
  e.scene_resolved = h5::read_string_dataset(file, "/scene/resolved");
  e.scene_overrides = read_overrides(in, file);
  // The record of run.h5: absent where none was given (a checkpoint written outside a run),
  // and in format-3 files written before run ids.
  if (h5::has_attribute(run.get(), "run_id")) {
    e.run_id = h5::read_string_attribute(run.get(), "run_id");
    e.run_frames = in.attribute<long>("/run", "run_file_frames");
    e.run_rows = in.attribute<long>("/run", "run_file_rows");
  }
}

}  // namespace

void write_checkpoint(const fs::path& path, const SolverState& state,
                      const CheckpointExtras& extras) {
  h5::AtomicWriteOptions sealed;
  sealed.user_block = seal::kUserBlockBytes;
  sealed.after_close = [](const fs::path& tmp) { seal::seal_file(tmp, kFormatVersion); };
  h5::write_file_atomically(
      path, "checkpoint",
      [&](hid_t file) {
        h5::write_attribute(file, "granshock_file", kFileKind);
        h5::write_attribute(file, "granshock_format_version", kFormatVersion);
        h5::write_attribute(file, "creator_version", GRANSHOCK_VERSION_STRING);
        write_state(file, state);
        write_extras(file, extras);
      },
      sealed);
}

std::optional<std::vector<std::string>> read_checkpoint_overrides(const fs::path& path) {
  h5::silence_error_printing();
  try {
    std::error_code ec;
    if (!fs::exists(path, ec)) return std::nullopt;
    // As read_checkpoint: nothing damaged is parsed.
    const int format = seal::verify_file(path, kOldestCheckpointFormat, kFormatVersion);
    const hid_t id = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
    if (id < 0) return std::nullopt;
    Handle file(id, H5Fclose);
    return read_overrides(Reader(file.get(), fs::file_size(path), format), file.get());
  } catch (const std::exception&) {
    return std::nullopt;  // read_checkpoint says what is wrong
  }
}

SolverState read_checkpoint(const fs::path& path, CheckpointExtras& extras) {
  const char* doing = "read checkpoint";
  h5::require_existing(path, doing);
  // Before HDF5 parses anything: damaged metadata must never reach the library.
  const int format = seal::verify_file(path, kOldestCheckpointFormat, kFormatVersion);
  Handle file = h5::open_existing_file(path, H5F_ACC_RDONLY, doing);
  return h5::naming_file_in_errors(path, "reading checkpoint", [&] {
    const hid_t f = file.get();
    if (!h5::is_granshock_file(f, kFileKind))
      throw h5::cannot_open(doing, path, "not a granshock checkpoint");
    const int version = h5::read_attribute<int>(f, "granshock_format_version");
    if (version != format) {
      throw h5::cannot_open(doing, path,
                            "@granshock_format_version " + std::to_string(version) +
                                " disagrees with its header's " + std::to_string(format));
    }

    const Reader in(f, fs::file_size(path), format);
    SolverState s = read_state(in);
    read_extras(in, f, extras);
    try {
      check_state(s);
      check_extras(extras);
    } catch (const InvalidCheckpoint& e) {
      throw refuse_checkpoint(path, e);
    }
    return s;
  });
}

}  // namespace granshock
