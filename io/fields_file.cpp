#include "io/fields_file.hpp"

#include <stdexcept>
#include <system_error>

#include "core/user_error.hpp"
#include "io/hdf5_helpers.hpp"

namespace granshock {

namespace fs = std::filesystem;
using h5::Handle;

namespace {

// 2: /obstacle/outline (format 1 files have none; the figures then draw the shape from
// its sizes, analysis/plot_fields.py).
constexpr int kFormatVersion = 2;

void check_content(const FieldsFileContent& c) {
  if (c.nx < 1 || c.ny < 1 || !(c.dx > 0) || !(c.dy > 0))
    throw std::invalid_argument(
        "write_fields_file: the grid needs nx, ny >= 1 and positive dx, dy");
  const std::size_t cells = static_cast<std::size_t>(c.nx) * static_cast<std::size_t>(c.ny);
  for (const auto& f : c.cell_fields)
    if (f.values.size() != cells)
      throw std::invalid_argument("write_fields_file: field '" + f.name + "' is not nx x ny");
  for (const auto& f : c.cell_flags)
    if (f.values.size() != cells)
      throw std::invalid_argument("write_fields_file: flag '" + f.name + "' is not nx x ny");
}

void write_grid(hid_t file, const FieldsFileContent& c) {
  Handle grid = h5::require_group(file, "/grid");
  h5::write_attribute(grid.get(), "nx", static_cast<long>(c.nx));
  h5::write_attribute(grid.get(), "ny", static_cast<long>(c.ny));
  h5::write_attribute(grid.get(), "x0", c.x0);
  h5::write_attribute(grid.get(), "y0", c.y0);
  h5::write_attribute(grid.get(), "dx", c.dx);
  h5::write_attribute(grid.get(), "dy", c.dy);
  const hsize_t nx = static_cast<hsize_t>(c.nx), ny = static_cast<hsize_t>(c.ny);
  std::vector<double> x(nx), y(ny), xn(nx + 1), yn(ny + 1), nodes;
  for (hsize_t i = 0; i < nx; ++i) x[i] = c.x0 + (static_cast<double>(i) + 0.5) * c.dx;
  for (hsize_t j = 0; j < ny; ++j) y[j] = c.y0 + (static_cast<double>(j) + 0.5) * c.dy;
  for (hsize_t i = 0; i <= nx; ++i) xn[i] = c.x0 + static_cast<double>(i) * c.dx;
  for (hsize_t j = 0; j <= ny; ++j) yn[j] = c.y0 + static_cast<double>(j) * c.dy;
  nodes.reserve(2 * (nx + 1) * (ny + 1));
  for (hsize_t j = 0; j <= ny; ++j)
    for (hsize_t i = 0; i <= nx; ++i) {
      nodes.push_back(xn[i]);
      nodes.push_back(yn[j]);
    }
  h5::write_dataset(grid.get(), "x", x, {nx});
  h5::write_dataset(grid.get(), "y", y, {ny});
  h5::write_dataset(grid.get(), "x_nodes", xn, {nx + 1});
  h5::write_dataset(grid.get(), "y_nodes", yn, {ny + 1});
  h5::write_dataset(grid.get(), "nodes", nodes, {ny + 1, nx + 1, 2});
  for (const char* name : {"x", "y", "x_nodes", "y_nodes", "nodes"}) {
    Handle set = h5::open_dataset(grid.get(), name);
    h5::write_attribute(set.get(), "unit", "m");
  }
}

void describe(hid_t file, const std::string& path, const std::string& unit,
              const std::string& description) {
  Handle set = h5::open_dataset(file, path);
  if (!unit.empty()) h5::write_attribute(set.get(), "unit", unit);
  if (!description.empty()) h5::write_attribute(set.get(), "description", description);
}

// /vectors/<v.name>: the cell fields v.x and v.y as components 0 and 1 of a virtual
// dataset [ny, nx, 3] of this file ("."); component 2 is unmapped and reads as 0.
void write_vector_view(hid_t file, const CellVector& v, hsize_t ny, hsize_t nx) {
  const hsize_t cells[2] = {ny, nx};
  const hsize_t dims[3] = {ny, nx, 3};
  Handle props = h5::plist(H5Pcreate(H5P_DATASET_CREATE), "creating dataset properties");
  const double zero = 0;
  h5::check(H5Pset_fill_value(props.get(), H5T_NATIVE_DOUBLE, &zero), "setting a fill value");
  Handle source = h5::dataspace(H5Screate_simple(2, cells, nullptr), "creating a dataspace");
  const std::string component[2] = {"/fields/" + v.x, "/fields/" + v.y};
  for (hsize_t c = 0; c < 2; ++c) {
    Handle target = h5::dataspace(H5Screate_simple(3, dims, nullptr), "creating a dataspace");
    const hsize_t start[3] = {0, 0, c};
    const hsize_t count[3] = {ny, nx, 1};
    h5::check(H5Sselect_hyperslab(target.get(), H5S_SELECT_SET, start, nullptr, count, nullptr),
              "selecting a component");
    h5::check(H5Pset_virtual(props.get(), target.get(), ".", component[c].c_str(), source.get()),
              "mapping '" + component[c] + "'");
  }
  Handle vectors = h5::require_group(file, "/vectors");
  Handle space = h5::dataspace(H5Screate_simple(3, dims, nullptr), "creating a dataspace");
  h5::dataset(H5Dcreate2(vectors.get(), v.name.c_str(), H5T_IEEE_F64LE, space.get(), H5P_DEFAULT,
                         props.get(), H5P_DEFAULT),
              "creating '/vectors/" + v.name + "'");
  describe(file, "/vectors/" + v.name, "m s-1",
           "(" + v.x + ", " + v.y + ", 0): a view of the two fields, for glyphs and stream lines");
}

void write_content(hid_t file, const FieldsFileContent& c) {
  h5::write_attribute(file, "granshock_file", "fields");
  h5::write_attribute(file, "granshock_format_version", kFormatVersion);
  write_grid(file, c);
  const std::vector<hsize_t> cells{static_cast<hsize_t>(c.ny), static_cast<hsize_t>(c.nx)};
  for (const auto& f : c.cell_fields) {
    h5::write_dataset(file, "/fields/" + f.name, f.values, cells);
    describe(file, "/fields/" + f.name, f.unit, f.description);
  }
  for (const auto& f : c.cell_flags) {
    h5::write_dataset(file, "/fields/" + f.name, f.values, cells);
    describe(file, "/fields/" + f.name, "", f.description);
  }
  for (const CellVector& v : cell_vectors(c)) write_vector_view(file, v, cells[0], cells[1]);
  for (const auto& set : c.lines) {
    std::vector<double> points;
    std::vector<long> offsets{0};
    for (const auto& line : set.lines) {
      for (const auto& p : line) {
        points.push_back(p[0]);
        points.push_back(p[1]);
      }
      offsets.push_back(static_cast<long>(points.size() / 2));
    }
    const std::string base = "/lines/" + set.name;
    h5::write_dataset(file, base + "/points", points, {static_cast<hsize_t>(points.size() / 2), 2});
    h5::write_dataset(file, base + "/offsets", offsets, {static_cast<hsize_t>(offsets.size())});
    describe(file, base + "/points", "m",
             "polyline vertices (x, y); line i is points[offsets[i]:offsets[i+1]]");
    Handle group = h5::open_group(file, base);
    h5::write_attribute(group.get(), "description", set.description);
  }
  if (!c.obstacle_outline.empty()) {
    // What fields.xmf draws and the figures fill (analysis/plot_fields.py): the shape's own
    // outline, so that no reader has to know how a shape is drawn.
    std::vector<double> points;
    for (const auto& p : c.obstacle_outline) points.insert(points.end(), {p[0], p[1]});
    h5::write_dataset(file, "/obstacle/outline", points,
                      {static_cast<hsize_t>(c.obstacle_outline.size()), 2});
    describe(file, "/obstacle/outline", "m",
             "the obstacle's cross-section as a closed polygon (x, y), counter-clockwise, "
             "the first point not repeated; a cylinder as 72 points on its circle");
  }
  for (const auto& s : c.series) {
    h5::write_dataset(file, s.path, s.values, {static_cast<hsize_t>(s.values.size())});
    describe(file, s.path, s.unit, s.description);
  }
  for (const auto& a : c.attributes) {
    Handle object = h5::require_group(file, a.object);
    h5::write_attribute(object.get(), a.name, a.value);
  }
  for (const auto& a : c.text_attributes) {
    Handle object = h5::require_group(file, a.object);
    h5::write_attribute(object.get(), a.name, a.value);
  }
}

// The data must reach the disk before the rename does (as for checkpoints).

}  // namespace

std::vector<CellVector> cell_vectors(const FieldsFileContent& content) {
  auto has = [&](const std::string& name) {
    for (const auto& f : content.cell_fields)
      if (f.name == name) return true;
    return false;
  };
  std::vector<CellVector> vectors;
  for (const auto& f : content.cell_fields) {
    if (f.name.rfind("ux", 0) != 0) continue;
    const std::string suffix = f.name.substr(2);  // "" or "_<species>"
    if (!suffix.empty() && suffix[0] != '_') continue;
    if (has("uy" + suffix)) vectors.push_back({"u" + suffix, f.name, "uy" + suffix});
  }
  return vectors;
}

void write_fields_file(const fs::path& path, const FieldsFileContent& content) {
  check_content(content);
  h5::write_file_atomically(path, "fields file", [&](hid_t file) { write_content(file, content); });
}

}  // namespace granshock
