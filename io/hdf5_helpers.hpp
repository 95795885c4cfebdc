// Small whole-object reads and writes on top of the HDF5 C API, shared by run.h5 and
// checkpoint.h5: attributes, strings, fixed-shape datasets and groups. Failures throw
// h5::Hdf5Error (hdf5_handle.hpp).
#pragma once

#include <hdf5.h>

#include <cstddef>
#include <filesystem>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "core/user_error.hpp"
#include "io/hdf5_handle.hpp"

namespace granshock::h5 {

// The memory type of T and the type it is stored as. Files are always little-endian
// with explicit widths, so they read the same on any machine.
template <class T>
struct TypeOf;
template <>
struct TypeOf<double> {
  static hid_t memory() { return H5T_NATIVE_DOUBLE; }
  static hid_t stored() { return H5T_IEEE_F64LE; }
};
template <>
struct TypeOf<int> {
  static hid_t memory() { return H5T_NATIVE_INT; }
  static hid_t stored() { return H5T_STD_I32LE; }
};
template <>
struct TypeOf<long> {
  static hid_t memory() { return H5T_NATIVE_LONG; }
  static hid_t stored() { return H5T_STD_I64LE; }
};
template <>
struct TypeOf<long long> {
  static hid_t memory() { return H5T_NATIVE_LLONG; }
  static hid_t stored() { return H5T_STD_I64LE; }
};
template <>
struct TypeOf<unsigned long> {
  static hid_t memory() { return H5T_NATIVE_ULONG; }
  static hid_t stored() { return H5T_STD_U64LE; }
};
template <>
struct TypeOf<unsigned long long> {
  static hid_t memory() { return H5T_NATIVE_ULLONG; }
  static hid_t stored() { return H5T_STD_U64LE; }
};

// True when every component of the slash-separated `path` exists below `loc`
// (H5Lexists alone fails when an intermediate group is missing).
bool exists(hid_t loc, const std::string& path);

// Opens the group at `path`, creating it and any missing parents.
Handle require_group(hid_t loc, const std::string& path);

Handle open_group(hid_t loc, const std::string& path);
Handle open_dataset(hid_t loc, const std::string& path);

// The current extent of a dataset (or of a dataspace).
std::vector<hsize_t> shape_of_space(hid_t space);
std::vector<hsize_t> shape_of(hid_t dataset);

// --- Attributes (written ones replace an existing attribute of that name) -------------
bool has_attribute(hid_t object, const std::string& name);
void write_attribute_raw(hid_t object, const std::string& name, hid_t stored_type,
                         hid_t memory_type, const std::vector<hsize_t>& shape, const void* data);
void read_attribute_raw(hid_t object, const std::string& name, hid_t memory_type, std::size_t count,
                        void* data);
std::size_t attribute_size(hid_t object, const std::string& name);

template <class T>
void write_attribute(hid_t object, const std::string& name, T value) {
  write_attribute_raw(object, name, TypeOf<T>::stored(), TypeOf<T>::memory(), {}, &value);
}
template <class T>
void write_attribute(hid_t object, const std::string& name, const std::vector<T>& values) {
  write_attribute_raw(object, name, TypeOf<T>::stored(), TypeOf<T>::memory(),
                      {static_cast<hsize_t>(values.size())}, values.data());
}
void write_attribute(hid_t object, const std::string& name, const std::string& value);
inline void write_attribute(hid_t object, const std::string& name, const char* value) {
  write_attribute(object, name, std::string(value));
}

template <class T>
T read_attribute(hid_t object, const std::string& name) {
  T value{};
  read_attribute_raw(object, name, TypeOf<T>::memory(), 1, &value);
  return value;
}
template <class T>
std::vector<T> read_attribute_vector(hid_t object, const std::string& name) {
  std::vector<T> values(attribute_size(object, name));
  read_attribute_raw(object, name, TypeOf<T>::memory(), values.size(), values.data());
  return values;
}
std::string read_string_attribute(hid_t object, const std::string& name);

// --- Whole datasets (fixed shape; a written one replaces an existing one) --------------
// none: contiguous. fletcher32: chunked (chunks of at most kChecksumChunkBytes) with HDF5's
// Fletcher32 filter, so that a damaged chunk fails to read instead of reading as numbers
// (run.h5: io/run_file.hpp). Every HDF5 library reads it: the filter is built in.
enum class Checksum { none, fletcher32 };
inline constexpr std::size_t kChecksumChunkBytes = std::size_t(1) << 30;
void write_dataset_raw(hid_t loc, const std::string& name, hid_t stored_type, hid_t memory_type,
                       const std::vector<hsize_t>& shape, const void* data,
                       Checksum checksum = Checksum::none);
// The chunk shape write_dataset_raw gives a checksummed dataset of `shape` and elements of
// `element_bytes`: the whole of it, cut along the first dimension to at most
// kChecksumChunkBytes.
std::vector<hsize_t> checksum_chunk(const std::vector<hsize_t>& shape, std::size_t element_bytes);
// Adds the Fletcher32 filter to a chunked dataset's creation properties.
void add_checksum(hid_t dataset_creation);
// Reads the whole dataset; `count` must equal its number of elements.
void read_dataset_raw(hid_t dataset, hid_t memory_type, std::size_t count, void* data);

template <class T>
void write_dataset(hid_t loc, const std::string& name, const std::vector<T>& data,
                   const std::vector<hsize_t>& shape, Checksum checksum = Checksum::none) {
  write_dataset_raw(loc, name, TypeOf<T>::stored(), TypeOf<T>::memory(), shape, data.data(),
                    checksum);
}

template <class T>
std::vector<T> read_dataset(hid_t loc, const std::string& name,
                            std::vector<hsize_t>* shape_out = nullptr) {
  Handle dataset = open_dataset(loc, name);
  const std::vector<hsize_t> shape = shape_of(dataset.get());
  std::size_t count = 1;
  for (hsize_t extent : shape) count *= static_cast<std::size_t>(extent);
  std::vector<T> data(count);
  read_dataset_raw(dataset.get(), TypeOf<T>::memory(), count, data.data());
  if (shape_out != nullptr) *shape_out = shape;
  return data;
}

// A text (a TOML scene) as a scalar fixed-length string dataset: h5dump prints it and
// h5py returns it as bytes.
void write_string_dataset(hid_t loc, const std::string& name, const std::string& text);
std::string read_string_dataset(hid_t loc, const std::string& name);

// A file whose stored checksum (h5::Checksum::fletcher32) does not match its data: its
// bytes changed after granshock wrote them. Refused as it is, whatever the reader wanted
// from it (no "holds no field sums": the sums are there, damaged).
class DamagedFile : public UserError {
 public:
  DamagedFile(const std::filesystem::path& path, const char* doing);
};
bool is_checksum_failure(const Hdf5Error& e);

// Runs f; an HDF5 failure inside becomes one UserError line naming the file ("writing
// 'out/run.h5' failed: ... No space left on device"): I/O trouble is the user's to fix.
template <class F>
auto naming_file_in_errors(const std::filesystem::path& path, const char* doing, F&& f)
    -> decltype(f()) {
  try {
    return std::forward<F>(f)();
  } catch (const Hdf5Error& e) {
    if (is_checksum_failure(e)) throw DamagedFile(path, doing);
    throw UserError(std::string(doing) + " '" + path.string() + "' failed: " + e.what());
  }
}

// Options of write_file_atomically: a user block (bytes before the HDF5 superblock that
// HDF5 leaves to the application: a power of 2, >= 512, or 0 for none) and what to do
// with the closed file before it is synced (e.g. write a checksum into the user block).
struct AtomicWriteOptions {
  hsize_t user_block = 0;
  std::function<void(const std::filesystem::path& closed_tmp)> after_close;
};

// Writes an HDF5 file so that readers never see half of it: `write` fills path.tmp,
// which is closed (HDF5 writes its buffers there), passed to options.after_close,
// fsync'ed and renamed over path. On any failure the .tmp is removed, the previous file
// stays, and a UserError names `what` and the path.
void write_file_atomically(const std::filesystem::path& path, const std::string& what,
                           const std::function<void(hid_t file)>& write,
                           const AtomicWriteOptions& options = {});

}  // namespace granshock::h5
