#include "analysis/iso_lines.hpp"

#include <cmath>
#include <map>
#include <stdexcept>
#include <utility>

namespace granshock {

namespace {

// Edge keys: the horizontal edge from node (ix, iy) to (ix + 1, iy) is 2 (iy nx + ix), the
// vertical edge from (ix, iy) to (ix, iy + 1) is 2 (iy nx + ix) + 1. Neighbouring cells
// share the key of their common edge, which is what joins their segments.
struct Segment {
  long a, b;  // edge keys of the two ends
};

}  // namespace

std::vector<Polyline> iso_lines(const std::vector<double>& v, const NodeGrid& g, double level) {
  if (v.size() != static_cast<std::size_t>(g.nx) * static_cast<std::size_t>(g.ny))
    throw std::invalid_argument("iso_lines: values do not match the grid");
  auto at = [&](int ix, int iy) { return v[static_cast<std::size_t>(iy) * g.nx + ix]; };
  auto hkey = [&](int ix, int iy) { return 2L * (long(iy) * g.nx + ix); };
  auto vkey = [&](int ix, int iy) { return 2L * (long(iy) * g.nx + ix) + 1; };

  // Crossing point of an edge key (computed once per key, so joined lines share points).
  auto crossing = [&](long key) {
    const long node = key / 2;
    const int ix = static_cast<int>(node % g.nx), iy = static_cast<int>(node / g.nx);
    const bool horizontal = key % 2 == 0;
    const double va = at(ix, iy), vb = horizontal ? at(ix + 1, iy) : at(ix, iy + 1);
    const double t = (level - va) / (vb - va);
    Point2 p{g.x0 + ix * g.dx, g.y0 + iy * g.dy};
    if (horizontal)
      p.x += t * g.dx;
    else
      p.y += t * g.dy;
    return p;
  };

  std::vector<Segment> segments;
  for (int iy = 0; iy + 1 < g.ny; ++iy) {
    for (int ix = 0; ix + 1 < g.nx; ++ix) {
      const double c00 = at(ix, iy), c10 = at(ix + 1, iy), c11 = at(ix + 1, iy + 1),
                   c01 = at(ix, iy + 1);
      if (!std::isfinite(c00) || !std::isfinite(c10) || !std::isfinite(c11) || !std::isfinite(c01))
        continue;
      const int cell = (c00 >= level ? 1 : 0) | (c10 >= level ? 2 : 0) | (c11 >= level ? 4 : 0) |
                       (c01 >= level ? 8 : 0);
      if (cell == 0 || cell == 15) continue;
      const long bottom = hkey(ix, iy), top = hkey(ix, iy + 1), left = vkey(ix, iy),
                 right = vkey(ix + 1, iy);
      const bool centre_above = (c00 + c10 + c11 + c01) / 4 >= level;
      switch (cell) {
        case 1:
        case 14:
          segments.push_back({left, bottom});
          break;
        case 2:
        case 13:
          segments.push_back({bottom, right});
          break;
        case 3:
        case 12:
          segments.push_back({left, right});
          break;
        case 4:
        case 11:
          segments.push_back({right, top});
          break;
        case 6:
        case 9:
          segments.push_back({bottom, top});
          break;
        case 7:
        case 8:
          segments.push_back({left, top});
          break;
        case 5:  // c00 and c11 above
          if (centre_above) {
            segments.push_back({left, top});
            segments.push_back({bottom, right});
          } else {
            segments.push_back({left, bottom});
            segments.push_back({right, top});
          }
          break;
        case 10:  // c10 and c01 above
          if (centre_above) {
            segments.push_back({left, bottom});
            segments.push_back({right, top});
          } else {
            segments.push_back({left, top});
            segments.push_back({bottom, right});
          }
          break;
        default:
          break;
      }
    }
  }

  // Join: every edge key is shared by at most two segments.
  std::map<long, std::vector<std::size_t>> by_key;
  for (std::size_t s = 0; s < segments.size(); ++s) {
    by_key[segments[s].a].push_back(s);
    by_key[segments[s].b].push_back(s);
  }
  std::vector<bool> used(segments.size(), false);
  std::vector<Polyline> lines;
  auto walk = [&](std::size_t first, long start_key) {
    std::vector<long> keys{start_key};
    std::size_t s = first;
    long key = start_key;
    while (true) {
      used[s] = true;
      key = segments[s].a == key ? segments[s].b : segments[s].a;
      keys.push_back(key);
      std::size_t next = segments.size();
      for (std::size_t candidate : by_key[key])
        if (!used[candidate]) next = candidate;
      if (next == segments.size()) break;
      s = next;
    }
    Polyline line;
    for (long k : keys) line.push_back(crossing(k));
    lines.push_back(std::move(line));
  };
  // Open lines first, from an end (a key used by one segment only), then closed loops.
  for (const auto& [key, list] : by_key)
    if (list.size() == 1 && !used[list[0]]) walk(list[0], key);
  for (std::size_t s = 0; s < segments.size(); ++s)
    if (!used[s]) walk(s, segments[s].a);
  return lines;
}

}  // namespace granshock
