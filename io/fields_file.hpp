// fields.h5, the averaged fields of a run on its bin grid (written by `granshock fields`;
// layout in docs/fields.md). The content is given as plain arrays, so this writer knows
// nothing of the analysis: cell fields on the grid, integer flags, polylines, 1-D series
// and attributes. The file is written to a temporary name, synced and renamed, so that a
// reader never sees half of it.
#pragma once

#include <array>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace granshock {

struct FieldsFileContent {
  // The grid: nx x ny cells of dx x dy, cell (0, 0) with its lower-left corner at (x0, y0).
  int nx = 0, ny = 0;
  double x0 = 0, y0 = 0, dx = 0, dy = 0;

  struct CellField {  // /fields/<name>, float64 [ny, nx]
    std::string name, unit, description;
    std::vector<double> values;
  };
  struct CellFlag {  // /fields/<name>, int32 [ny, nx]
    std::string name, description;
    std::vector<int> values;
  };
  struct Lines {  // /lines/<name>/points float64 [k, 2], /lines/<name>/offsets int64 [lines + 1]
    std::string name, description;
    std::vector<std::vector<std::array<double, 2>>> lines;
  };
  struct Series {  // a 1-D float64 dataset at `path` (e.g. "/profile/phi")
    std::string path, unit, description;
    std::vector<double> values;
  };
  struct Attribute {  // on `object` (a group, created when missing; "/" for the file)
    std::string object, name;
    double value = 0;
  };
  struct TextAttribute {
    std::string object, name, value;
  };

  std::vector<CellField> cell_fields;
  std::vector<CellFlag> cell_flags;
  // The obstacle's cross-section, a closed polygon in m (empty: none), which fields.xmf
  // shows as a grid of its own (io/xdmf_writer.hpp, obstacle_grid_xml).
  std::vector<std::array<double, 2>> obstacle_outline;
  std::vector<Lines> lines;
  std::vector<Series> series;
  std::vector<Attribute> attributes;
  std::vector<TextAttribute> text_attributes;
};

// A cell vector that fields files show besides the scalars (docs/fields.md, "fields.xmf"):
// /vectors/<name>, float64 [ny, nx, 3], an HDF5 virtual dataset whose components are the
// cell fields x and y and 0 (no data copied), so that a viewer draws glyphs or stream
// lines of the mean flow without a calculator.
struct CellVector {
  std::string name, x, y;
};
// The mean velocity u = (ux, uy, 0) and each species' u_s = (ux_s, uy_s, 0), where the
// content has both components.
std::vector<CellVector> cell_vectors(const FieldsFileContent& content);

// Writes `path` atomically. Besides the content it writes /grid: x [nx] and y [ny] (cell
// centres), x_nodes [nx + 1], y_nodes [ny + 1], nodes [ny + 1, nx + 1, 2] (the corner
// coordinates the XDMF geometry refers to) and @nx, @ny, @x0, @y0, @dx, @dy; and on the
// root @granshock_file = "fields", @granshock_format_version = 2; and cell_vectors().
// Throws std::invalid_argument when an array does not match the grid, UserError naming the
// file when it cannot be written.
void write_fields_file(const std::filesystem::path& path, const FieldsFileContent& content);

}  // namespace granshock
