// What a case costs, in particle-steps, and the time that takes (docs/study.md, "Cost and
// ETA"): the expected particles (phi_inf times the free area over the mean particle area)
// times the steps, at a rate measured on the cases run so far.
#pragma once

#include <string>

#include "core/scene.hpp"

namespace granshock {

// phi_inf x (domain area - obstacle area) / mean particle area: the particles of the
// upstream state filling the domain. A dense region in front of the obstacle adds to it and
// a wake takes from it; the default scene holds about this many (4,028 particles at the end
// of its 0.3 s: docs/quickstart.md).
double expected_particles(const Scene& scene);

// expected_particles x the steps left after `steps_done`.
double expected_particle_steps(const Scene& scene, long steps_done = 0);

// The whole-run rate assumed before a study has measured one: expected particle-steps per
// wall second on 2 cores, the setup, outputs and field analysis of a run included; a little
// below the default scene's measured rate, for denser scenes and a machine shared with
// other work (the measurement: docs/study.md, "Cost and ETA").
inline constexpr double kReferenceRate = 1.5e8;

// Wall seconds as "H:MM:SS" (hours past 99 as "D d HH:MM:SS").
std::string duration_text(double seconds);

}  // namespace granshock
