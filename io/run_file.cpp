#include "io/run_file.hpp"

#include <fmt/format.h>
#include <sys/stat.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <limits>
#include <random>
#include <stdexcept>
#include <system_error>
#include <utility>

#include "core/user_error.hpp"
#include "io/file_room.hpp"
#include "io/hdf5_helpers.hpp"
#include "io/hdf5_open.hpp"
#include "io/marked_directory.hpp"
#include "io/regular_file.hpp"
#include "io/run_file_growth.hpp"
#include "io/run_file_parts.hpp"
#include "version.hpp"

namespace granshock {

using namespace run_file_detail;

namespace {

namespace fs = std::filesystem;
using h5::Handle;

constexpr const char* kFileKind = "run";
constexpr int kFormatVersion = kRunFileFormat;  // io/run_file.hpp
constexpr const char* kSpeciesRadius = "/parameters/species_radius";
constexpr std::uintmax_t kMostPromised = std::uintmax_t(1) << 20;

constexpr double kFloatFill = std::numeric_limits<double>::quiet_NaN();
constexpr int kIntFill = -1;

}  // namespace

namespace run_file_detail {

Handle open_existing(const fs::path& path, unsigned flags, const char* doing) {
  h5::require_existing(path, doing);
  require_regular_file(path, "run file");  // HDF5 would block on a FIFO
  // Written in place: a second name would see the change (io/marked_directory.hpp).
  if (flags & H5F_ACC_RDWR) {
    struct stat st {};
    if (::lstat(path.c_str(), &st) == 0 && st.st_nlink > 1) refuse_hard_link(path, st.st_nlink);
  }
  Handle file = h5::open_existing_file(path, flags, doing);
  bool ours = false;
  try {
    ours = h5::is_granshock_file(file.get(), kFileKind) && h5::exists(file.get(), kParticles);
  } catch (const h5::Hdf5Error&) {
    ours = false;
  }
  if (!ours) throw h5::cannot_open(doing, path, "not a granshock run file");
  const int version =
      h5::naming_file_in_errors(path, "reading", [&] { return read_format_version(file.get()); });
  if (version > kFormatVersion) {
    throw h5::cannot_open(doing, path,
                          "it is a run file of format " + std::to_string(version) +
                              ", written by a newer granshock (this one reads formats 1 to " +
                              std::to_string(kFormatVersion) + ")");
  }
  return file;
}

int read_dim(hid_t file) {
  Handle box = h5::open_group(file, std::string(kParticles) + "/box");
  return h5::read_attribute<int>(box.get(), "dimension");
}

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

int read_format_version(hid_t file) {
  return h5::read_attribute<int>(file, "granshock_format_version");
}

}  // namespace run_file_detail

namespace {

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
    // About z in 2-D, a vector in 3-D (core/solver_state.hpp, spin_components).
    const std::vector<hsize_t> spin_shape =
        dim == 3 ? std::vector<hsize_t>{0, 3} : std::vector<hsize_t>{0};
    create_time_element(f, all + "/angular_velocity", H5T_IEEE_F64LE, spin_shape, &kFloatFill,
                        H5T_NATIVE_DOUBLE, "rad s-1");
  }
  create_time_element(f, all + "/count", H5T_STD_I64LE, {}, nullptr, H5T_NATIVE_LONG, nullptr);

  create_observables(f);
  h5::check(H5Fflush(f, H5F_SCOPE_GLOBAL), "flushing");
}

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

RunFile RunFile::open_for_append(const fs::path& path) {
  Handle file = open_existing(path, H5F_ACC_RDWR, "write");
  const int dim = h5::naming_file_in_errors(path, "opening", [&] { return read_dim(file.get()); });
  return RunFile(path, std::move(file), dim);
}

RunFile RunFile::open_read_only(const fs::path& path) {
  Handle file = open_existing(path, H5F_ACC_RDONLY, "read");
  const int dim = h5::naming_file_in_errors(path, "reading", [&] { return read_dim(file.get()); });
  return RunFile(path, std::move(file), dim);
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
