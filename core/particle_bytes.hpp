// Particles as bytes, for gathering them from several processes (docs/parallel.md): the
// per-particle vectors of a SolverState or HostParticles, each as its length and its raw
// values, so that the parts of every rank, concatenated in rank order, read back as one
// set in that order. Also the selection of some particles of a state (a rank's own).
#pragma once

#include <vector>

#include "core/host_particles.hpp"
#include "core/solver_state.hpp"

namespace granshock {

std::vector<char> pack_particles(const SolverState& s);
std::vector<char> pack_particles(const HostParticles& p);
// Appends every part in `parts` (one or more packs, back to back) to `into`.
void append_particles(const std::vector<char>& parts, SolverState& into);
void append_particles(const std::vector<char>& parts, HostParticles& into);

// The particles `rows` of s (in that order) with s's scalars; neighbour lists are left
// empty (they index the whole state). Also of host particles (a gathered snapshot).
SolverState select_particles(const SolverState& s, const std::vector<int>& rows);
HostParticles select_particles(const HostParticles& p, const std::vector<int>& rows);

}  // namespace granshock
