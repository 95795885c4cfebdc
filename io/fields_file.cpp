#include "fields_file.hpp"

#include <stdexcept>
#include <system_error>

#include "hdf5_helpers.hpp"
#include "user_error.hpp"

namespace granshock {

namespace fs = std::filesystem;
using h5::Handle;

namespace {

constexpr int kFormatVersion = 1;

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

void write_fields_file(const fs::path& path, const FieldsFileContent& content) {
  check_content(content);
  h5::write_file_atomically(path, "fields file", [&](hid_t file) { write_content(file, content); });
}

}  // namespace granshock
