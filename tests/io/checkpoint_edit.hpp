// Test-only edits of a written checkpoint.h5 with the plain HDF5 C API, re-sealed
// afterwards (a valid checksum again), so that the edit reaches the semantic checks
// that stand between a checkpoint and the solver. Production code never re-seals.
#pragma once

#include <hdf5.h>

#include <cstring>
#include <filesystem>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

#include "io/checkpoint_file.hpp"
#include "io/checkpoint_seal.hpp"

namespace granshock::test {

inline void h5_ok(herr_t status, const std::string& what) {
  if (status < 0) throw std::runtime_error("test edit failed: " + what);
}

// Recomputes the checksum header of `file` as write_checkpoint does (or as a granshock
// writing format `format` did).
inline void reseal(const std::filesystem::path& file, int format = kCheckpointFormat) {
  seal::seal_file(file, format);
}

// Opens `file` read-write, runs `edit`, closes it and re-seals it (as format `format`).
inline void edit_checkpoint(const std::filesystem::path& file,
                            const std::function<void(hid_t file)>& edit,
                            int format = kCheckpointFormat) {
  const hid_t f = H5Fopen(file.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
  if (f < 0) throw std::runtime_error("test edit: cannot open " + file.string());
  try {
    edit(f);
  } catch (...) {
    H5Fclose(f);
    throw;
  }
  h5_ok(H5Fclose(f), "closing");
  reseal(file, format);
}

// Inside an edit: the root's @granshock_format_version set to `format`, as a granshock
// that wrote that format did (seal with the same format: edit_checkpoint's last argument).
inline void set_format_version(hid_t file, int format) {
  const hid_t a = H5Aopen(file, "granshock_format_version", H5P_DEFAULT);
  h5_ok(a, "opening @granshock_format_version");
  const herr_t written = H5Awrite(a, H5T_NATIVE_INT, &format);
  H5Aclose(a);
  h5_ok(written, "writing @granshock_format_version");
}

// `file` as a granshock writing format `format` left it: `edit` (if any), then the root's
// @granshock_format_version and the checksum header's version.
inline void rewrite_as_format(const std::filesystem::path& file, int format,
                              const std::function<void(hid_t file)>& edit = {}) {
  edit_checkpoint(
      file,
      [&](hid_t f) {
        if (edit) edit(f);
        set_format_version(f, format);
      },
      format);
}

// A dataset read whole in its own type (native memory layout), with its shape.
struct RawDataset {
  std::vector<hsize_t> shape;
  hid_t stored_type = H5I_INVALID_HID;  // owned: closed by the destructor
  std::size_t element_size = 0;
  std::vector<unsigned char> bytes;

  RawDataset() = default;
  RawDataset(const RawDataset&) = delete;
  RawDataset& operator=(const RawDataset&) = delete;
  ~RawDataset() {
    if (stored_type >= 0) H5Tclose(stored_type);
  }
  std::size_t elements() const { return element_size == 0 ? 0 : bytes.size() / element_size; }
};

inline void read_raw(hid_t file, const std::string& name, RawDataset& out) {
  const hid_t d = H5Dopen2(file, name.c_str(), H5P_DEFAULT);
  if (d < 0) throw std::runtime_error("test edit: no dataset " + name);
  out.stored_type = H5Dget_type(d);
  out.element_size = H5Tget_size(out.stored_type);
  const hid_t space = H5Dget_space(d);
  const int rank = H5Sget_simple_extent_ndims(space);
  out.shape.assign(static_cast<std::size_t>(rank), 0);
  if (rank > 0) H5Sget_simple_extent_dims(space, out.shape.data(), nullptr);
  std::size_t count = 1;
  for (hsize_t e : out.shape) count *= static_cast<std::size_t>(e);
  out.bytes.assign(count * out.element_size, 0);
  herr_t status = 0;
  // The stored type doubles as memory type: files are little-endian like the test hosts.
  if (count > 0)
    status = H5Dread(d, out.stored_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, out.bytes.data());
  H5Sclose(space);
  H5Dclose(d);
  h5_ok(status, "reading " + name);
}

// Replaces dataset `name` by `data` (same stored type, new shape).
inline void write_raw(hid_t file, const std::string& name, const RawDataset& data) {
  h5_ok(H5Ldelete(file, name.c_str(), H5P_DEFAULT), "deleting " + name);
  const hid_t space = data.shape.empty() ? H5Screate(H5S_SCALAR)
                                         : H5Screate_simple(static_cast<int>(data.shape.size()),
                                                            data.shape.data(), nullptr);
  const hid_t d = H5Dcreate2(file, name.c_str(), data.stored_type, space, H5P_DEFAULT, H5P_DEFAULT,
                             H5P_DEFAULT);
  herr_t status = d < 0 ? -1 : 0;
  if (d >= 0 && !data.bytes.empty())
    status = H5Dwrite(d, data.stored_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data.bytes.data());
  if (d >= 0) H5Dclose(d);
  H5Sclose(space);
  h5_ok(status, "writing " + name);
}

// Sets element `index` (flat, row-major) of a dataset to `value`, converted by HDF5 to
// the stored type (pass the value in the stored type's width to keep it exact).
template <class T>
void set_element(hid_t file, const std::string& name, std::size_t index, T value,
                 hid_t memory_type) {
  const hid_t d = H5Dopen2(file, name.c_str(), H5P_DEFAULT);
  if (d < 0) throw std::runtime_error("test edit: no dataset " + name);
  const hid_t space = H5Dget_space(d);
  const int rank = H5Sget_simple_extent_ndims(space);
  std::vector<hsize_t> shape(static_cast<std::size_t>(rank)), at(shape.size());
  if (rank > 0) H5Sget_simple_extent_dims(space, shape.data(), nullptr);
  for (int k = rank - 1; k >= 0; --k) {
    at[static_cast<std::size_t>(k)] = index % shape[static_cast<std::size_t>(k)];
    index /= shape[static_cast<std::size_t>(k)];
  }
  herr_t status = H5Sselect_elements(space, H5S_SELECT_SET, 1, at.data());
  const hsize_t one = 1;
  const hid_t memory = H5Screate_simple(1, &one, nullptr);
  if (status >= 0) status = H5Dwrite(d, memory_type, memory, space, H5P_DEFAULT, &value);
  H5Sclose(memory);
  H5Sclose(space);
  H5Dclose(d);
  h5_ok(status, "setting an element of " + name);
}

inline void set_double(hid_t file, const std::string& name, std::size_t index, double value) {
  set_element(file, name, index, value, H5T_NATIVE_DOUBLE);
}
inline void set_int(hid_t file, const std::string& name, std::size_t index, int value) {
  set_element(file, name, index, value, H5T_NATIVE_INT);
}

// Replaces a whole float64 dataset's values (same shape).
inline void set_doubles(hid_t file, const std::string& name, const std::vector<double>& values) {
  const hid_t d = H5Dopen2(file, name.c_str(), H5P_DEFAULT);
  if (d < 0) throw std::runtime_error("test edit: no dataset " + name);
  const herr_t status =
      H5Dwrite(d, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data());
  H5Dclose(d);
  h5_ok(status, "writing " + name);
}

}  // namespace granshock::test
