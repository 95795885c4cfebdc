// run.h5's time-indexed elements (H5MD style: GROUP/{step,time,value}): creating them,
// appending entries, and the /observables series (RunFile::append_time_series).
#include <hdf5.h>

#include <string>
#include <type_traits>
#include <vector>

#include "io/hdf5_helpers.hpp"
#include "io/run_file.hpp"
#include "io/run_file_parts.hpp"

namespace granshock {

using namespace run_file_detail;

namespace {

using h5::Handle;

// Time-indexed 1-D datasets grow by this many entries per chunk (2 KiB of int64).
constexpr hsize_t kSeriesChunk = 256;
// Snapshots are stored byte-shuffled and gzip level 1 (0 = uncompressed): a third smaller
// for a few times the write time (docs/output_format.md, "Storage"). Compression also
// keeps small runs small: a frame's last chunk is padded with fill values up to the
// chunk size, and the padding compresses to almost nothing.
constexpr unsigned kSnapshotDeflate = 1;

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

}  // namespace

namespace run_file_detail {

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

void create_observables(hid_t file) {
  for_each_observable(TimeSeriesRow{}, [&](const char* name, auto value, const char* unit) {
    const bool integer = std::is_integral_v<decltype(value)>;
    create_time_element(file, std::string(kObservables) + "/" + name,
                        integer ? H5T_STD_I64LE : H5T_IEEE_F64LE, {}, nullptr, H5T_NATIVE_DOUBLE,
                        unit);
  });
}

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

void append_step_time(hid_t file, const std::string& group_path, hsize_t index, long step,
                      double time) {
  Handle time_set = h5::open_dataset(file, group_path + "/time");
  extend_and_write(time_set.get(), {index + 1}, {index}, {1}, H5T_NATIVE_DOUBLE, &time);
  Handle step_set = h5::open_dataset(file, group_path + "/step");
  extend_and_write(step_set.get(), {index + 1}, {index}, {1}, H5T_NATIVE_LONG, &step);
}

}  // namespace run_file_detail

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

}  // namespace granshock
