// The checks that need the run loop: its schedule, counters and physical scales.
#include <algorithm>

#include "core/checkpoint_check_support.hpp"

namespace granshock {

using namespace checks;

namespace {

void check_counters(const SolverState& s, const CheckpointExtras& e, const RunFit& fit) {
  if (s.step > fit.total_steps)
    fail(fmt::format("/state@step = {} is past the scene's last step ({})", s.step,
                     fit.total_steps));
  long removed = 0;
  for (int d = 0; d < 3; ++d)
    removed += s.removed_low[std::size_t(d)] + s.removed_high[std::size_t(d)];
  if (e.inserted - removed != long(s.size()))
    fail(
        fmt::format("/run@inserted = {} less {} deleted (/state@removed_low/high) leaves {} "
                    "particles, but /state/id holds {}",
                    e.inserted, removed, e.inserted - removed, s.size()));
  if (e.deleted_outlet != s.removed_high[1] || e.deleted_inlet != s.removed_low[1])
    fail(
        fmt::format("/run@deleted_outlet/inlet = {}/{} disagree with /state@removed_high[1]/"
                    "removed_low[1] = {}/{}",
                    e.deleted_outlet, e.deleted_inlet, s.removed_high[1], s.removed_low[1]));
  // Ids are handed out consecutively from 0, one per inserted particle.
  if (long(s.next_id) != e.inserted)
    fail(fmt::format("/state@next_id = {}, but /run@inserted = {} particles got ids from 0",
                     s.next_id, e.inserted));
  if (e.rng_counter != fit.insertion_events)
    fail(fmt::format("/run@rng_counter = {}, but by step {} the inflow has drawn {} batches",
                     e.rng_counter, s.step, fit.insertion_events));
  if (e.insertion_carry > fit.max_carry * (1 + 1e-9) + 1e-9)
    fail(
        fmt::format("/run@insertion_carry = {} is more than the {} particles the batches since "
                    "the prefill asked for",
                    e.insertion_carry, fit.max_carry));
  // One build at the start, at most one per step and one per insertion batch.
  const long max_builds = s.step + long(fit.insertion_events) + 2;
  if (s.list_builds < 1 || s.list_builds > max_builds)
    fail(fmt::format("/state@list_builds = {} is not in [1, {}] (step + batches + 2)",
                     s.list_builds, max_builds));
}

// The run's health check (run_command.cpp) stops a run whose mean kinetic energy per
// particle passes 100 times the inflow's: a stored state past that has blown up. The
// same budget bounds one particle, and the force and torque of its next half step.
void check_energy(const SolverState& s, const RunFit& fit) {
  if (s.size() == 0 || !(fit.inflow_energy > 0)) return;
  const std::size_t dim = std::size_t(s.dim);
  const double budget = 100 * double(s.size()) * fit.inflow_energy;
  double kinetic = 0, rotational = 0;
  for (std::size_t i = 0; i < s.size(); ++i) {
    const std::size_t a = std::size_t(s.species[i]);
    if (a >= fit.mass.size()) fail(fmt::format("{} is not a species", at("/state/species", i)));
    double v2 = 0, f2 = 0;
    for (std::size_t d = 0; d < dim; ++d) {
      v2 += s.velocity[i * dim + d] * s.velocity[i * dim + d];
      f2 += s.force[i * dim + d] * s.force[i * dim + d];
    }
    kinetic += 0.5 * fit.mass[a] * v2;
    // A force that changes the speed by more than twice the budget's speed in half a step.
    const double v_max = std::sqrt(2 * budget / fit.mass[a]);
    if (std::sqrt(f2) * 0.5 * fit.dt / fit.mass[a] > 2 * v_max)
      fail(
          fmt::format("{} = {} N would change the particle's speed by more than {} m/s in half "
                      "a step: the state has blown up",
                      at("/state/force", i * dim), std::sqrt(f2), 2 * v_max));
    if (s.angular_velocity.empty()) continue;
    const std::size_t spins = std::size_t(spin_components(s.dim));
    double w2 = 0, t2 = 0;
    for (std::size_t c = 0; c < spins; ++c) {
      w2 += s.angular_velocity[i * spins + c] * s.angular_velocity[i * spins + c];
      t2 += s.torque[i * spins + c] * s.torque[i * spins + c];
    }
    rotational += 0.5 * fit.inertia[a] * w2;
    const double w_max = std::sqrt(2 * budget / fit.inertia[a]);
    if (std::sqrt(t2) * 0.5 * fit.dt / fit.inertia[a] > 2 * w_max)
      fail(
          fmt::format("{} = {} N m would change the spin by more than {} rad/s in half a step: "
                      "the state has blown up",
                      at("/state/torque", i * spins), std::sqrt(t2), 2 * w_max));
  }
  for (const auto& [name, energy] : {std::pair<const char*, double>{"/state/velocity", kinetic},
                                     {"/state/angular_velocity", rotational}})
    if (!(energy <= budget))
      fail(
          fmt::format("{}: the mean energy per particle is {:.3g} times the inflow's kinetic "
                      "energy, past the run's health limit of 100: the state has blown up",
                      name, energy / double(s.size()) / fit.inflow_energy));
}

}  // namespace

void check_run(const SolverState& s, const CheckpointExtras& e, const RunFit& fit) {
  check_counters(s, e, fit);
  check_energy(s, fit);
  check_field_sums(e, fit);
}

}  // namespace granshock
