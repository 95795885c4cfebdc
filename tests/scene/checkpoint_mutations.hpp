// The mutations of the checkpoint fuzzer (test_checkpoint_fuzz.cpp), test-only: raw byte
// damage that the checksum must catch, and edits of datasets and attributes through
// HDF5, re-sealed (io/checkpoint_edit.hpp), that only the semantic checks can catch.
// Each returns a description for failure messages.
#pragma once

#include <hdf5.h>

#include <climits>
#include <cstdint>
#include <cstring>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "io/checkpoint_bytes.hpp"
#include "io/checkpoint_edit.hpp"

namespace granshock::testing {

using Rng = std::mt19937_64;

inline std::size_t pick(Rng& rng, std::size_t n) {
  return n == 0 ? 0 : std::size_t(rng() % n);
}

// --- raw bytes: flips, random overwrites, truncation, extension ----------------------
inline std::string mutate_bytes(std::string& bytes, Rng& rng) {
  switch (pick(rng, 4)) {
    case 0: {
      const std::size_t at = pick(rng, bytes.size());
      const unsigned mask = 1u + unsigned(pick(rng, 255));
      bytes[at] = char(static_cast<unsigned char>(bytes[at]) ^ mask);
      return "xor byte " + std::to_string(at) + " with " + std::to_string(mask);
    }
    case 1: {
      const std::size_t at = pick(rng, bytes.size()), length = 1 + pick(rng, 64);
      for (std::size_t k = at; k < std::min(bytes.size(), at + length); ++k) bytes[k] = char(rng());
      return "overwrite " + std::to_string(length) + " bytes at " + std::to_string(at);
    }
    case 2: {
      const std::size_t keep = pick(rng, bytes.size());
      bytes.resize(keep);
      return "truncate to " + std::to_string(keep) + " bytes";
    }
    default: {
      const std::size_t extra = 1 + pick(rng, 4096);
      for (std::size_t k = 0; k < extra; ++k) bytes.push_back(char(rng()));
      return "append " + std::to_string(extra) + " bytes";
    }
  }
}

// --- the objects of a checkpoint, found by walking it ---------------------------------
struct Objects {
  std::vector<std::string> datasets;                            // full paths
  std::vector<std::pair<std::string, std::string>> attributes;  // (object, name)
};

inline herr_t collect_attribute(hid_t, const char* name, const H5A_info_t*, void* data) {
  auto* out = static_cast<std::pair<Objects*, std::string>*>(data);
  out->first->attributes.emplace_back(out->second, name);
  return 0;
}

inline herr_t collect_object(hid_t root, const char* name, const H5O_info_t* info, void* data) {
  auto* objects = static_cast<Objects*>(data);
  const std::string path = std::string(name) == "." ? "/" : "/" + std::string(name);
  if (info->type == H5O_TYPE_DATASET) objects->datasets.push_back(path);
  const hid_t object = H5Oopen(root, path.c_str(), H5P_DEFAULT);
  std::pair<Objects*, std::string> context{objects, path};
  hsize_t at = 0;
  H5Aiterate2(object, H5_INDEX_NAME, H5_ITER_INC, &at, collect_attribute, &context);
  H5Oclose(object);
  return 0;
}

inline Objects list_objects(hid_t file) {
  Objects objects;
#if H5_VERSION_GE(1, 12, 0)
  test::h5_ok(H5Ovisit3(
                  file, H5_INDEX_NAME, H5_ITER_INC,
                  [](hid_t root, const char* name, const H5O_info2_t* info, void* data) {
                    H5O_info_t old{};
                    old.type = info->type;
                    return collect_object(root, name, &old, data);
                  },
                  &objects, H5O_INFO_BASIC),
              "walking the file");
#else
  test::h5_ok(H5Ovisit2(file, H5_INDEX_NAME, H5_ITER_INC, collect_object, &objects, H5O_INFO_BASIC),
              "walking the file");
#endif
  return objects;
}

// Values no field can hold in a healthy checkpoint of the small test scene: not finite,
// beyond every bound, negative where only counts or indices belong.
inline double poison_double(Rng& rng) {
  const double values[] = {std::numeric_limits<double>::quiet_NaN(),
                           std::numeric_limits<double>::infinity(),
                           -std::numeric_limits<double>::infinity(), 1e300, -1e300};
  return values[pick(rng, 5)];
}
inline long long poison_integer(Rng& rng, std::size_t bytes, bool is_signed) {
  if (!is_signed) return pick(rng, 2) == 0 ? -1 : LLONG_MIN;  // 2^64 - 1 and 2^63 as uint64
  const long long big = bytes == 4 ? INT_MAX : LLONG_MAX, small = bytes == 4 ? INT_MIN : LLONG_MIN;
  const long long values[] = {big, small, -1};
  return values[pick(rng, 3)];
}

// Writes a poison value into element `index` of `data` (in its stored type).
inline std::string poison_element(test::RawDataset& data, std::size_t index, Rng& rng) {
  unsigned char* at = data.bytes.data() + index * data.element_size;
  const H5T_class_t type = H5Tget_class(data.stored_type);
  if (type == H5T_FLOAT && data.element_size == 8) {
    const double v = poison_double(rng);
    std::memcpy(at, &v, 8);
    return std::to_string(v);
  }
  if (type == H5T_INTEGER) {
    const long long v =
        poison_integer(rng, data.element_size, H5Tget_sign(data.stored_type) == H5T_SGN_2);
    std::memcpy(at, &v, data.element_size);  // little-endian: the low bytes
    return std::to_string(v);
  }
  if (type == H5T_STRING && data.element_size > 0) {
    for (std::size_t k = 0; k + 1 < data.element_size; ++k) at[k] = 'x';
    return "'xxx...'";
  }
  return "unchanged (type not handled)";
}

inline std::string set_dataset_element(hid_t file, const std::string& name, Rng& rng) {
  test::RawDataset data;
  test::read_raw(file, name, data);
  if (data.elements() == 0 || H5Tis_variable_str(data.stored_type) > 0) return name + ": empty";
  const std::size_t index = pick(rng, data.elements());
  const std::string value = poison_element(data, index, rng);
  test::write_raw(file, name, data);
  return name + "[" + std::to_string(index) + "] = " + value;
}

inline std::string set_attribute_element(hid_t file, const std::string& object,
                                         const std::string& name, Rng& rng) {
  // Through the object: HDF5 1.10 cannot write an attribute opened by H5Aopen_by_name.
  const hid_t owner = H5Oopen(file, object.c_str(), H5P_DEFAULT);
  const hid_t attr = H5Aopen(owner, name.c_str(), H5P_DEFAULT);
  test::RawDataset data;
  data.stored_type = H5Aget_type(attr);
  data.element_size = H5Tget_size(data.stored_type);
  const hid_t space = H5Aget_space(attr);
  const hssize_t count = H5Sget_simple_extent_npoints(space);
  H5Sclose(space);
  data.bytes.assign(std::size_t(count) * data.element_size, 0);
  herr_t status = H5Aread(attr, data.stored_type, data.bytes.data());
  std::string value = "?";
  std::size_t index = 0;
  if (status >= 0 && count > 0) {
    index = pick(rng, std::size_t(count));
    value = poison_element(data, index, rng);
    status = H5Awrite(attr, data.stored_type, data.bytes.data());
  }
  H5Aclose(attr);
  H5Oclose(owner);
  test::h5_ok(status, "poisoning " + object + "@" + name);
  return object + "@" + name + "[" + std::to_string(index) + "] = " + value;
}

// Removes the last row (truncate) or repeats it (extend; a zero row when empty).
inline std::string resize_dataset(hid_t file, const std::string& name, bool extend) {
  test::RawDataset data;
  test::read_raw(file, name, data);
  if (data.shape.empty()) return name + ": scalar, unchanged";
  if (!extend && data.shape[0] == 0) return name + ": empty, unchanged";
  std::size_t row_bytes = data.element_size;
  for (std::size_t d = 1; d < data.shape.size(); ++d) row_bytes *= data.shape[d];
  if (extend) {
    std::vector<unsigned char> last(row_bytes, 0);
    if (data.shape[0] > 0) last.assign(data.bytes.end() - long(row_bytes), data.bytes.end());
    data.bytes.insert(data.bytes.end(), last.begin(), last.end());
    ++data.shape[0];
  } else {
    data.bytes.resize(data.bytes.size() - row_bytes);
    --data.shape[0];
  }
  test::write_raw(file, name, data);
  return name + (extend ? " extended to " : " truncated to ") + std::to_string(data.shape[0]) +
         " rows";
}

inline std::string swap_datasets(hid_t file, const std::string& a, const std::string& b) {
  test::h5_ok(H5Lmove(file, a.c_str(), file, "/swap_tmp", H5P_DEFAULT, H5P_DEFAULT), "moving");
  test::h5_ok(H5Lmove(file, b.c_str(), file, a.c_str(), H5P_DEFAULT, H5P_DEFAULT), "moving");
  test::h5_ok(H5Lmove(file, "/swap_tmp", file, b.c_str(), H5P_DEFAULT, H5P_DEFAULT), "moving");
  return "swap " + a + " and " + b;
}

}  // namespace granshock::testing
