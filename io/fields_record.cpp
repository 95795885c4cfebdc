#include "io/fields_record.hpp"

#include <fmt/format.h>

#include <array>

#include "io/hdf5_helpers.hpp"

namespace granshock {

namespace fs = std::filesystem;
using h5::checked;
using h5::Handle;

namespace {

// Groups copied whole, where the fields file has them.
constexpr std::array<const char*, 6> kCopiedGroups = {"lines",    "front",   "profile",
                                                      "upstream", "summary", "obstacle"};

struct AttributeCopy {
  hid_t to;
  std::string error;
};

// One attribute of `from` onto the object in `op` (an AttributeCopy), with its own type and
// shape; variable-length data is copied and then freed.
herr_t copy_attribute(hid_t from, const char* name, const H5A_info_t*, void* op) {
  auto& copy = *static_cast<AttributeCopy*>(op);
  try {
    Handle a = checked(H5Aopen(from, name, H5P_DEFAULT), H5Aclose, "opening an attribute");
    Handle type = checked(H5Aget_type(a.get()), H5Tclose, "reading an attribute's type");
    Handle space = checked(H5Aget_space(a.get()), H5Sclose, "reading an attribute's shape");
    const hssize_t points = H5Sget_simple_extent_npoints(space.get());
    std::vector<unsigned char> buffer(std::size_t(std::max<hssize_t>(points, 1)) *
                                      H5Tget_size(type.get()));
    h5::check(H5Aread(a.get(), type.get(), buffer.data()), "reading an attribute");
    Handle b = checked(H5Acreate2(copy.to, name, type.get(), space.get(), H5P_DEFAULT, H5P_DEFAULT),
                       H5Aclose, "creating an attribute");
    const herr_t written = H5Awrite(b.get(), type.get(), buffer.data());
    if (H5Tdetect_class(type.get(), H5T_VLEN) > 0 || H5Tis_variable_str(type.get()) > 0)
      H5Dvlen_reclaim(type.get(), space.get(), H5P_DEFAULT, buffer.data());
    h5::check(written, "writing an attribute");
    return 0;
  } catch (const std::exception& e) {
    copy.error = fmt::format("attribute '{}': {}", name, e.what());
    return -1;
  }
}

void copy_attributes(hid_t from, hid_t to) {
  AttributeCopy copy{to, {}};
  hsize_t index = 0;
  if (H5Aiterate2(from, H5_INDEX_NAME, H5_ITER_INC, &index, copy_attribute, &copy) < 0)
    throw h5::Hdf5Error(copy.error.empty() ? "copying attributes failed" : copy.error);
}

void copy_object(hid_t from, hid_t to, const std::string& path) {
  h5::check(H5Ocopy(from, path.c_str(), to, path.c_str(), H5P_DEFAULT, H5P_DEFAULT),
            "copying '" + path + "'");
}

// A [ny, nx] field as `stored` (float32 or uint8), in one deflated chunk with the shuffle
// filter, its attributes (unit, description) kept.
template <class T>
void write_reduced_field(hid_t in_fields, hid_t out_fields, const std::string& name, hid_t stored,
                         hid_t memory) {
  std::vector<hsize_t> shape;
  const std::vector<double> values = h5::read_dataset<double>(in_fields, name, &shape);
  std::vector<T> reduced(values.begin(), values.end());
  Handle space = checked(H5Screate_simple(int(shape.size()), shape.data(), nullptr), H5Sclose,
                         "creating the shape of '" + name + "'");
  Handle creation = checked(H5Pcreate(H5P_DATASET_CREATE), H5Pclose, "creating properties");
  std::vector<hsize_t> chunk = shape;
  for (hsize_t& c : chunk) c = std::max<hsize_t>(c, 1);
  if (!chunk.empty()) {
    h5::check(H5Pset_chunk(creation.get(), int(chunk.size()), chunk.data()), "setting chunks");
    h5::check(H5Pset_shuffle(creation.get()), "setting the shuffle filter");
    h5::check(H5Pset_deflate(creation.get(), 6), "setting deflate");
  }
  Handle set = checked(H5Dcreate2(out_fields, name.c_str(), stored, space.get(), H5P_DEFAULT,
                                  creation.get(), H5P_DEFAULT),
                       H5Dclose, "creating '" + name + "'");
  if (!reduced.empty())
    h5::check(H5Dwrite(set.get(), memory, H5S_ALL, H5S_ALL, H5P_DEFAULT, reduced.data()),
              "writing '" + name + "'");
  Handle source = h5::open_dataset(in_fields, name);
  copy_attributes(source.get(), set.get());
}

}  // namespace

const std::vector<std::string>& default_record_fields() {
  static const std::vector<std::string> names = {"phi", "T",          "Ma",    "ux",
                                                 "uy",  "mean_count", "masked"};
  return names;
}

void write_fields_record(const fs::path& fields_h5, const fs::path& record,
                         const std::vector<std::string>& fields) {
  h5::silence_error_printing();
  Handle in = h5::naming_file_in_errors(fields_h5, "reading", [&] {
    return checked(H5Fopen(fields_h5.string().c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose,
                   "opening the fields file");
  });
  std::vector<std::string> kept;
  h5::write_file_atomically(record, "the case record's fields", [&](hid_t out) {
    Handle in_root = h5::open_group(in.get(), "/");
    Handle out_root = h5::open_group(out, "/");
    copy_attributes(in_root.get(), out_root.get());
    for (const char* group : kCopiedGroups)
      if (h5::exists(in.get(), group)) copy_object(in.get(), out, group);
    Handle in_grid = h5::open_group(in.get(), "grid");
    Handle out_grid = h5::require_group(out, "grid");
    copy_attributes(in_grid.get(), out_grid.get());
    for (const char* axis : {"grid/x", "grid/y", "grid/x_nodes", "grid/y_nodes"})
      copy_object(in.get(), out, axis);
    Handle in_fields = h5::open_group(in.get(), "fields");
    Handle out_fields = h5::require_group(out, "fields");
    for (const std::string& name : fields) {
      if (!h5::exists(in_fields.get(), name)) continue;
      if (name == "masked")
        write_reduced_field<unsigned char>(in_fields.get(), out_fields.get(), name, H5T_STD_U8LE,
                                           H5T_NATIVE_UCHAR);
      else
        write_reduced_field<float>(in_fields.get(), out_fields.get(), name, H5T_IEEE_F32LE,
                                   H5T_NATIVE_FLOAT);
      kept.push_back(name);
    }
    h5::write_attribute(out_root.get(), "granshock_record", 1);
    h5::write_attribute(out_root.get(), "record_fields", fmt::format("{}", fmt::join(kept, ",")));
  });
}

}  // namespace granshock
