#include "bin_sums.hpp"

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

}  // namespace granshock
