#include "io/field_sums_file.hpp"

#include <cmath>
#include <limits>
#include <string>

#include "core/user_error.hpp"
#include "io/hdf5_helpers.hpp"
#include "io/run_file.hpp"

namespace granshock {

namespace {

// The geometry of one bin layout as attributes of `group` (docs/fields.md, section 1).
void write_geometry(RunFile& f, const std::string& group, const BinLayout& l, double y_end) {
  f.write_attribute(group, "nx", long(l.nx));
  f.write_attribute(group, "ny", long(l.ny));
  f.write_attribute(group, "blocks", long(l.blocks));
  f.write_attribute(group, "n_species", long(l.n_species));
  f.write_attribute(group, "x0", l.x0);
  f.write_attribute(group, "y0", l.y0);
  f.write_attribute(group, "dx", l.dx);
  f.write_attribute(group, "dy", l.dy);
  f.write_attribute(group, "x_period", l.x_period);
  f.write_attribute(group, "y_end", y_end);
  if (l.dim == 3) {  // 2-D files as they were
    f.write_attribute(group, "depth", l.depth);
    f.write_attribute(group, "z0", l.z0);
  }
}

}  // namespace

void write_field_sums(RunFile& f, const FieldSumsRecord& r) {
  const BinLayout& g = r.sampling.grid;
  const std::vector<double> samples(r.samples.begin(), r.samples.end());
  f.write_array("/fields/grid/sums", r.grid_sums, {g.blocks, g.ny, g.nx, g.quantities()});
  f.write_array("/fields/grid/samples", samples, {g.blocks});
  write_geometry(f, "/fields/grid", g, r.y_end);
  f.write_attribute("/fields/grid", "production_start", r.production_start);
  f.write_attribute("/fields/grid", "production_end", r.production_end);
  f.write_attribute("/fields/grid", "sample_every", r.sample_every);
  if (r.sampling.has_profile()) {
    const BinLayout& p = r.sampling.profile;
    f.write_array("/fields/profile/sums", r.profile_sums, {g.blocks, p.ny, p.nx, g.quantities()});
    f.write_array("/fields/profile/samples", samples, {g.blocks});
    write_geometry(f, "/fields/profile", p, r.y_end);
  }
}

namespace {

std::string shape_text(const std::vector<long>& shape) {
  std::string s = "[";
  for (std::size_t i = 0; i < shape.size(); ++i) s += (i ? ", " : "") + std::to_string(shape[i]);
  return s + "]";
}

// Runs f, which reads attributes and arrays; a failure there means the run file has no
// (complete) field sums, which the user can fix by running with a production window.
template <class F>
void reading_sums(const RunFile& run, const std::string& group, F&& f) {
  try {
    f();
  } catch (const h5::DamagedFile&) {
    throw;  // the sums are there, damaged
  } catch (const UserError& e) {
    throw UserError("'" + run.path().string() + "' holds no usable field sums at " + group +
                    " (written by `granshock run` over its production window): " + e.what());
  }
}

double optional_double(const RunFile& run, const std::string& object, const std::string& name) {
  try {
    return run.read_attribute_double(object, name);
  } catch (const UserError&) {
    return std::numeric_limits<double>::quiet_NaN();
  }
}

// Checks what was read against the attributes: sums [blocks, ny, nx, q] (grid) or
// [blocks, n, q] (profile) with q = 6 n_species + 4, samples [blocks].
void validate(const RunFile& run, const std::string& group, BinSums& s,
              const std::vector<long>& shape, const std::vector<long>& sample_shape,
              std::size_t rank) {
  const std::string where = "'" + run.path().string() + "': " + group;
  if (s.nx < 1 || s.ny < 1 || s.blocks < 1 || !(s.dx > 0) || !(s.dy > 0))
    throw UserError(where + " has " + std::to_string(s.nx) + " x " + std::to_string(s.ny) +
                    " bins of " + std::to_string(s.dx) + " m x " + std::to_string(s.dy) + " m in " +
                    std::to_string(s.blocks) + " blocks; all must be positive");
  const long q = shape.size() == rank ? shape.back() : 0;
  // 6 n + 4 quantities, and 2 n + 1 more in 3-D (core/bin_layout.hpp).
  const long fixed = s.dim == 3 ? 5 : 4, per = BinLayout::per_species + (s.dim == 3 ? 2 : 0);
  if (q < fixed + per || (q - fixed) % per != 0 || (s.dim == 3 && !(s.depth > 0)))
    throw UserError(where + "/sums has shape " + shape_text(shape) + ": expected rank " +
                    std::to_string(rank) +
                    (s.dim == 3 ? " with a last extent of 8 n_species + 5 and depth > 0"
                                : " with a last extent of 6 n_species + 4") +
                    " (core/bin_layout.hpp)");
  const int species_from_shape = static_cast<int>((q - fixed) / per);
  if (s.n_species <= 0) s.n_species = species_from_shape;
  const std::vector<long> expected = rank == 4
                                         ? std::vector<long>{s.blocks, s.ny, s.nx, s.quantities()}
                                         : std::vector<long>{s.blocks, s.ny, s.quantities()};
  if (!(s.y_end > s.y0) || !(s.x_period >= 0))
    throw UserError(where + " has y_end = " + std::to_string(s.y_end) + " and x_period = " +
                    std::to_string(s.x_period) + ": the domain must end after the first row");
  if (shape != expected || sample_shape != std::vector<long>{s.blocks})
    throw UserError(where + "/sums has shape " + shape_text(shape) + " and /samples " +
                    shape_text(sample_shape) + "; its attributes ask for " + shape_text(expected) +
                    " and [" + std::to_string(s.blocks) + "]");
  for (double n : s.samples)
    if (!(n >= 0)) throw UserError(where + "/samples holds " + std::to_string(n) + ", not a count");
}

}  // namespace

namespace {

// Reads a layout written by write_geometry; files before granshock 0.9 had square grid bins
// (@bin_size) and a profile of one column (@n rows, @x_lo, @x_hi, @dy).
void read_geometry(const RunFile& run, const std::string& g, BinSums& s) {
  s.n_species = static_cast<int>(run.read_attribute_long(g, "n_species"));
  s.x0 = run.read_attribute_double(g, "x0");
  s.y0 = run.read_attribute_double(g, "y0");
  s.nx = static_cast<int>(run.read_attribute_long(g, "nx"));
  s.ny = static_cast<int>(run.read_attribute_long(g, "ny"));
  s.dx = run.read_attribute_double(g, "dx");
  s.dy = run.read_attribute_double(g, "dy");
  s.x_period = run.read_attribute_double(g, "x_period");
  s.y_end = run.read_attribute_double(g, "y_end");
  s.depth = optional_double(run, g, "depth");
  s.dim = std::isfinite(s.depth) ? 3 : 2;
  if (s.dim == 2) s.depth = 0;
  s.z0 = s.dim == 3 ? run.read_attribute_double(g, "z0") : 0;
}

bool has_attribute(const RunFile& run, const std::string& object, const std::string& name) {
  return std::isfinite(optional_double(run, object, name));
}

}  // namespace

BinSums read_grid_sums(const RunFile& run) {
  const std::string g = "/fields/grid";
  BinSums s;
  std::vector<long> shape, sample_shape;
  reading_sums(run, g, [&] {
    if (has_attribute(run, g, "dx")) {
      read_geometry(run, g, s);
    } else {
      s.nx = static_cast<int>(run.read_attribute_long(g, "nx"));
      s.ny = static_cast<int>(run.read_attribute_long(g, "ny"));
      s.n_species = static_cast<int>(run.read_attribute_long(g, "n_species"));
      s.x0 = run.read_attribute_double(g, "x0");
      s.y0 = run.read_attribute_double(g, "y0");
      s.dx = s.dy = run.read_attribute_double(g, "bin_size");
    }
    s.blocks = static_cast<int>(run.read_attribute_long(g, "blocks"));
    s.production_start = optional_double(run, g, "production_start");
    s.production_end = optional_double(run, g, "production_end");
    s.sums = run.read_array(g + "/sums", &shape);
    s.samples = run.read_array(g + "/samples", &sample_shape);
  });
  validate(run, g, s, shape, sample_shape, 4);
  return s;
}

bool has_profile_sums(const RunFile& run) {
  return has_attribute(run, "/fields/profile", "dy");
}

BinSums read_profile_sums(const RunFile& run) {
  const std::string g = "/fields/profile";
  BinSums s;
  std::vector<long> shape, sample_shape;
  std::size_t rank = 4;
  reading_sums(run, g, [&] {
    if (has_attribute(run, g, "dx")) {
      read_geometry(run, g, s);
      s.n_species = 0;  // from the shape
    } else {
      rank = 3;
      s.n_species = 0;
      s.nx = 1;
      s.ny = static_cast<int>(run.read_attribute_long(g, "n"));
      s.x0 = run.read_attribute_double(g, "x_lo");
      s.dx = run.read_attribute_double(g, "x_hi") - s.x0;
      s.y0 = run.read_attribute_double(g, "y0");
      s.dy = run.read_attribute_double(g, "dy");
    }
    s.production_start = s.production_end = std::numeric_limits<double>::quiet_NaN();
    s.sums = run.read_array(g + "/sums", &shape);
    s.samples = run.read_array(g + "/samples", &sample_shape);
    s.blocks = static_cast<int>(s.samples.size());
  });
  validate(run, g, s, shape, sample_shape, rank);
  return s;
}

}  // namespace granshock
