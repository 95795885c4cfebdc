#include "io/hdf5_helpers.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <string_view>
#include <system_error>

#include <algorithm>

#include "io/atomic_file.hpp"

namespace granshock::h5 {

namespace {

std::vector<std::string> split_path(const std::string& path) {
  std::vector<std::string> parts;
  std::string part;
  for (char c : path) {
    if (c == '/') {
      if (!part.empty()) parts.push_back(part);
      part.clear();
    } else {
      part += c;
    }
  }
  if (!part.empty()) parts.push_back(part);
  return parts;
}

Handle simple_space(const std::vector<hsize_t>& shape, const std::string& what) {
  if (shape.empty()) return dataspace(H5Screate(H5S_SCALAR), what);
  return dataspace(H5Screate_simple(static_cast<int>(shape.size()), shape.data(), nullptr), what);
}

// A fixed-length, NUL-terminated UTF-8 string type that holds `length` bytes. HDF5
// types cannot have size 0, hence the terminator even for "".
Handle string_type(std::size_t length) {
  Handle type = datatype(H5Tcopy(H5T_C_S1), "copying the string type");
  check(H5Tset_size(type.get(), length + 1), "sizing a string type");
  check(H5Tset_strpad(type.get(), H5T_STR_NULLTERM), "setting string padding");
  check(H5Tset_cset(type.get(), H5T_CSET_UTF8), "setting string encoding");
  return type;
}

// Reads a scalar string from an attribute or dataset, whether stored fixed-length
// (as granshock writes) or variable-length (as h5py writes by default).
template <class ReadFn>
std::string read_string(hid_t stored_type, ReadFn read) {
  if (H5Tget_class(stored_type) != H5T_STRING) throw Hdf5Error("expected a string");
  const htri_t variable = H5Tis_variable_str(stored_type);
  check(variable, "inspecting a string type");
  // The memory type is a copy of the stored one: no padding or character-set conversion.
  Handle type = datatype(H5Tcopy(stored_type), "copying a string type");
  if (variable > 0) {
    char* text = nullptr;
    read(type.get(), &text);
    std::string result = text != nullptr ? text : "";
    H5free_memory(text);
    return result;
  }
  const std::size_t size = H5Tget_size(stored_type);
  std::vector<char> buffer(size + 1, '\0');
  read(type.get(), buffer.data());
  return std::string(buffer.data(), std::find(buffer.data(), buffer.data() + size, '\0'));
}

}  // namespace

bool exists(hid_t loc, const std::string& path) {
  std::string prefix = path.rfind('/', 0) == 0 ? "" : ".";
  for (const std::string& part : split_path(path)) {
    prefix += "/" + part;
    const htri_t found = H5Lexists(loc, prefix.c_str(), H5P_DEFAULT);
    check(found, "looking up '" + prefix + "'");
    if (found == 0) return false;
  }
  return true;
}

Handle require_group(hid_t loc, const std::string& path) {
  if (split_path(path).empty()) return group(H5Gopen2(loc, "/", H5P_DEFAULT), "opening '/'");
  if (exists(loc, path)) return open_group(loc, path);
  Handle links = plist(H5Pcreate(H5P_LINK_CREATE), "creating link properties");
  check(H5Pset_create_intermediate_group(links.get(), 1), "setting intermediate groups");
  return group(H5Gcreate2(loc, path.c_str(), links.get(), H5P_DEFAULT, H5P_DEFAULT),
               "creating group '" + path + "'");
}

Handle open_group(hid_t loc, const std::string& path) {
  return group(H5Gopen2(loc, path.c_str(), H5P_DEFAULT), "opening group '" + path + "'");
}

Handle open_dataset(hid_t loc, const std::string& path) {
  return dataset(H5Dopen2(loc, path.c_str(), H5P_DEFAULT), "opening dataset '" + path + "'");
}

std::vector<hsize_t> shape_of_space(hid_t space) {
  const int rank = H5Sget_simple_extent_ndims(space);
  check(rank, "reading a dataspace's rank");
  std::vector<hsize_t> shape(static_cast<std::size_t>(rank));
  if (rank > 0) check(H5Sget_simple_extent_dims(space, shape.data(), nullptr), "reading a shape");
  return shape;
}

std::vector<hsize_t> shape_of(hid_t dataset_id) {
  Handle space = dataspace(H5Dget_space(dataset_id), "reading a dataset's dataspace");
  return shape_of_space(space.get());
}

bool has_attribute(hid_t object, const std::string& name) {
  const htri_t found = H5Aexists(object, name.c_str());
  check(found, "looking up attribute '" + name + "'");
  return found > 0;
}

void write_attribute_raw(hid_t object, const std::string& name, hid_t stored_type,
                         hid_t memory_type, const std::vector<hsize_t>& shape, const void* data) {
  if (has_attribute(object, name)) {
    check(H5Adelete(object, name.c_str()), "replacing attribute '" + name + "'");
  }
  Handle space = simple_space(shape, "creating the dataspace of attribute '" + name + "'");
  Handle attr = attribute(
      H5Acreate2(object, name.c_str(), stored_type, space.get(), H5P_DEFAULT, H5P_DEFAULT),
      "creating attribute '" + name + "'");
  check(H5Awrite(attr.get(), memory_type, data), "writing attribute '" + name + "'");
}

void read_attribute_raw(hid_t object, const std::string& name, hid_t memory_type, std::size_t count,
                        void* data) {
  Handle attr =
      attribute(H5Aopen(object, name.c_str(), H5P_DEFAULT), "opening attribute '" + name + "'");
  Handle space = dataspace(H5Aget_space(attr.get()), "reading attribute '" + name + "'");
  const hssize_t points = H5Sget_simple_extent_npoints(space.get());
  if (points < 0 || static_cast<std::size_t>(points) != count) {
    throw Hdf5Error("attribute '" + name + "' has " + std::to_string(points) +
                    " values, expected " + std::to_string(count));
  }
  check(H5Aread(attr.get(), memory_type, data), "reading attribute '" + name + "'");
}

std::size_t attribute_size(hid_t object, const std::string& name) {
  Handle attr =
      attribute(H5Aopen(object, name.c_str(), H5P_DEFAULT), "opening attribute '" + name + "'");
  Handle space = dataspace(H5Aget_space(attr.get()), "reading attribute '" + name + "'");
  const hssize_t points = H5Sget_simple_extent_npoints(space.get());
  check(static_cast<herr_t>(points < 0 ? -1 : 0), "sizing attribute '" + name + "'");
  return static_cast<std::size_t>(points);
}

void write_attribute(hid_t object, const std::string& name, const std::string& value) {
  Handle type = string_type(value.size());
  write_attribute_raw(object, name, type.get(), type.get(), {}, value.c_str());
}

std::string read_string_attribute(hid_t object, const std::string& name) {
  Handle attr =
      attribute(H5Aopen(object, name.c_str(), H5P_DEFAULT), "opening attribute '" + name + "'");
  Handle stored = datatype(H5Aget_type(attr.get()), "reading the type of '" + name + "'");
  return read_string(stored.get(), [&](hid_t memory_type, void* buffer) {
    check(H5Aread(attr.get(), memory_type, buffer), "reading attribute '" + name + "'");
  });
}

std::vector<hsize_t> checksum_chunk(const std::vector<hsize_t>& shape, std::size_t element_bytes) {
  std::vector<hsize_t> chunk(shape.begin(), shape.end());
  for (hsize_t& c : chunk) c = std::max<hsize_t>(c, 1);  // HDF5 refuses a chunk extent of 0
  hsize_t row_bytes = element_bytes;
  for (std::size_t k = 1; k < chunk.size(); ++k) row_bytes *= chunk[k];
  if (!chunk.empty())
    chunk[0] =
        std::clamp<hsize_t>(kChecksumChunkBytes / std::max<hsize_t>(row_bytes, 1), 1, chunk[0]);
  return chunk;
}

DamagedFile::DamagedFile(const std::filesystem::path& path, const char* doing)
    : UserError("'" + path.string() + "' is damaged: " + doing +
                " it, a stored Fletcher32 checksum does not match its data (bytes changed on "
                "disk or in a copy since granshock wrote it); it cannot be used: restore it "
                "from a copy, or run the case again") {}

bool is_checksum_failure(const Hdf5Error& e) {
  return std::string_view(e.what()).find("Fletcher32 checksum") != std::string_view::npos;
}

void add_checksum(hid_t dataset_creation) {
  check(H5Pset_fletcher32(dataset_creation), "enabling the Fletcher32 checksum");
}

void write_dataset_raw(hid_t loc, const std::string& name, hid_t stored_type, hid_t memory_type,
                       const std::vector<hsize_t>& shape, const void* data, Checksum checksum) {
  if (exists(loc, name))
    check(H5Ldelete(loc, name.c_str(), H5P_DEFAULT), "replacing '" + name + "'");
  Handle space = simple_space(shape, "creating the dataspace of '" + name + "'");
  Handle links = plist(H5Pcreate(H5P_LINK_CREATE), "creating link properties");
  check(H5Pset_create_intermediate_group(links.get(), 1), "setting intermediate groups");
  Handle creation = plist(H5Pcreate(H5P_DATASET_CREATE), "creating dataset properties");
  // A scalar has no chunks, and a chunked dataset needs a rank of at least 1.
  if (checksum == Checksum::fletcher32 && !shape.empty()) {
    const std::vector<hsize_t> chunk = checksum_chunk(shape, H5Tget_size(stored_type));
    check(H5Pset_chunk(creation.get(), int(chunk.size()), chunk.data()), "setting the chunk shape");
    add_checksum(creation.get());
  }
  Handle set = dataset(H5Dcreate2(loc, name.c_str(), stored_type, space.get(), links.get(),
                                  creation.get(), H5P_DEFAULT),
                       "creating dataset '" + name + "'");
  const hssize_t points = H5Sget_simple_extent_npoints(space.get());
  // An empty dataset has nothing to write (and HDF5 rejects a null buffer).
  if (points > 0) {
    check(H5Dwrite(set.get(), memory_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data),
          "writing dataset '" + name + "'");
  }
}

void read_dataset_raw(hid_t dataset_id, hid_t memory_type, std::size_t count, void* data) {
  Handle space = dataspace(H5Dget_space(dataset_id), "reading a dataset's dataspace");
  const hssize_t points = H5Sget_simple_extent_npoints(space.get());
  if (points < 0 || static_cast<std::size_t>(points) != count) {
    throw Hdf5Error("dataset has " + std::to_string(points) + " values, expected " +
                    std::to_string(count));
  }
  if (count == 0) return;
  check(H5Dread(dataset_id, memory_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data), "reading a dataset");
}

void write_string_dataset(hid_t loc, const std::string& name, const std::string& text) {
  Handle type = string_type(text.size());
  write_dataset_raw(loc, name, type.get(), type.get(), {}, text.c_str());
}

std::string read_string_dataset(hid_t loc, const std::string& name) {
  Handle set = open_dataset(loc, name);
  Handle stored = datatype(H5Dget_type(set.get()), "reading the type of '" + name + "'");
  return read_string(stored.get(), [&](hid_t memory_type, void* buffer) {
    check(H5Dread(set.get(), memory_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, buffer),
          "reading dataset '" + name + "'");
  });
}

namespace {
void sync_file(const std::filesystem::path& path) {
  const int fd = ::open(path.c_str(), O_RDONLY | O_NOFOLLOW | O_CLOEXEC);
  if (fd < 0) throw Hdf5Error("reopening to sync failed");
  const int status = ::fsync(fd);
  ::close(fd);
  if (status != 0) throw Hdf5Error("fsync failed (disk full?)");
}
}  // namespace

void write_file_atomically(const std::filesystem::path& path, const std::string& what,
                           const std::function<void(hid_t file)>& write,
                           const AtomicWriteOptions& options) {
  namespace fs = std::filesystem;
  silence_error_printing();
  const fs::path tmp = path.string() + ".tmp";
  Handle creation = plist(H5Pcreate(H5P_FILE_CREATE), "creating file properties");
  if (options.user_block > 0)
    check(H5Pset_userblock(creation.get(), options.user_block), "setting the user block");
  // The temporary is a file granshock creates itself (io/atomic_file.hpp): a stale one
  // that is a regular file is removed, and H5F_ACC_EXCL creates it with O_CREAT | O_EXCL,
  // which fails on any name that exists, a symbolic link included.
  remove_stale_temporary(tmp);
  const hid_t id = H5Fcreate(tmp.c_str(), H5F_ACC_EXCL, creation.get(), H5P_DEFAULT);
  if (id < 0) {
    const std::string reason = take_error_message();
    // A create that failed half-way (a full disk) can leave the file: nothing else has
    // that name now, and unlinking never follows a link.
    std::error_code ignored;
    fs::remove(tmp, ignored);
    throw UserError("cannot write " + what + " '" + path.string() + "': " + reason);
  }
  Handle file(id, H5Fclose);
  auto discard_tmp = [&] {
    file.close();
    std::error_code ignored;
    fs::remove(tmp, ignored);
  };
  try {
    naming_file_in_errors(path, ("writing " + what).c_str(), [&] {
      write(file.get());
      check(file.close(), "closing");  // closing is where HDF5 writes what it buffered
      if (options.after_close) {
        try {
          options.after_close(tmp);
        } catch (const std::runtime_error& e) {
          if (dynamic_cast<const UserError*>(&e) != nullptr) throw;
          throw Hdf5Error(std::string("finishing the file failed: ") + e.what());
        }
      }
      sync_file(tmp);
    });
  } catch (...) {
    discard_tmp();
    throw;
  }
  std::error_code ec;
  fs::rename(tmp, path, ec);
  if (ec) {
    discard_tmp();
    throw UserError("cannot replace " + what + " '" + path.string() + "': " + ec.message());
  }
}

}  // namespace granshock::h5
