#include "field_sums_file.hpp"

#include <cmath>
#include <limits>
#include <string>

#include "run_file.hpp"
#include "user_error.hpp"

namespace granshock {

void write_field_sums(RunFile& f, const FieldSumsRecord& r) {
  const BinLayout& g = r.sampling.grid;
  const std::vector<double> samples(r.samples.begin(), r.samples.end());
  f.write_array("/fields/grid/sums", r.grid_sums, {g.blocks, g.ny, g.nx, g.quantities()});
  f.write_array("/fields/grid/samples", samples, {g.blocks});
  f.write_attribute("/fields/grid", "nx", long(g.nx));
  f.write_attribute("/fields/grid", "ny", long(g.ny));
  f.write_attribute("/fields/grid", "blocks", long(g.blocks));
  f.write_attribute("/fields/grid", "n_species", long(g.n_species));
  f.write_attribute("/fields/grid", "x0", g.x0);
  f.write_attribute("/fields/grid", "y0", g.y0);
  f.write_attribute("/fields/grid", "bin_size", g.bin_size);
  f.write_attribute("/fields/grid", "production_start", r.production_start);
  f.write_attribute("/fields/grid", "production_end", r.production_end);
  f.write_attribute("/fields/grid", "sample_every", r.sample_every);
  const ProfileLayout& p = r.sampling.profile;
  if (p.n > 0) {
    f.write_array("/fields/profile/sums", r.profile_sums, {g.blocks, p.n, g.quantities()});
    f.write_array("/fields/profile/samples", samples, {g.blocks});
    f.write_attribute("/fields/profile", "n", long(p.n));
    f.write_attribute("/fields/profile", "x_lo", p.x_lo);
    f.write_attribute("/fields/profile", "x_hi", p.x_hi);
    f.write_attribute("/fields/profile", "y0", p.y0);
    f.write_attribute("/fields/profile", "dy", p.dy);
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
  if (q < 4 + BinLayout::per_species || (q - 4) % BinLayout::per_species != 0)
    throw UserError(where + "/sums has shape " + shape_text(shape) + ": expected rank " +
                    std::to_string(rank) +
                    " with a last extent of 6 n_species + 4 (core/bin_layout.hpp)");
  const int species_from_shape = static_cast<int>((q - 4) / BinLayout::per_species);
  if (s.n_species <= 0) s.n_species = species_from_shape;
  const std::vector<long> expected = rank == 4
                                         ? std::vector<long>{s.blocks, s.ny, s.nx, s.quantities()}
                                         : std::vector<long>{s.blocks, s.ny, s.quantities()};
  if (shape != expected || sample_shape != std::vector<long>{s.blocks})
    throw UserError(where + "/sums has shape " + shape_text(shape) + " and /samples " +
                    shape_text(sample_shape) + "; its attributes ask for " + shape_text(expected) +
                    " and [" + std::to_string(s.blocks) + "]");
  for (double n : s.samples)
    if (!(n >= 0)) throw UserError(where + "/samples holds " + std::to_string(n) + ", not a count");
}

}  // namespace

BinSums read_grid_sums(const RunFile& run) {
  const std::string g = "/fields/grid";
  BinSums s;
  std::vector<long> shape, sample_shape;
  reading_sums(run, g, [&] {
    s.nx = static_cast<int>(run.read_attribute_long(g, "nx"));
    s.ny = static_cast<int>(run.read_attribute_long(g, "ny"));
    s.blocks = static_cast<int>(run.read_attribute_long(g, "blocks"));
    s.n_species = static_cast<int>(run.read_attribute_long(g, "n_species"));
    s.x0 = run.read_attribute_double(g, "x0");
    s.y0 = run.read_attribute_double(g, "y0");
    s.dx = s.dy = run.read_attribute_double(g, "bin_size");
    s.production_start = optional_double(run, g, "production_start");
    s.production_end = optional_double(run, g, "production_end");
    s.sums = run.read_array(g + "/sums", &shape);
    s.samples = run.read_array(g + "/samples", &sample_shape);
  });
  validate(run, g, s, shape, sample_shape, 4);
  return s;
}

bool has_profile_sums(const RunFile& run) {
  try {
    static_cast<void>(run.read_attribute_long("/fields/profile", "n"));
    return true;
  } catch (const UserError&) {
    return false;
  }
}

BinSums read_profile_sums(const RunFile& run) {
  const std::string g = "/fields/profile";
  BinSums s;
  std::vector<long> shape, sample_shape;
  reading_sums(run, g, [&] {
    s.n_species = 0;  // from the shape
    s.nx = 1;
    s.ny = static_cast<int>(run.read_attribute_long(g, "n"));
    s.x0 = run.read_attribute_double(g, "x_lo");
    s.dx = run.read_attribute_double(g, "x_hi") - s.x0;
    s.y0 = run.read_attribute_double(g, "y0");
    s.dy = run.read_attribute_double(g, "dy");
    s.production_start = s.production_end = std::numeric_limits<double>::quiet_NaN();
    s.sums = run.read_array(g + "/sums", &shape);
    s.samples = run.read_array(g + "/samples", &sample_shape);
    s.blocks = static_cast<int>(s.samples.size());
  });
  validate(run, g, s, shape, sample_shape, 3);
  return s;
}

}  // namespace granshock
