#include "cases/bow_shock/run_observables.hpp"

#include <fmt/format.h>

#include <array>

#include "cases/bow_shock/run_checks.hpp"

namespace granshock {

double mixture_temperature(const Scene& s, const std::vector<SpeciesMoments>& mom) {
  const int dim = s.setup.dim;
  double mass = 0, count = 0;
  std::array<double, 3> momentum{0, 0, 0};
  for (std::size_t a = 0; a < mom.size(); ++a) {
    const double m = s.setup.species[a].mass_kg();
    mass += m * mom[a].count;
    count += mom[a].count;
    for (int c = 0; c < dim; ++c) momentum[c] += m * mom[a].velocity_sum[c];
  }
  if (count == 0) return 0;
  double t = 0;
  for (std::size_t a = 0; a < mom.size(); ++a) {
    if (mom[a].count == 0) continue;
    const double m = s.setup.species[a].mass_kg();
    double fluct = mom[a].speed_squared_sum;  // sum |c - u|^2 = sum c^2 - 2 u.sum c + N u^2
    for (int c = 0; c < dim; ++c) {
      const double u = momentum[c] / mass;
      fluct += -2 * u * mom[a].velocity_sum[c] + mom[a].count * u * u;
    }
    t += (mom[a].count / count) * m * fluct / (dim * mom[a].count);
  }
  return t;
}

double inflow_energy(const Scene& s) {
  return 0.5 * s.mean_mass() *
         (s.inflow.speed_m_per_s * s.inflow.speed_m_per_s +
          s.setup.dim * s.inflow.sigma * s.inflow.sigma);
}

void check_health(const Scene& s, long step, const Diagnostics& d, std::size_t particles) {
  const double per_particle_inflow = inflow_energy(s);
  const double per_particle = particles > 0 ? d.kinetic_energy / double(particles) : 0.0;
  if (d.inside_obstacle == 0 && d.non_finite == 0 && per_particle <= 100 * per_particle_inflow)
    return;
  const TimeStepAssessment guard = assess_time_step(s);
  if (d.inside_obstacle > 0)
    throw NumericalFailure(fmt::format(
        "{} particles were pushed through the obstacle's surface by step {} (t = {:.4g} s): "
        "their centres lie inside it; dt = {:.3g} s is {:.2f} t_c (stable limit {:.3g} s); "
        "reduce time.dt",
        d.inside_obstacle, step, step * s.setup.dt, s.setup.dt, guard.dt_over_tc(),
        guard.dt_stable));
  throw NumericalFailure(
      fmt::format("the integration blew up at step {} (t = {:.4g} s): {} particles with a "
                  "non-finite state, mean kinetic energy {:.3g} times the inflow's; dt = {:.3g} "
                  "s is {:.2f} t_c (stable limit {:.3g} s); reduce time.dt",
                  step, step * s.setup.dt, d.non_finite, per_particle / per_particle_inflow,
                  s.setup.dt, guard.dt_over_tc(), guard.dt_stable));
}

std::string inlet_backflow_warning(long deleted_inlet, long inserted, double time) {
  if (inserted < 100 || double(deleted_inlet) <= kInletBackflowWarning * double(inserted))
    return {};
  return fmt::format(
      "{} of {} inserted particles ({:.1f}%) left through the inlet, against the inflow, by "
      "t = {:.4g} s: the flow upstream is no longer the inflow (a time step past the stable "
      "limit, a choked channel or a subsonic inflow; summary.json: inlet_backflow_fraction)",
      deleted_inlet, inserted, 100.0 * double(deleted_inlet) / double(inserted), time);
}

std::string energy_warning(const Scene& s, double kinetic_energy, std::size_t particles,
                           double time) {
  if (particles == 0) return {};
  const double ratio = kinetic_energy / double(particles) / inflow_energy(s);
  if (!(ratio > kEnergyWarning)) return {};
  const TimeStepAssessment guard = assess_time_step(s);
  return fmt::format(
      "the mean kinetic energy per particle is {:.3g} times the inflow's at t = {:.4g} s: the "
      "integration creates energy (dt = {:.3g} s is {:.2f} t_c, stable limit {:.3g} s)",
      ratio, time, s.setup.dt, guard.dt_over_tc(), guard.dt_stable);
}

}  // namespace granshock
