// What the run loop reads off the solver besides the trajectory (docs/design.md, "The
// bow-shock case"): the mixture temperature of the time series and the health check that
// stops a run which has blown up.
#pragma once

#include <stdexcept>
#include <string>
#include <vector>

#include "core/scene.hpp"
#include "core/solver.hpp"

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
// always because dt is too large for the impacts that occur: throws NumericalFailure. So
// does a particle whose centre lies inside the obstacle (pushed through its surface).
// core/checkpoint_run_checks.cpp refuses to resume a state past the same limit.
void check_health(const Scene& scene, long step, const Diagnostics& d, std::size_t particles);

// docs/stability.md: particles that leave through the inlet, against the inflow. A
// supersonic inflow loses few that way (0.2 % of those inserted at Ma_inf = 2.64 in the
// paper's cases, none at 5.9); past kInletBackflowWarning of at least 100 inserted the flow
// upstream is no longer the inflow (a time step past the stable limit run with --force, a
// choked channel, a subsonic inflow), and the run warns. Returns the warning, or "".
inline constexpr double kInletBackflowWarning = 0.05;
std::string inlet_backflow_warning(long deleted_inlet, long inserted, double time);

// docs/stability.md: energy enters only with the inflow, and no collision creates it
// (e <= 1), so a mean kinetic energy per particle past kEnergyWarning times the inflow's
// means the integration creates energy (a time step past the stable limit run with --force)
// long before check_health's 100 times stops the run. Returns the warning, or "".
inline constexpr double kEnergyWarning = 2.0;
std::string energy_warning(const Scene& scene, double kinetic_energy, std::size_t particles,
                           double time);

}  // namespace granshock
