#include "cases/bow_shock/inlet_calibration.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "analysis/bin_fields.hpp"
#include "analysis/block_error.hpp"
#include "analysis/field_physics.hpp"
#include "analysis/upstream_state.hpp"
#include "cases/bow_shock/inflow.hpp"
#include "cases/bow_shock/interrupt.hpp"
#include "core/user_error.hpp"
#include "models/sampled_layer.hpp"

namespace granshock {

namespace {

constexpr int kRows = 2;  // the paper's "two bins from the inlet"

// The scene cut down to the inlet channel: as wide as the scene (at most max_width_bins
// whole bins), length_bins long, no obstacle, the inflow at fluctuation sigma; the
// production window long enough for InletChannel::visits particles to cross the rows.
Scene inlet_channel(const Scene& s, double sigma) {
  Scene c = s;
  const double bin = s.bin_size_m;
  const int nx =
      std::clamp(int(s.setup.box.length(0) / bin + 1e-9), 1, InletChannel::max_width_bins);
  c.setup.obstacle.reset();
  c.setup.box.hi[0] = c.setup.box.lo[0] + nx * bin;
  c.setup.box.hi[1] =
      c.setup.box.lo[1] + std::max(InletChannel::length_bins * bin, s.inflow.strip_m + kRows * bin);
  c.inflow.sigma = sigma;
  c.inflow.sigma_m_per_s = sigma;

  const double flux = s.inflow_number_per_area() * c.setup.box.length(0) * s.inflow.speed_m_per_s;
  // Prefilled, the channel is developed after one transit; two make sure.
  const double spin_up = 2 * c.setup.box.length(1) / s.inflow.speed_m_per_s;
  c.run.production_start_s = spin_up;
  c.run.duration_s = spin_up + InletChannel::visits / flux;
  c.run.blocks = InletChannel::blocks;
  return c;
}

// Adds one sample of the particles in the first kRows rows to block `block` of `sums`
// (the quantities of core/bin_layout.hpp; the virial stays zero: the Mach number needs
// only T and phi).
void add_sample(BinSums& sums, const HostParticles& p, int block) {
  const BinLayout layout = sums.layout();
  const double width = sums.nx * sums.dx;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const double y = p.position[i][1] - sums.y0;
    if (y < 0 || y >= kRows * sums.dy) continue;
    double x = std::fmod(p.position[i][0] - sums.x0, width);
    if (x < 0) x += width;
    const int ix = std::min(sums.nx - 1, int(x / sums.dx));
    const int iy = std::min(kRows - 1, int(y / sums.dy));
    const double vx = p.velocity[i][0], vy = p.velocity[i][1];
    const int a = p.species[i];
    double* q = &sums.sums[std::size_t(layout.offset(block, iy, ix, 0))];
    q[layout.species_index(a, BinLayout::count)] += 1;
    q[layout.species_index(a, BinLayout::sum_vx)] += vx;
    q[layout.species_index(a, BinLayout::sum_vy)] += vy;
    q[layout.species_index(a, BinLayout::sum_vxvx)] += vx * vx;
    q[layout.species_index(a, BinLayout::sum_vxvy)] += vx * vy;
    q[layout.species_index(a, BinLayout::sum_vyvy)] += vy * vy;
    if (layout.dim == 3) {
      const double vz = p.velocity[i][2];
      q[layout.depth_index(a, BinLayout::sum_vz)] += vz;
      q[layout.depth_index(a, BinLayout::sum_vzvz)] += vz * vz;
    }
  }
  sums.samples[std::size_t(block)] += 1;
}

UpstreamState inlet_rows(const BinSums& sums, const FieldPhysics& phys) {
  return measure_upstream(compute_bin_fields(sums, phys), sums, phys, 0, kRows);
}

}  // namespace

