#include "cases/bow_shock/run_checks.hpp"

#include <fmt/format.h>

#include <cmath>

#include "analysis/field_sampling_check.hpp"
#include "cases/bow_shock/run_memory.hpp"
#include "cases/bow_shock/run_summary.hpp"
#include "core/user_error.hpp"

namespace granshock {

namespace {

void refuse_count(const char* key, double count, const char* what, double limit) {
  throw UserError(
      fmt::format("scene key '{}': the run would {} {:.3g} times, more than the "
                  "{:.3g} granshock allows; choose a larger value",
                  key, what, count, limit));
}

// summary.json measures every pair's restitution at the run's dt (run_summary.hpp); a pair
// whose collision cannot be measured there once ran the whole simulation and then ended
// without a summary. The same collisions, before anything runs.
void check_effective_restitution(const Scene& s) {
  try {
    effective_restitution_table(s);
  } catch (const UserError& e) {
    throw UserError(fmt::format(
        "scene keys 'contact.restitution' / 'time.dt': the effective restitution of the pairs "
        "at this step cannot be measured, as summary.json must: {}",
        e.what()));
  }
}

}  // namespace

TimeStepAssessment assess_time_step(const Scene& s) {
  return assess_time_step(s.setup, s.fastest_impact_speed());
}

OverlapAssessment assess_overlap(const Scene& s) {
  return assess_overlap(s.setup, s.fastest_impact_speed());
}

double expected_insertions(const Scene& s) {
  const double width = s.setup.box.length(0);
  const double streamwise = s.setup.box.length(1) + s.inflow.speed_m_per_s * s.run.duration_s;
  return s.inflow_number_per_area() * width * streamwise;
}

std::vector<std::string> check_scene_before_run(const Scene& s, bool force, int processes,
                                                const std::optional<CertifiedStep>& certified) {
  std::vector<std::string> warnings;
  const double steps = s.run.duration_s / s.setup.dt;
  if (steps < 1)
    throw UserError(
        fmt::format("scene keys 'time.duration' / 'time.dt' = {:g} s / {:g} s: shorter than one "
                    "time step",
                    s.run.duration_s, s.setup.dt));
  if (!(steps <= RunLimits::max_steps))
    throw UserError(fmt::format(
        "scene keys 'time.duration' / 'time.dt' = {:g} s / {:g} s: {:.3g} steps, more than the "
        "{:.3g} a run may take",
        s.run.duration_s, s.setup.dt, steps, RunLimits::max_steps));
  if (s.run.duration_s / s.run.snapshot_interval_s > RunLimits::max_snapshots)
    refuse_count("output.snapshot_interval", s.run.duration_s / s.run.snapshot_interval_s,
                 "write a particle snapshot", RunLimits::max_snapshots);
  if (s.run.duration_s / s.run.series_interval_s > RunLimits::max_series_rows)
    refuse_count("output.series_interval", s.run.duration_s / s.run.series_interval_s,
                 "write a time-series row", RunLimits::max_series_rows);
  if (s.run.duration_s / s.run.checkpoint_interval_s > RunLimits::max_checkpoints)
    refuse_count("output.checkpoint_interval", s.run.duration_s / s.run.checkpoint_interval_s,
                 "write a checkpoint", RunLimits::max_checkpoints);

  if (!(s.capacity_unbounded() <= RunLimits::max_particles))
    throw UserError(fmt::format(
        "scene keys 'domain.width' x 'domain.length' at 'inflow.area_fraction' = {:g}: about "
        "{:.3g} particles, more than the {:.3g} one process holds",
        s.inflow.area_fraction, s.capacity_unbounded(), RunLimits::max_particles));
  const double range = s.setup.max_diameter() + s.setup.skin();
  const double cells = (s.setup.box.length(0) / range) * (s.setup.box.length(1) / range);
  if (!(cells <= RunLimits::max_cells))
    throw UserError(fmt::format(
        "scene keys 'domain.width' x 'domain.length' = {:g} m x {:g} m: {:.3g} neighbour-search "
        "cells of {:g} m, more than the {:.3g} granshock allows",
        s.setup.box.length(0), s.setup.box.length(1), cells, range, RunLimits::max_cells));
  const double period_steps = s.inflow.strip_m / s.inflow.speed_m_per_s / s.setup.dt;
  if (!(period_steps <= RunLimits::max_steps))
    throw UserError(fmt::format(
        "scene key 'inflow.velocity' = {:g} m/s: the inflow would cross its strip once in "
        "{:.3g} steps, more than the {:.3g} a run may take",
        s.inflow.speed_m_per_s, period_steps, RunLimits::max_steps));
  if (expected_insertions(s) > RunLimits::max_particle_ids)
    throw UserError(fmt::format(
        "scene key 'time.duration' = {:g} s: the inflow would insert about {:.3g} particles, "
        "more than the {:.3g} distinct particle ids of a run; shorten the run",
        s.run.duration_s, expected_insertions(s), RunLimits::max_particle_ids));

  using Verdict = TimeStepAssessment::Verdict;
  const TimeStepAssessment guard = assess_time_step(s);
  if (guard.verdict == Verdict::refuse && !force) throw UserError(guard.message);
  if (guard.verdict == Verdict::warn && certified && s.setup.dt <= certified->dt)
    // t_c/10 is the guard's rule of thumb; the table measured this dt/t_c's error
    // (docs/accuracy.md): the measurement is the better knowledge, and is named.
    warnings.push_back(fmt::format(
        "time step dt = {:.4g} s resolves the {} contact (t_c = {:.4g} s at {:.3g} m/s) in "
        "{:.1f} steps, past t_c/10, the time-step guard's general limit for accuracy; {}",
        s.setup.dt, guard.stiffest_pair, guard.t_c, guard.impact_speed, guard.t_c / s.setup.dt,
        certified->why));
  else if (guard.verdict != Verdict::ok)
    warnings.push_back(guard.message);
  const OverlapAssessment overlap = assess_overlap(s);
  if (overlap.verdict == Verdict::refuse && !force) throw UserError(overlap.message);
  if (overlap.verdict != Verdict::ok) warnings.push_back(overlap.message);
  validate_field_sampling(s);  // before any output: no hours spent on empty fields
  // Where the available memory cannot be read (no /proc), nothing is refused; an allocation
  // that fails then ends the run as "not enough memory" (apps/granshock/main.cpp).
  if (const auto available = available_memory_bytes())
    check_run_memory(s, estimate_run_memory(s, processes), *available);
  check_effective_restitution(s);
  return warnings;
}

}  // namespace granshock
