// run.h5's particle snapshots: appending a frame (alone, or collectively with parallel
// HDF5), listing the frames and reading one back.
#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cstring>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/failure_agreement.hpp"
#include "core/user_error.hpp"
#include "io/frame_views.hpp"
#include "io/hdf5_helpers.hpp"
#include "io/run_file.hpp"
#include "io/run_file_growth.hpp"
#include "io/run_file_parts.hpp"

namespace granshock {

using namespace run_file_detail;

namespace {

namespace fs = std::filesystem;
using h5::Handle;

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

// Whether the snapshot datasets make a frame's chunks when they grow to it, as parallel
// HDF5 needs (create_time_element); format-1 files, and format-2 files written before
// collective output, do not.
bool snapshot_chunks_made_early(hid_t file) {
  Handle set = h5::open_dataset(file, std::string(kParticles) + "/position/value");
  Handle props = h5::plist(H5Dget_create_plist(set.get()), "reading dataset properties");
  H5D_alloc_time_t when = H5D_ALLOC_TIME_DEFAULT;
  h5::check(H5Pget_alloc_time(props.get(), &when), "reading the allocation time");
  return when == H5D_ALLOC_TIME_EARLY;
}

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
    // The new frame's views, and those of earlier frames without any (a format-1 file, or a
    // format-2 file written before frame views, resumed).
    long without_views = 1;
    for (long k = 0; k < frames; ++k) without_views += h5::exists(f, frame_view_group(k)) ? 0 : 1;
    const long vertices = vertex_index_length(f);
    return run_growth::series_entries(frames, growth_layout().frame_series) +
           run_growth::frame_views(without_views, frame_view_arrays().size() + 2, vertices,
                                   std::max({vertices, total, particle_capacity()}),
                                   kVertexIndexChunk);
  });
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
  const std::size_t spins = dim_ == 3 ? 3 : 1;
  std::vector<double> spin = p.angular_velocity;
  if (spin.empty()) spin.assign(n * spins, 0.0);
  if (spin.size() != n * spins)
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
    // `width` values a particle: a scalar element, or a 3-D spin vector.
    auto write_doubles = [&](const char* name, const std::vector<double>& v, std::size_t width) {
      Handle set = h5::open_dataset(f, all + "/" + name + "/value");
      std::vector<hsize_t> dims = {frame + 1, capacity};
      if (width > 1) dims.push_back(hsize_t(width));
      write_frame_rows(set.get(), dims, frame, rows, H5T_NATIVE_DOUBLE, v.data(), transfer);
    };
    if (!contents_.species_radius.empty()) write_doubles("radius", radius, 1);
    if (contents_.angular_velocity) write_doubles("angular_velocity", spin, spins);
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
      read_frame_rows(file_.get(), base + "/angular_velocity", frame, n, dim_ == 3 ? 3 : 0,
                      p.angular_velocity);
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

}  // namespace granshock
