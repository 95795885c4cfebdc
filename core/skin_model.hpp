// The adaptive Verlet skin (docs/design.md, "Adaptive skin"). A thicker skin means longer
// lists, checked every step; a thinner one means more list builds. SkinModel prices both
// in one unit, the distance check of one list candidate, from what the last list
// interval counted, and picks the skin of least cost per particle-step:
//   cost(s) = l(s) + (2 m + build_overhead) / T(s)
//   l(s)  partners per particle, l0 ((range + s) / (range + s0))^dim (partners fill the
//         ball of radius range + s about as uniformly as at s0);
//   m     candidates per particle that a build checks, twice (count, fill): the 3^dim
//         cells about a particle, l0 (3 cell)^dim / (ball of range + s0); host backends
//         now check them once (kernels/neighbours/verlet_list.hpp), so there the model
//         prices a build m checks above its cost; build_overhead was fitted with two
//         visits and is kept, so the skins it picks are those measured (docs/design.md);
//   T(s)  steps between builds, (s/2) / u, with u the largest displacement per step
//         measured over the last interval (ballistic: displacement grows with time);
//   build_overhead  the sort, reorder and offsets of a build per particle, in candidate
//         checks; fitted to the gas benchmark's skin sweep (docs/benchmarks.md).
// Everything it reads is a count or a displacement, never a timing, so a run with an
// adaptive skin is reproducible, across thread counts and processes.
#pragma once

namespace granshock {

// What one list interval measured.
struct SkinSample {
  double skin = 0;                   // the skin its list was built with (m)
  double partners_per_particle = 0;  // list entries / particles at that build
  double drift_per_step = 0;         // largest displacement since the build / steps (m)
};

struct SkinModel {
  int dim = 2;
  double range = 0;                  // the largest diameter (m): partners lie within range + skin
  double cell = 0;                   // the cell size (m), fixed by the largest skin
  double smallest = 0, largest = 0;  // allowed skins (m)
  double build_overhead = 50;        // candidate checks per particle and build

  // Modelled cost per particle-step at skin s, in candidate checks.
  double cost(const SkinSample& at, double s) const;
  // The skin in [smallest, largest] of least cost (cost() is convex in s).
  double best(const SkinSample& at) const;
};

}  // namespace granshock
