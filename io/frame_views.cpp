#include "io/frame_views.hpp"

#include <algorithm>
#include <cstdio>
#include <numeric>

#include "io/hdf5_helpers.hpp"

namespace granshock {

namespace {

using h5::Handle;

constexpr const char* kViews = "/xdmf";
constexpr const char* kVertexIndex = "/xdmf/vertex_index";
// The per-particle elements of /particles/all a view can show, in the order a viewer
// lists them (the first scalar is the one it colours by).
constexpr const char* kElements[] = {"species", "id", "velocity", "radius", "angular_velocity"};

std::string element_value(const std::string& name) {
  return "/particles/all/" + name + "/value";
}

// The stored type of `dataset`, as the views store it (int32 or float64).
bool stored_as_integer(hid_t dataset) {
  Handle type = h5::datatype(H5Dget_type(dataset), "reading a dataset type");
  return H5Tget_class(type.get()) == H5T_INTEGER;
}

// /xdmf/vertex_index holds 0, 1, 2, ...: the vertex cells' point indices, which the
// Xdmf3 readers need (they make no cells from a Polyvertex without them). Grown to at
// least n entries.
void grow_vertex_index(hid_t file, hsize_t n) {
  if (!h5::exists(file, kVertexIndex)) {
    const hsize_t dims[1] = {0};
    const hsize_t max_dims[1] = {H5S_UNLIMITED};
    const hsize_t chunk[1] = {kVertexIndexChunk};
    Handle space = h5::dataspace(H5Screate_simple(1, dims, max_dims), "creating a dataspace");
    Handle props = h5::plist(H5Pcreate(H5P_DATASET_CREATE), "creating dataset properties");
    h5::check(H5Pset_chunk(props.get(), 1, chunk), "setting the chunk shape");
    if (H5Zfilter_avail(H5Z_FILTER_DEFLATE) > 0)
      h5::check(H5Pset_deflate(props.get(), 1), "enabling gzip");
    h5::add_checksum(props.get());  // as run.h5's other chunks (io/run_file.cpp)
    Handle views = h5::require_group(file, kViews);
    h5::dataset(H5Dcreate2(views.get(), "vertex_index", H5T_STD_I32LE, space.get(), H5P_DEFAULT,
                           props.get(), H5P_DEFAULT),
                "creating '" + std::string(kVertexIndex) + "'");
  }
  Handle index = h5::open_dataset(file, kVertexIndex);
  const hsize_t have = h5::shape_of(index.get()).at(0);
  if (have >= n) return;
  const hsize_t new_dims[1] = {n};
  h5::check(H5Dset_extent(index.get(), new_dims), "extending '" + std::string(kVertexIndex) + "'");
  std::vector<int> values(n - have);
  std::iota(values.begin(), values.end(), static_cast<int>(have));
  const hsize_t start[1] = {have};
  const hsize_t count[1] = {n - have};
  Handle file_space = h5::dataspace(H5Dget_space(index.get()), "reading a dataspace");
  h5::check(H5Sselect_hyperslab(file_space.get(), H5S_SELECT_SET, start, nullptr, count, nullptr),
            "selecting a hyperslab");
  Handle memory_space = h5::dataspace(H5Screate_simple(1, count, nullptr), "creating a dataspace");
  h5::check(H5Dwrite(index.get(), H5T_NATIVE_INT, memory_space.get(), file_space.get(), H5P_DEFAULT,
                     values.data()),
            "writing '" + std::string(kVertexIndex) + "'");
}

// The virtual dataset GROUP/name of n rows: rows [first_row..., 0:n, 0:width] of the
// dataset at `source` (the leading index `frame` when the source has a frame axis),
// `columns` wide (more than the source's width: the rest reads as 0).
void make_view(hid_t group, const char* name, const std::string& source, bool frame_axis,
               hsize_t frame, hsize_t n, hsize_t columns) {
  Handle set = h5::open_dataset(group, source);
  const std::vector<hsize_t> source_dims = h5::shape_of(set.get());
  const bool vector = source_dims.size() == (frame_axis ? 3u : 2u);
  const hsize_t width = vector ? source_dims.back() : 1;
  const bool integer = stored_as_integer(set.get());
  set.close();

  Handle source_space =
      h5::dataspace(H5Screate_simple(int(source_dims.size()), source_dims.data(), nullptr),
                    "creating a dataspace");
  std::vector<hsize_t> start, count;
  if (frame_axis) {
    start.push_back(frame);
    count.push_back(1);
  }
  start.push_back(0);
  count.push_back(n);
  if (vector) {
    start.push_back(0);
    count.push_back(width);
  }
  h5::check(H5Sselect_hyperslab(source_space.get(), H5S_SELECT_SET, start.data(), nullptr,
                                count.data(), nullptr),
            "selecting a frame");

  const hsize_t view_dims[2] = {n, vector ? columns : 1};
  const int view_rank = vector ? 2 : 1;
  Handle view_space =
      h5::dataspace(H5Screate_simple(view_rank, view_dims, nullptr), "creating a dataspace");
  const hsize_t view_start[2] = {0, 0};
  const hsize_t view_count[2] = {n, width};
  h5::check(H5Sselect_hyperslab(view_space.get(), H5S_SELECT_SET, view_start, nullptr, view_count,
                                nullptr),
            "selecting a view");

  Handle props = h5::plist(H5Pcreate(H5P_DATASET_CREATE), "creating dataset properties");
  const double zero = 0;
  const int zero_int = 0;
  h5::check(integer ? H5Pset_fill_value(props.get(), H5T_NATIVE_INT, &zero_int)
                    : H5Pset_fill_value(props.get(), H5T_NATIVE_DOUBLE, &zero),
            "setting a fill value");
  // "." is this file, wherever it is moved.
  h5::check(H5Pset_virtual(props.get(), view_space.get(), ".", source.c_str(), source_space.get()),
            "mapping a view");
  Handle whole =
      h5::dataspace(H5Screate_simple(view_rank, view_dims, nullptr), "creating a dataspace");
  h5::dataset(H5Dcreate2(group, name, integer ? H5T_STD_I32LE : H5T_IEEE_F64LE, whole.get(),
                         H5P_DEFAULT, props.get(), H5P_DEFAULT),
              std::string("creating the view '") + name + "'");
}

void make_frame_views(hid_t file, int dim, long frame, long count) {
  Handle group = h5::require_group(file, frame_view_group(frame));
  if (count == 0) return;  // an empty group: viewers leave empty frames out
  const hsize_t k = hsize_t(frame), n = hsize_t(count);
  make_view(group.get(), "position", element_value("position"), true, k, n, hsize_t(dim));
  make_view(group.get(), "vertex", kVertexIndex, false, 0, n, 1);
  for (const FrameViewArray& a : frame_view_arrays(file))
    make_view(group.get(), a.name.c_str(), element_value(a.name), true, k, n, 3);
}

void remove_views(hid_t file, long frame) {
  const std::string path = frame_view_group(frame);
  h5::check(H5Ldelete(file, path.c_str(), H5P_DEFAULT), "removing '" + path + "'");
}

}  // namespace

long vertex_index_length(hid_t file) {
  if (!h5::exists(file, kVertexIndex)) return 0;
  Handle index = h5::open_dataset(file, kVertexIndex);
  return long(h5::shape_of(index.get()).at(0));
}

std::string frame_view_group(long frame) {
  char name[48];
  std::snprintf(name, sizeof name, "%s/frame_%06ld", kViews, frame);
  return name;
}

std::vector<FrameViewArray> frame_view_arrays(hid_t file) {
  std::vector<FrameViewArray> arrays;
  for (const char* name : kElements) {
    if (!h5::exists(file, element_value(name))) continue;
    Handle set = h5::open_dataset(file, element_value(name));
    const bool vector = h5::shape_of(set.get()).size() == 3;
    arrays.push_back({name, vector ? 3 : 1, stored_as_integer(set.get())});
  }
  return arrays;
}

void update_frame_views(hid_t file, int dim, const std::vector<long>& counts) {
  if (counts.empty()) return;
  const long last = long(counts.size()) - 1;
  grow_vertex_index(file, hsize_t(*std::max_element(counts.begin(), counts.end())));
  for (long k = 0; k < last; ++k)
    if (!h5::exists(file, frame_view_group(k))) make_frame_views(file, dim, k, counts[k]);
  if (h5::exists(file, frame_view_group(last))) remove_views(file, last);
  make_frame_views(file, dim, last, counts[last]);
  for (long k = last + 1; h5::exists(file, frame_view_group(k)); ++k) remove_views(file, k);
}

}  // namespace granshock
