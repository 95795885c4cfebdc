#include "cases/bow_shock/run_summary.hpp"

#include <Kokkos_Core.hpp>
#include <utility>

#include "cases/build_info/build_description.hpp"
#include "cases/collision/head_on_collision.hpp"
#include "core/cpu_model.hpp"
#include "kernels/models/restitution_calibration.hpp"
#include "kernels/models/time_step_guard.hpp"

namespace granshock {

nlohmann::json inflow_summary(const InflowController& inflow) {
  const double requested = inflow.requested();
  return {{"requested", requested},
          {"inserted", inflow.inserted()},
          {"backlog", inflow.backlog()},
          {"lost", inflow.shortfall() - inflow.backlog()},
          {"achieved_fraction", requested > 0 ? double(inflow.inserted()) / requested : 1.0},
          {"falls_short", inflow.falls_short()}};
}

nlohmann::json effective_restitution_table(const Scene& s) {
  nlohmann::json out = nlohmann::json::object();
  const int n = int(s.setup.species.size());
  for (int a = 0; a < n; ++a) {
    for (int b = s.setup.obstacle ? -1 : a; b < n; ++b) {
      if (b >= 0 && b < a) continue;
      nlohmann::json entry;
      for (const auto& [label, speed] :
           {std::pair<const char*, double>{"at_inflow_speed", s.inflow.speed_m_per_s},
            {"at_fastest_impact", s.fastest_impact_speed()}}) {
        const CollisionResult r =
            collide_species(s.setup, a, b, speed, s.setup.dt, true, 1.0, {}, Backend::serial);
        // One impact is one phase of the first contact step on the time grid; a gas meets
        // every phase, and the discrete mode is calibrated on their average (the reduced
        // integrator of restitution_calibration.hpp, in double; docs/output_format.md).
        const PairProperties p = b < 0 ? s.setup.obstacle_pair(a) : s.setup.pair(a, b);
        const double averaged = phase_averaged_restitution(
            s.setup.contacts.model, p, s.setup.contacts.options, s.setup.dt, speed);
        entry[label] = {{"speed", speed},
                        {"e_eff", r.e_eff},
                        {"e_eff_phase_averaged", averaged},
                        {"dt_over_tc", r.dt / r.t_c}};
        entry["e_in"] = r.e_in;
        out[r.pair] = entry;
      }
    }
  }
  return out;
}

nlohmann::json restitution_calibration_summary(const Scene& s) {
  if (s.setup.contacts.restitution_mode == RestitutionMode::continuous) return nullptr;
  SolverSetup setup = s.setup;
  const RestitutionCalibration c = apply_restitution_mode(setup);
  nlohmann::json pairs = nlohmann::json::object();
  for (const PairCalibration& p : c.pairs) pairs[p.pair] = to_json(p, c.speed);
  return {{"mode", to_string(s.setup.contacts.restitution_mode)},
          {"speed", c.speed},
          {"dt", c.dt},
          {"phases", kCalibrationPhases},
          {"pairs", pairs}};
}

nlohmann::json calibration_summary(const InletCalibration& c) {
  nlohmann::json iterations = nlohmann::json::array();
  for (const InletMach& m : c.iterations)
    iterations.push_back({{"sigma", m.sigma},
                          {"mach", m.mach},
                          {"mach_err", m.mach_err},
                          {"mach_mixture_mean", m.mach_mixture_mean},
                          {"mach_paper_sum", m.mach_paper_sum},
                          {"phi", m.phi},
                          {"simulated_seconds", m.simulated_s}});
  return {{"mach_at", to_string(MachReference::inlet_bins)},
          {"target", c.target},
          {"sigma_inserted", c.sigma_inserted},
          {"sigma", c.sigma},
          {"converged", c.converged},
          {"tolerance", c.tolerance},
          {"iterations", iterations}};
}

nlohmann::json run_summary(const Scene& s, const Solver& solver, const InflowController& inflow,
                           const InletCalibration* calibration, bool completed,
                           const RunTimes& times) {
  const long steps = solver.steps_done();
  const RemovalCounts removed = solver.removed();
  const TimeStepAssessment guard = assess_time_step(s.setup, s.fastest_impact_speed());
  nlohmann::json j;
  j["scene"] = s.name;
  j["dimension"] = s.setup.dim;  // 2: quasi-2-D; 3: spheres in a layer (scene.dim)
  j["completed"] = completed;
  j["steps"] = steps;
  j["simulated_time"] = steps * s.setup.dt;
  j["wall_seconds"] = times.wall_seconds;
  // What the run cost on a shared machine (wall time also counts others' turns); null
  // when an earlier leg did not record it.
  j["cpu_seconds"] = times.cpu_seconds >= 0 ? nlohmann::json(times.cpu_seconds) : nlohmann::json();
  j["particles_final"] = solver.global_size();
  j["inserted"] = inflow.inserted();
  j["inflow"] = inflow_summary(inflow);
  j["deleted"] = removed.total();
  j["deleted_outlet"] = removed.high[1];
  j["deleted_inlet"] = removed.low[1];
  j["inlet_backflow_fraction"] =
      inflow.inserted() > 0 ? double(removed.low[1]) / double(inflow.inserted()) : 0.0;
  j["dt"] = s.setup.dt;
  j["t_c"] = guard.t_c;
  j["dt_over_tc"] = guard.dt_over_tc();
  j["impact_speed_for_t_c"] = guard.impact_speed;
  j["stiffest_pair"] = guard.stiffest_pair;
  j["contact_model"] = to_string(s.setup.contacts.model);
  j["inflow_sigma"] = s.inflow.sigma;
  j["inflow_mach_at"] = to_string(s.inflow.mach_at);
  j["inflow_calibration"] = calibration ? calibration_summary(*calibration) : nlohmann::json();
  j["ma_inf_target"] =
      s.inflow.target_mach ? nlohmann::json(*s.inflow.target_mach) : nlohmann::json();
  j["variant"] = solver.variant();
  j["backend"] = Kokkos::DefaultExecutionSpace::name();
  j["threads"] = Kokkos::DefaultExecutionSpace().concurrency();
  j["cpu_model"] = cpu_model_name();  // beside the speeds (core/cpu_model.hpp)
  j["list_builds"] = solver.list_builds();
  j["skin_m"] = solver.skin();  // the last list's: adaptive skins change (core/skin_model.hpp)
  // The rate of this leg only (earlier legs of a resumed run are in wall_seconds).
  j["particle_steps_per_second"] =
      times.leg_seconds > 0 ? times.particle_steps / times.leg_seconds : 0.0;
  j["build"] = build_description();  // this leg's program (run.h5: the first leg's)
  j["effective_restitution_at_dt"] = effective_restitution_table(s);
  j["restitution_calibration"] = restitution_calibration_summary(s);
  return j;
}

}  // namespace granshock
