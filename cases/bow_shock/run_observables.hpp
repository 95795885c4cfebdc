// What the run loop reads off the solver besides the trajectory (docs/design.md, "The
// bow-shock case"): the mixture temperature of the time series and the health check that
// stops a run which has blown up.
#pragma once

#include <stdexcept>
#include <vector>

#include "scene.hpp"
#include "solver.hpp"

namespace granshock {

// A run that blew up numerically (NaN state, exploding energy): exit code 4.
class NumericalFailure : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Mixture granular temperature of the whole domain (docs/fields.md, applied to all
// particles at once): T_a = m_a <|c - u|^2> / Dim about the mass-averaged velocity u,
// T = sum_a xi_a T_a.
double mixture_temperature(const Scene& scene, const std::vector<SpeciesMoments>& moments);

// Kinetic energy of a mean-mass particle at the inflow's mean velocity and fluctuation.
double inflow_energy(const Scene& scene);

// docs/design.md, "Stability": a run either stays correct or stops with a diagnosis. A NaN
// or infinite state, or a mean kinetic energy per particle 100 times that of the inflow
// (energy is only ever supplied by the inflow), means the integration has blown up, almost
// always because dt is too large for the impacts that occur: throws NumericalFailure.
// core/checkpoint_run_checks.cpp refuses to resume a state past the same limit.
void check_health(const Scene& scene, long step, const Diagnostics& d, std::size_t particles);

}  // namespace granshock
