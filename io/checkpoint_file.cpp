#include "checkpoint_file.hpp"

#include <algorithm>
#include <array>
#include <stdexcept>
#include <system_error>

#include "checkpoint_seal.hpp"
#include "hdf5_helpers.hpp"
#include "user_error.hpp"
#include "version.hpp"

namespace granshock {

namespace {

namespace fs = std::filesystem;
using h5::Handle;

constexpr const char* kFileKind = "checkpoint";
// 2: checksum header in a 512-byte user block (io/checkpoint_seal.hpp).
constexpr int kFormatVersion = 2;

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
  put("history_wall_spring", s.history_wall_spring, {dim});

  // The neighbour list: restoring it avoids a rebuild that would change the run.
  put("reference_position", s.reference_position, {dim});
  h5::write_dataset(state.get(), "neighbour_offsets", s.neighbour_offsets,
                    {static_cast<hsize_t>(s.neighbour_offsets.size())});
  h5::write_dataset(state.get(), "neighbours", s.neighbours,
                    {static_cast<hsize_t>(s.neighbours.size())});
  h5::write_attribute(state.get(), "list_builds", s.list_builds);
  h5::write_attribute(state.get(), "removed_low",
                      std::vector<long>(s.removed_low.begin(), s.removed_low.end()));
  h5::write_attribute(state.get(), "removed_high",
                      std::vector<long>(s.removed_high.begin(), s.removed_high.end()));
}

void write_extras(hid_t file, const CheckpointExtras& e) {
  Handle run = h5::require_group(file, "/run");
  h5::write_attribute(run.get(), "rng_counter", e.rng_counter);
  h5::write_attribute(run.get(), "inserted", e.inserted);
  h5::write_attribute(run.get(), "deleted_outlet", e.deleted_outlet);
  h5::write_attribute(run.get(), "deleted_inlet", e.deleted_inlet);
  h5::write_attribute(run.get(), "insertion_carry", e.insertion_carry);
  h5::write_attribute(run.get(), "wall_seconds_so_far", e.wall_seconds_so_far);
  h5::write_dataset(run.get(), "bin_sums", e.bin_sums, {static_cast<hsize_t>(e.bin_sums.size())});
  h5::write_dataset(run.get(), "bin_shape", e.bin_shape,
                    {static_cast<hsize_t>(e.bin_shape.size())});
  h5::write_string_dataset(file, "/scene/resolved", e.scene_resolved);
}

// HDF5 leaves the data in the page cache; the rename must not reach the disk before it
// does, or a power cut could leave a checkpoint of the right name and wrong content.

void read_axes(hid_t group, const char* name, std::array<long, 3>& axes) {
  const std::vector<long> values = h5::read_attribute_vector<long>(group, name);
  if (values.size() != axes.size()) {
    throw h5::Hdf5Error(std::string("attribute '") + name + "' does not have 3 values");
  }
  std::copy(values.begin(), values.end(), axes.begin());
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

SolverState read_checkpoint(const fs::path& path, CheckpointExtras& extras) {
  h5::silence_error_printing();
  std::error_code ec;
  if (!fs::exists(path, ec)) {
    throw UserError("cannot read checkpoint '" + path.string() + "': no such file");
  }
  // Before HDF5 parses anything: damaged metadata must never reach the library.
  seal::verify_file(path, kFormatVersion);
  const hid_t id = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  if (id < 0) {
    throw UserError("cannot read checkpoint '" + path.string() + "': " + h5::take_error_message());
  }
  Handle file(id, H5Fclose);
  return h5::naming_file_in_errors(path, "reading checkpoint", [&] {
    const hid_t f = file.get();
    if (!h5::has_attribute(f, "granshock_file") ||
        h5::read_string_attribute(f, "granshock_file") != kFileKind) {
      throw UserError("cannot read checkpoint '" + path.string() + "': not a granshock checkpoint");
    }
    const int version = h5::read_attribute<int>(f, "granshock_format_version");
    if (version != kFormatVersion) {
      throw UserError("cannot read checkpoint '" + path.string() + "': @granshock_format_version " +
                      std::to_string(version) + " disagrees with its header's " +
                      std::to_string(kFormatVersion));
    }

    SolverState s;
    Handle state = h5::open_group(f, "/state");
    const hid_t g = state.get();
    s.dim = h5::read_attribute<int>(g, "dim");
    s.step = h5::read_attribute<long>(g, "step");
    s.next_id = h5::read_attribute<int>(g, "next_id");
    s.history_slots = h5::read_attribute<int>(g, "history_slots");
    s.position = h5::read_dataset<double>(g, "position");
    s.velocity = h5::read_dataset<double>(g, "velocity");
    s.force = h5::read_dataset<double>(g, "force");
    s.angular_velocity = h5::read_dataset<double>(g, "angular_velocity");
    s.torque = h5::read_dataset<double>(g, "torque");
    s.species = h5::read_dataset<int>(g, "species");
    s.id = h5::read_dataset<int>(g, "id");
    s.history_partner = h5::read_dataset<int>(g, "history_partner");
    s.history_spring = h5::read_dataset<double>(g, "history_spring");
    s.history_wall_spring = h5::read_dataset<double>(g, "history_wall_spring");
    s.reference_position = h5::read_dataset<double>(g, "reference_position");
    s.neighbour_offsets = h5::read_dataset<int>(g, "neighbour_offsets");
    s.neighbours = h5::read_dataset<int>(g, "neighbours");
    s.list_builds = h5::read_attribute<long>(g, "list_builds");
    read_axes(g, "removed_low", s.removed_low);
    read_axes(g, "removed_high", s.removed_high);

    Handle run = h5::open_group(f, "/run");
    const hid_t r = run.get();
    extras.rng_counter = h5::read_attribute<std::uint64_t>(r, "rng_counter");
    extras.inserted = h5::read_attribute<long>(r, "inserted");
    extras.deleted_outlet = h5::read_attribute<long>(r, "deleted_outlet");
    extras.deleted_inlet = h5::read_attribute<long>(r, "deleted_inlet");
    extras.insertion_carry = h5::read_attribute<double>(r, "insertion_carry");
    extras.wall_seconds_so_far = h5::read_attribute<double>(r, "wall_seconds_so_far");
    extras.bin_sums = h5::read_dataset<double>(r, "bin_sums");
    extras.bin_shape = h5::read_dataset<long>(r, "bin_shape");
    extras.scene_resolved = h5::read_string_dataset(f, "/scene/resolved");
    return s;
  });
}

}  // namespace granshock
