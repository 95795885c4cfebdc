#include "cases/bow_shock/run_state.hpp"

#include "cases/bow_shock/run_observables.hpp"

namespace granshock {

// Field sums travel as one array: the grid's sums, the profile's, then the samples per
// block, with their three lengths in bin_shape.
CheckpointExtras pack_run_state(const std::string& scene_resolved, const Solver& solver,
                                const InflowController& inflow, const std::vector<long>& samples,
                                double wall_seconds, double cpu_seconds) {
  CheckpointExtras e;
  e.rng_counter = inflow.events();
  e.inserted = inflow.inserted();
  const RemovalCounts removed = solver.removed();
  e.deleted_outlet = removed.high[1];
  e.deleted_inlet = removed.low[1];
  e.insertion_carry = inflow.carry();
  e.wall_seconds_so_far = wall_seconds;
  e.cpu_seconds_so_far = cpu_seconds;
  e.scene_resolved = scene_resolved;
  e.bin_sums = solver.field_sums(false);
  const std::vector<double> profile = solver.field_sums(true);
  e.bin_shape = {long(e.bin_sums.size()), long(profile.size()), long(samples.size())};
  e.bin_sums.insert(e.bin_sums.end(), profile.begin(), profile.end());
  e.bin_sums.insert(e.bin_sums.end(), samples.begin(), samples.end());
  return e;
}

void restore_run_state(const CheckpointExtras& e, Solver& solver, InflowController& inflow,
                       std::vector<long>& samples) {
  inflow.restore(e.rng_counter, e.inserted, e.insertion_carry);
  const auto grid_end = e.bin_sums.begin() + e.bin_shape[0];
  const auto profile_end = grid_end + e.bin_shape[1];
  solver.restore_field_sums({e.bin_sums.begin(), grid_end}, {grid_end, profile_end});
  for (std::size_t b = 0; b < samples.size(); ++b) samples[b] = long(*(profile_end + long(b)));
}

RunFit run_fit(const Scene& s, const InflowController& inflow, const SamplingPlan& sampling,
               long step) {
  RunFit f;
  f.total_steps = s.total_steps();
  f.insertion_events = inflow.events_by(step);
  f.max_carry = inflow.particles_per_batch() * double(step / inflow.period_steps() + 1);
  f.dt = s.setup.dt;
  for (const Species& species : s.setup.species) {
    f.mass.push_back(species.mass_kg());
    f.inertia.push_back(species.moment_of_inertia());
  }
  f.max_diameter = s.setup.max_diameter();
  f.inflow_energy = inflow_energy(s);
  const BinLayout& g = sampling.layout().grid;
  f.quantities = g.quantities();
  f.n_species = g.n_species;
  f.dim = g.dim;
  f.grid_sums = long(g.bins()) * g.quantities() * g.blocks;
  f.profile_sums = long(sampling.layout().profile.bins()) * g.quantities() * g.blocks;
  f.samples = sampling.samples_by(step);
  return f;
}

}  // namespace granshock
