#include "bin_sums.hpp"

#include <cmath>
#include <limits>
#include <numeric>
#include <stdexcept>
#include <string>

#include "run_file.hpp"
#include "user_error.hpp"

namespace granshock {

BinLayout BinSums::layout() const {
  BinLayout l;
  l.n_species = n_species;
  l.nx = nx;
  l.ny = ny;
  l.x0 = x0;
  l.y0 = y0;
  l.bin_size = dx;
  l.blocks = blocks;
  return l;
}

double BinSums::total_samples() const {
  return std::accumulate(samples.begin(), samples.end(), 0.0);
}

double BinSums::pooled(int iy, int ix, int q) const {
  const BinLayout l = layout();
  double s = 0;
  for (int b = 0; b < blocks; ++b) s += sums[static_cast<std::size_t>(l.offset(b, iy, ix, q))];
  return s;
}

BinSums BinSums::block(int b) const {
  if (b < 0 || b >= blocks)
    throw std::invalid_argument("BinSums::block: no block " + std::to_string(b));
  BinSums out = *this;
  out.blocks = 1;
  const std::size_t per_block =
      static_cast<std::size_t>(bins()) * static_cast<std::size_t>(quantities());
  out.sums.assign(sums.begin() + static_cast<long>(per_block * static_cast<std::size_t>(b)),
                  sums.begin() + static_cast<long>(per_block * static_cast<std::size_t>(b + 1)));
  out.samples = {samples[static_cast<std::size_t>(b)]};
  return out;
}

BinSums BinSums::pooled_blocks() const {
  BinSums out = *this;
  out.blocks = 1;
  const std::size_t per_block =
      static_cast<std::size_t>(bins()) * static_cast<std::size_t>(quantities());
  out.sums.assign(per_block, 0.0);
  for (int b = 0; b < blocks; ++b)
    for (std::size_t k = 0; k < per_block; ++k)
      out.sums[k] += sums[per_block * static_cast<std::size_t>(b) + k];
  out.samples = {total_samples()};
  return out;
}

BinSums BinSums::column(int ix) const {
  if (ix < 0 || ix >= nx)
    throw std::invalid_argument("BinSums::column: no column " + std::to_string(ix));
  BinSums out = *this;
  out.nx = 1;
  out.x0 = x0 + ix * dx;
  out.sums.clear();
  const BinLayout l = layout();
  for (int b = 0; b < blocks; ++b)
    for (int iy = 0; iy < ny; ++iy)
      for (int q = 0; q < quantities(); ++q)
        out.sums.push_back(sums[static_cast<std::size_t>(l.offset(b, iy, ix, q))]);
  return out;
}

void BinSums::check_consistent() const {
  if (n_species < 1 || nx < 1 || ny < 1 || blocks < 1)
    throw std::invalid_argument("BinSums: species, bins and blocks must be positive");
  if (!(dx > 0) || !(dy > 0)) throw std::invalid_argument("BinSums: bin sides must be positive");
  const std::size_t expected = static_cast<std::size_t>(blocks) * static_cast<std::size_t>(bins()) *
                               static_cast<std::size_t>(quantities());
  if (sums.size() != expected)
    throw std::invalid_argument("BinSums: " + std::to_string(sums.size()) + " sums, expected " +
                                std::to_string(expected));
  if (samples.size() != static_cast<std::size_t>(blocks))
    throw std::invalid_argument("BinSums: " + std::to_string(samples.size()) +
                                " sample counts for " + std::to_string(blocks) + " blocks");
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
