// The touching pairs of a 2-D configuration by an O(N^2) search with minimum-image
// distances on periodic axes: the independent answer the solver's cell and Verlet lists
// are checked against (test_neighbour_search.cpp, test_adaptive_skin.cpp).
#pragma once

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include "core/host_particles.hpp"
#include "core/solver_setup.hpp"

namespace granshock::test {

// Pairs (smaller id, larger id), sorted, as Solver::contact_pairs() returns them.
inline std::vector<std::pair<int, int>> brute_force_contacts(const SolverSetup& s,
                                                             const HostParticles& p) {
  std::vector<std::pair<int, int>> pairs;
  for (std::size_t i = 0; i < p.size(); ++i) {
    for (std::size_t j = i + 1; j < p.size(); ++j) {
      double r2 = 0;
      for (int d = 0; d < 2; ++d) {
        double dx = p.position[i][d] - p.position[j][d];
        if (s.box.periodic[d]) dx -= s.box.length(d) * std::round(dx / s.box.length(d));
        r2 += dx * dx;
      }
      const double reach = s.species[p.species[i]].radius_m() + s.species[p.species[j]].radius_m();
      if (r2 < reach * reach)
        pairs.emplace_back(std::min(p.id[i], p.id[j]), std::max(p.id[i], p.id[j]));
    }
  }
  std::sort(pairs.begin(), pairs.end());
  return pairs;
}

}  // namespace granshock::test
