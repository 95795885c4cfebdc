// A homogeneous granular gas in a periodic box: the initial state of the benchmarks and
// of several physics tests. Particles sit on a jittered square lattice (2-D) or cubic
// lattice (setup.dim = 3), so they never overlap, with Gaussian velocities of zero total
// momentum.
#pragma once

#include <cstdint>

#include "core/host_particles.hpp"
#include "core/solver_setup.hpp"

namespace granshock {

// Where the particles start. On a jittered lattice no pair is closer than the spacing less
// the jitter's room: at an area fraction of 0.1 the centres are 2.8 d apart, so a list of
// reach 1.3 d starts nearly empty and stays so for thousands of steps. Random sequential
// addition (uniform positions, each refused while it overlaps an earlier particle) gives
// the pair distribution of a dilute random gas instead, with its list partners, as a
// gas that has moved for a while has (docs/benchmarks.md, "The paper case against a
// random gas"). It jams near 0.55 in 2-D and 0.38 in 3-D.
enum class GasPlacement { lattice, random };

struct GasSpec {
  int particles = 1000;        // rounded to a full lattice (the box is the lattice's)
  double area_fraction = 0.1;  // the solid fraction: of area in 2-D, of volume in 3-D
  double sigma_m_per_s = 1.0;  // velocity standard deviation per component
  std::uint64_t seed = 1;
  GasPlacement placement = GasPlacement::lattice;
};

// The square (2-D) or cubic (3-D) periodic box that holds spec.particles at
// spec.area_fraction for the setup's species (equal number fractions). Writes setup.box.
void size_periodic_box(SolverSetup& setup, const GasSpec& spec);

// Fills setup.box (which must come from size_periodic_box) with the gas, placed as
// spec.placement says; species alternate so number fractions are equal. Throws if the
// lattice is too dense for non-overlapping placement (area fraction above pi/4 for equal
// diameters, volume fraction above pi/6 in 3-D), or random addition finds no room.
HostParticles make_homogeneous_gas(const SolverSetup& setup, const GasSpec& spec);

// The paper's binary mixture (steel and aluminium, d = 1 mm, e per pair, no friction),
// frictionless and without obstacle, with a time step to be set by the caller.
SolverSetup paper_mixture(double restitution);

}  // namespace granshock