InletMach measure_inlet_mach(const Scene& scene, double sigma, Backend backend) {
  const Scene c = inlet_channel(scene, sigma);
  BinSums sums;
  sums.n_species = int(c.setup.species.size());
  sums.nx = int(c.setup.box.length(0) / c.bin_size_m + 1e-9);
  sums.ny = kRows;
  sums.blocks = c.run.blocks;
  sums.x0 = c.setup.box.lo[0];
  sums.y0 = c.setup.box.lo[1];
  sums.dx = sums.dy = c.bin_size_m;
  sums.dim = c.setup.dim;
  sums.z0 = sampled_z_range(c)[0];  // the whole layer: the channel has no obstacle
  sums.depth = sampled_z_range(c)[1];
  sums.sums.assign(std::size_t(sums.blocks) * sums.bins() * sums.quantities(), 0.0);
  sums.samples.assign(std::size_t(sums.blocks), 0.0);

  InflowController inflow(c);
  const std::unique_ptr<Solver> solver = make_solver(c.setup, c.capacity_estimate(), backend);
  solver->set_particles(HostParticles{});
  inflow.prefill(*solver, [](long, long) { throw_if_interrupted(); });
  inflow.insert_if_due(*solver, 0);
  const long total = c.total_steps();
  const long first = long(std::llround(c.run.production_start_s / c.setup.dt));
  const long every = std::max(1L, scene.run.sample_every);
  const long period = inflow.period_steps();
  long step = 0;
  while (step < total) {
    throw_if_interrupted();  // a channel run can take minutes (docs/output_format.md, "Signals")
    long next = std::min(total, (step / period + 1) * period);
    const long sample = step < first ? first : first + ((step - first) / every + 1) * every;
    next = std::min(next, sample);
    solver->advance(next - step);
    step = next;
    inflow.insert_if_due(*solver, step);
    if (step >= first && step < total && (step - first) % every == 0)
      add_sample(
          sums, solver->particles(),
          int(std::min<long>(sums.blocks - 1, (step - first) * sums.blocks / (total - first))));
  }

  const FieldPhysics phys = field_physics_from_scene(c);
  const UpstreamState rows = inlet_rows(sums, phys);
  if (!rows.determined())
    throw UserError(
        "inflow.mach_at = \"inlet_bins\": the inlet rows of the calibration channel "
        "hold no temperature (" +
        rows.reason +
        "); use inflow.mach_at = \"inserted\" or a larger output.sample_every window");
  std::vector<double> by_block;
  for (int b = 0; b < sums.blocks; ++b) {
    const UpstreamState s = inlet_rows(sums.block(b), phys);
    if (s.determined()) by_block.push_back(s.mach);
  }
  InletMach m;
  m.sigma = sigma;
  m.mach = rows.mach;
  m.mach_err = block_standard_error(by_block);
  m.mach_mixture_mean = rows.mach_mixture_mean;
  m.mach_paper_sum = rows.mach_paper_sum;
  m.phi = rows.phi;
  m.simulated_s = c.run.duration_s;
  return m;
}

const InletMach& InletCalibration::chosen() const {
  for (const InletMach& m : iterations)
    if (m.sigma == sigma) return m;
  return iterations.back();
}

InletCalibration calibrate_inlet_mach(const Scene& scene, int max_iterations, Backend backend) {
  InletCalibration cal;
  cal.target = scene.inflow.target_mach.value_or(0.0);
  if (!(cal.target > 0))
    throw UserError(
        "inflow.mach_at = \"inlet_bins\" needs inflow.mach (the target to calibrate for)");
  cal.sigma_inserted = scene.inflow.sigma;
  double sigma = scene.inflow.sigma;
  for (int k = 0; k < max_iterations; ++k) {
    const InletMach m = measure_inlet_mach(scene, sigma, backend);
    cal.iterations.push_back(m);
    cal.sigma = sigma;
    cal.tolerance = std::max(0.01, 2 * m.mach_err / m.mach);
    if (std::abs(m.mach / cal.target - 1) <= cal.tolerance) {
      cal.converged = true;
      break;
    }
    // Ma falls as 1/sigma at a fixed state; cooling in front of the rows bends that, which
    // the secant through the last two iterates (in logs) follows.
    double next = sigma * m.mach / cal.target;
    if (cal.iterations.size() >= 2) {
      const InletMach& p = cal.iterations[cal.iterations.size() - 2];
      const double slope = std::log(m.mach / p.mach) / std::log(m.sigma / p.sigma);
      if (slope < -0.2 && std::isfinite(slope))
        next = sigma * std::exp(std::log(cal.target / m.mach) / slope);
    }
    sigma = std::clamp(next, 0.5 * sigma, 2.0 * sigma);
  }
  if (!cal.converged) {
    // The iterate closest to the target.
    const InletMach* best = &cal.iterations.front();
    for (const InletMach& m : cal.iterations)
      if (std::abs(m.mach / cal.target - 1) < std::abs(best->mach / cal.target - 1)) best = &m;
    cal.sigma = best->sigma;
  }
  return cal;
}

}  // namespace granshock
