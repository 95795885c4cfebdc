// Helpers for the io tests: a scratch directory per test, and reading datasets back with
// the plain HDF5 C API (not granshock's own helpers), so that the tests check the files
// as any other HDF5 reader sees them.
#pragma once

#include <hdf5.h>
#include <stdlib.h>

#include <algorithm>
#include <filesystem>
#include <numeric>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/host_particles.hpp"

namespace granshock::test {

class TempDir {
 public:
  TempDir() {
    std::string pattern = (std::filesystem::temp_directory_path() / "granshock_io_XXXXXX").string();
    if (mkdtemp(pattern.data()) == nullptr) throw std::runtime_error("mkdtemp failed");
    path_ = pattern;
  }
  ~TempDir() {
    std::error_code ignored;
    std::filesystem::remove_all(path_, ignored);
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
  const std::filesystem::path& path() const { return path_; }
  std::filesystem::path operator/(const std::string& name) const { return path_ / name; }

 private:
  std::filesystem::path path_;
};

template <class T>
struct NativeType;
template <>
struct NativeType<double> {
  static hid_t get() { return H5T_NATIVE_DOUBLE; }
};
template <>
struct NativeType<int> {
  static hid_t get() { return H5T_NATIVE_INT; }
};
template <>
struct NativeType<long> {
  static hid_t get() { return H5T_NATIVE_LONG; }
};

// A whole dataset, row-major, with its shape.
template <class T>
struct Array {
  std::vector<T> values;
  std::vector<hsize_t> shape;
};

template <class T>
Array<T> read_array(const std::filesystem::path& file, const std::string& dataset) {
  Array<T> result;
  const hid_t f = H5Fopen(file.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  if (f < 0) throw std::runtime_error("cannot open " + file.string());
  const hid_t d = H5Dopen2(f, dataset.c_str(), H5P_DEFAULT);
  if (d < 0) {
    H5Fclose(f);
    throw std::runtime_error("no dataset " + dataset);
  }
  const hid_t space = H5Dget_space(d);
  const int rank = H5Sget_simple_extent_ndims(space);
  result.shape.resize(static_cast<std::size_t>(rank));
  if (rank > 0) H5Sget_simple_extent_dims(space, result.shape.data(), nullptr);
  std::size_t count = 1;
  for (hsize_t e : result.shape) count *= static_cast<std::size_t>(e);
  result.values.resize(count);
  herr_t status = 0;
  if (count > 0) {
    status = H5Dread(d, NativeType<T>::get(), H5S_ALL, H5S_ALL, H5P_DEFAULT, result.values.data());
  }
  H5Sclose(space);
  H5Dclose(d);
  H5Fclose(f);
  if (status < 0) throw std::runtime_error("cannot read " + dataset);
  return result;
}

inline bool has_object(const std::filesystem::path& file, const std::string& path) {
  const hid_t f = H5Fopen(file.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  if (f < 0) return false;
  const htri_t found = H5Oexists_by_name(f, path.c_str(), H5P_DEFAULT);
  H5Fclose(f);
  return found > 0;
}

// n particles with values that identify them: position (frame + i, 2 i, 3 i) ...
inline HostParticles make_particles(int n, int frame) {
  HostParticles p;
  for (int i = 0; i < n; ++i) {
    const double x = frame + 0.5 * i;
    p.add({x, 2.0 * x, 3.0 * x}, {-x, 0.25 * x, 7.0}, i % 3, 1000 * frame + i);
  }
  return p;
}

// Snapshot data as a run has it: positions spread over the domain, thermal velocities,
// ids in cell order (a permutation). Regular values would compress unrealistically well
// and make write-speed measurements meaningless.
inline HostParticles random_particles(int n) {
  std::mt19937_64 rng(1);
  std::uniform_real_distribution<double> where(0.0, 0.2);
  std::normal_distribution<double> thermal(0.0, 0.3);
  std::vector<int> ids(static_cast<std::size_t>(n));
  std::iota(ids.begin(), ids.end(), 0);
  std::shuffle(ids.begin(), ids.end(), rng);
  HostParticles p;
  for (int i = 0; i < n; ++i) {
    p.add({where(rng), where(rng), where(rng)}, {thermal(rng), 10.0 + thermal(rng), thermal(rng)},
          static_cast<int>(rng() % 2), ids[static_cast<std::size_t>(i)]);
  }
  return p;
}

}  // namespace granshock::test
