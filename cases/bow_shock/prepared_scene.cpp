#include "cases/bow_shock/prepared_scene.hpp"

#include <fmt/format.h>

#include "cases/bow_shock/interrupt.hpp"
#include "cases/bow_shock/run_checks.hpp"

namespace granshock {

namespace {

void say(const PrepareOptions& o, const std::string& line) {
  if (o.say) o.say(line);
}

// contact.restitution_mode = "discrete" (docs/contact_model.md, "Restitution at the chosen
// time step"): a pure function of the scene, so a resumed run finds the same damping.
void calibrate_restitution(PreparedScene& p, const PrepareOptions& o) {
  const RestitutionCalibration c = apply_restitution_mode(p.loaded.scene.setup);
  for (const PairCalibration& pair : c.pairs)
    say(o, fmt::format(
               "granshock: restitution of {} calibrated at dt = {:.3g} s, {:g} m/s: beta {:.5f} "
               "(continuous {:.5f}) returns e = {:.5f} for {:g} (continuous: {:.5f})",
               pair.pair, c.dt, c.speed, pair.beta, pair.beta_continuous, pair.e_eff,
               pair.restitution, pair.e_eff_continuous));
  p.restitution = c;
}

// inflow.mach_at = "inlet_bins" (docs/fields.md, "Three upstream Mach numbers"): sigma is
// calibrated in the inlet channel before anything is written. The calibration is a pure
// function of the scene, so a resumed run computes the same sigma; the resolved scene (in
// run.h5 and the checkpoint) carries it.
void calibrate_inflow(PreparedScene& p, const PrepareOptions& o, Backend backend) {
  Scene& scene = p.loaded.scene;
  say(o, fmt::format("granshock: calibrating sigma so that Ma over the two inlet bin rows is {:g} "
                     "(inflow.mach_at = \"inlet_bins\")",
                     *scene.inflow.target_mach));
  const InletCalibration& c = p.inlet.emplace(calibrate_inlet_mach(scene, 6, backend));
  scene.inflow.sigma = c.sigma;
  p.loaded.resolved = scene_to_toml(scene);
  const InletMach& last = c.chosen();
  if (!c.converged)
    p.warnings.push_back(fmt::format(
        "the inflow calibration did not converge in {} runs: sigma = {:.4g} m/s gives Ma = "
        "{:.3f} at the inlet rows against the target {:g}",
        c.iterations.size(), c.sigma, last.mach, c.target));
  else
    say(o, fmt::format("granshock: sigma = {:.4g} m/s (inserted convention: {:.4g}): Ma = {:.3f} "
                       "+- {:.3f} at the inlet rows after {} channel run{}",
                       c.sigma, c.sigma_inserted, last.mach, last.mach_err, c.iterations.size(),
                       c.iterations.size() == 1 ? "" : "s"));
}

}  // namespace

PreparedScene prepare_scene(LoadedScene loaded, const PrepareOptions& o) {
  PreparedScene p{std::move(loaded), {}, std::nullopt, std::nullopt};
  const auto check = [&] {
    return check_scene_before_run(p.scene(), o.force, o.processes, o.certified);
  };
  std::vector<std::string> checked = check();
  const Backend backend = o.checked ? o.checked() : Backend::default_space;
  throw_if_interrupted();
  const bool discrete = p.scene().setup.contacts.restitution_mode == RestitutionMode::discrete;
  if (discrete) calibrate_restitution(p, o);
  throw_if_interrupted();
  const bool inlet = o.calibrate_inflow && p.scene().inflow.mach_at == MachReference::inlet_bins;
  if (inlet) calibrate_inflow(p, o, backend);
  // Again with the calibrated damping or sigma: the time-step guard depends on the damping
  // ratio and on the fastest impact.
  if (discrete || inlet) checked = check();
  p.warnings.insert(p.warnings.end(), checked.begin(), checked.end());
  return p;
}

}  // namespace granshock
