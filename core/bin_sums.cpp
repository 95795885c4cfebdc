#include "core/bin_sums.hpp"

#include <cmath>
#include <limits>
#include <numeric>
#include <stdexcept>
#include <string>

namespace granshock {

BinLayout BinSums::layout() const {
  BinLayout l;
  l.n_species = n_species;
  l.nx = nx;
  l.ny = ny;
  l.x0 = x0;
  l.y0 = y0;
  l.dx = dx;
  l.dy = dy;
  l.x_period = x_period;
  l.dim = dim;
  l.depth = depth;
  l.z0 = z0;
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

BinSums BinSums::columns(int ix_begin, int ix_end) const {
  if (ix_begin < 0 || ix_end > nx || ix_begin >= ix_end)
    throw std::invalid_argument("BinSums::columns: no columns [" + std::to_string(ix_begin) + ", " +
                                std::to_string(ix_end) + ") of " + std::to_string(nx));
  BinSums out = *this;
  out.nx = 1;
  out.x0 = x0 + ix_begin * dx;
  out.dx = (ix_end - ix_begin) * dx;
  out.x_period = 0;
  const BinLayout l = layout(), o = out.layout();
  out.sums.assign(static_cast<std::size_t>(blocks) * static_cast<std::size_t>(ny) *
                      static_cast<std::size_t>(quantities()),
                  0.0);
  for (int b = 0; b < blocks; ++b)
    for (int iy = 0; iy < ny; ++iy)
      for (int ix = ix_begin; ix < ix_end; ++ix)
        for (int q = 0; q < quantities(); ++q)
          out.sums[static_cast<std::size_t>(o.offset(b, iy, 0, q))] +=
              sums[static_cast<std::size_t>(l.offset(b, iy, ix, q))];
  return out;
}

BinSums BinSums::merged_rows(int k, int row_end) const {
  row_end = std::min(row_end, ny);
  const int groups = k >= 1 ? row_end / k : 0;
  if (groups < 1)
    throw std::invalid_argument("BinSums::merged_rows: no whole group of " + std::to_string(k) +
                                " rows below row " + std::to_string(row_end));
  const int first = row_end - groups * k;
  BinSums out = *this;
  out.ny = groups;
  out.y0 = y0 + first * dy;
  out.dy = k * dy;
  const BinLayout l = layout(), o = out.layout();
  out.sums.assign(static_cast<std::size_t>(blocks) * static_cast<std::size_t>(groups) *
                      static_cast<std::size_t>(nx) * static_cast<std::size_t>(quantities()),
                  0.0);
  for (int b = 0; b < blocks; ++b)
    for (int iy = first; iy < row_end; ++iy)
      for (int ix = 0; ix < nx; ++ix)
        for (int q = 0; q < quantities(); ++q)
          out.sums[static_cast<std::size_t>(o.offset(b, (iy - first) / k, ix, q))] +=
              sums[static_cast<std::size_t>(l.offset(b, iy, ix, q))];
  return out;
}

BinSums BinSums::block_range(int b_begin, int b_end) const {
  if (b_begin < 0 || b_end > blocks || b_begin >= b_end)
    throw std::invalid_argument("BinSums::block_range: no blocks [" + std::to_string(b_begin) +
                                ", " + std::to_string(b_end) + ")");
  BinSums out = *this;
  out.blocks = b_end - b_begin;
  const std::size_t per_block =
      static_cast<std::size_t>(bins()) * static_cast<std::size_t>(quantities());
  out.sums.assign(sums.begin() + static_cast<long>(per_block * static_cast<std::size_t>(b_begin)),
                  sums.begin() + static_cast<long>(per_block * static_cast<std::size_t>(b_end)));
  out.samples.assign(samples.begin() + b_begin, samples.begin() + b_end);
  return out;
}

BinSums BinSums::weighted_blocks(const std::vector<int>& weights) const {
  if (weights.size() != static_cast<std::size_t>(blocks))
    throw std::invalid_argument("BinSums::weighted_blocks: " + std::to_string(weights.size()) +
                                " weights for " + std::to_string(blocks) + " blocks");
  BinSums out = *this;
  out.blocks = 1;
  const std::size_t per_block =
      static_cast<std::size_t>(bins()) * static_cast<std::size_t>(quantities());
  out.sums.assign(per_block, 0.0);
  double total = 0;
  for (std::size_t b = 0; b < weights.size(); ++b) {
    if (weights[b] == 0) continue;
    const double w = weights[b];
    for (std::size_t k = 0; k < per_block; ++k) out.sums[k] += w * sums[per_block * b + k];
    total += w * samples[b];
  }
  out.samples = {total};
  return out;
}

void BinSums::check_consistent() const {
  if (n_species < 1 || nx < 1 || ny < 1 || blocks < 1)
    throw std::invalid_argument("BinSums: species, bins and blocks must be positive");
  if (!(dx > 0) || !(dy > 0)) throw std::invalid_argument("BinSums: bin sides must be positive");
  if (!(y_end > y0)) throw std::invalid_argument("BinSums: the domain ends before the first row");
  const std::size_t expected = static_cast<std::size_t>(blocks) * static_cast<std::size_t>(bins()) *
                               static_cast<std::size_t>(quantities());
  if (sums.size() != expected)
    throw std::invalid_argument("BinSums: " + std::to_string(sums.size()) + " sums, expected " +
                                std::to_string(expected));
  if (samples.size() != static_cast<std::size_t>(blocks))
    throw std::invalid_argument("BinSums: " + std::to_string(samples.size()) +
                                " sample counts for " + std::to_string(blocks) + " blocks");
}

}  // namespace granshock
