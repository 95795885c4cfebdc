#include "core/snapshot_part.hpp"

#include <stdexcept>

#include "core/particle_bytes.hpp"

namespace granshock {

std::vector<FileRows> file_rows_by_layer(const std::vector<long>& counts, int layers, int rank) {
  if (layers <= 0 || counts.size() % std::size_t(layers) != 0)
    throw std::invalid_argument("file_rows_by_layer: counts is not ranks x layers");
  const int ranks = int(counts.size() / std::size_t(layers));
  if (rank < 0 || rank >= ranks) throw std::invalid_argument("file_rows_by_layer: no such rank");
  const auto count = [&](int r, int layer) { return counts[std::size_t(r) * layers + layer]; };
  std::vector<FileRows> rows;
  long before_layer = 0;  // every rank's particles in the layers below
  for (int layer = 0; layer < layers; ++layer) {
    long first = before_layer;
    for (int r = 0; r < rank; ++r) first += count(r, layer);
    const long mine = count(rank, layer);
    if (mine > 0) {
      if (!rows.empty() && rows.back().first + rows.back().count == first)
        rows.back().count += mine;
      else
        rows.push_back({first, mine});
    }
    for (int r = 0; r < ranks; ++r) before_layer += count(r, layer);
  }
  return rows;
}

std::vector<int> row_sources(const std::vector<FileRows>& rows, long total, std::size_t parts) {
  std::vector<int> source(std::size_t(total), -1);
  int k = 0;
  for (const FileRows& r : rows)
    for (long row = r.first; row < r.first + r.count; ++row) {
      if (row < 0 || row >= total || source[std::size_t(row)] >= 0 || k >= int(parts))
        throw std::logic_error("the parts' rows do not fill the frame once each");
      source[std::size_t(row)] = k++;
    }
  if (k != total || std::size_t(k) != parts)
    throw std::logic_error("the parts' rows do not fill the frame once each");
  return source;
}

HostParticles gather_snapshot(const Communicator& comm, const SnapshotPart& part) {
  if (comm.size() == 1) return part.particles;
  HostParticles parts;  // rank by rank, each in the order of its rows
  append_particles(comm.gather(pack_particles(part.particles), 0), parts);
  const std::vector<FileRows> rows = gather_to_root(comm, part.rows);
  if (!comm.is_root()) return {};
  return select_particles(parts, row_sources(rows, part.total, parts.size()));
}

}  // namespace granshock
