#include "cases/bow_shock/run_memory.hpp"

#include <fmt/format.h>
#include <sys/resource.h>

#include <Kokkos_Core.hpp>
#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

#include "cases/bow_shock/sampling_plan.hpp"
#include "core/solver_state.hpp"
#include "core/user_error.hpp"
#include "kernels/device/backends.hpp"

namespace granshock {

namespace {

// The list holds every partner within d_max + skin of a particle (kernels/neighbours/
// verlet_list.hpp): n pi ((d + skin)^2 - d^2) of them at the inflow's number density n =
// phi / (pi d^2 / 4), the hard core excluded. Counted for every slot of the capacity, whose
// margin over the inflow's count (Scene::capacity_estimate) is the shock layer's
// compression.
double partners_per_particle(const Scene& s) {
  // The number density times the shell between d and the list's range.
  const double d = s.setup.max_diameter(), range = d + s.setup.skin();
  if (s.setup.dim == 3) return 8 * s.inflow.area_fraction * (std::pow(range / d, 3) - 1);
  return 4 * s.inflow.area_fraction * (range * range - d * d) / (d * d);
}

// Bytes of the particle arrays per slot (kernels/particles/particle_store.hpp): positions
// (x, x_ref, the fused step's x_next and the reordering's scratch) in double, velocity,
// force and v_next in Real, species, id, insertion order and scratch; cell, order and list
// offsets with a quarter in reserve; the contact virial (Dim^2 Real) and its scratch; with
// friction spins, torques and the springs, with their scratch.
double bytes_per_slot(const Scene& s, bool host_backend) {
  const int dim = s.setup.dim;
  const double real = s.setup.precision == Precision::single_precision ? 4 : 8;
  const double position = 8.0 * dim, vector = real * dim;
  double b = 4 * position + 3 * vector + 4 * 4 + 1.25 * 3 * 4;
  if (s.setup.precision == Precision::single_precision) b += vector;  // its own scratch
  b += 2 * real * dim * dim;
  if (!host_backend) b += 8;  // a device's sampling: bins
  if (s.setup.contacts.has_friction()) {
    const int slots = dim == 2 ? 8 : 16;
    b += 4 * real * spin_components(dim) + 2 * slots * 4 + 2 * slots * dim * real + vector;
  }
  return b;
}

// The host copies of a checkpoint (SolverState: positions, velocities, forces, reference
// positions, contact virial, species, ids, friction state, the list) and of a snapshot
// (HostParticles).
// On a host backend they come on top of the solver's arrays as well.
double host_bytes_per_particle(const Scene& s, double partners) {
  const int dim = s.setup.dim;
  double b = 4 * 8.0 * dim + 8.0 * dim * dim + 8 + 4 + 4 * partners;  // state, offsets, list
  const int spins = spin_components(dim);
  if (s.setup.contacts.has_friction())
    b += 16 * spins + (dim == 2 ? 8 : 16) * (4 + 8.0 * dim) + 8.0 * dim;
  b += 2 * 24 + 8 * spins + 8;  // the snapshot's positions and velocities (3 doubles), spin, ids
  return b;
}

std::string gb(double bytes) {
  return bytes >= 1e9 ? fmt::format("{:.3g} GB", bytes / 1e9)
                      : fmt::format("{:.3g} MB", bytes / 1e6);
}

}  // namespace

MemoryEstimate estimate_run_memory(const Scene& s, int processes, int threads) {
  const double share = 1.0 / std::max(1, processes);
  const bool host_backend = threads > 0;
  MemoryEstimate m;
  const double slots = double(s.capacity_estimate()) * share;
  m.particles = slots * bytes_per_slot(s, host_backend);
  const double partners = partners_per_particle(s);
  // The list and, on host backends, the per-thread parts it is built in, each with a
  // quarter in reserve.
  m.lists = slots * partners * 4 * 1.25 * (host_backend ? 2 : 1);
  const double range = s.setup.max_diameter() + s.setup.skin();
  const double cells = (s.setup.box.length(0) / range) * (s.setup.box.length(1) / range);
  m.cells = cells * share * 2 * 4;  // cell starts and fills
  // Every block's sums, the current block and, per host thread, a private copy of it; a
  // checkpoint copies every block to the host.
  const FieldSampling layout = SamplingPlan(s).layout();
  double block = double(layout.grid.bins()) * layout.grid.quantities() * 8;
  if (layout.has_profile()) block += double(layout.profile.bins()) * layout.grid.quantities() * 8;
  m.field_sums = block * (layout.grid.blocks + 1 + std::max(threads, 1));
  m.host = slots * host_bytes_per_particle(s, partners) + block * layout.grid.blocks;
  m.analysis = 4 * block * layout.grid.blocks;
  return m;
}

MemoryEstimate estimate_run_memory(const Scene& s, int processes) {
  // The arrays follow the kernels' paths (docs/cuda.md, "Branch points"): per-thread list
  // parts and field-sum copies on host paths only.
  using Space = Kokkos::DefaultExecutionSpace;
  constexpr bool host = uses_host_paths<Space>();
  return estimate_run_memory(s, processes, host ? Space().concurrency() : 0);
}

void check_run_memory(const Scene& s, const MemoryEstimate& m, double available) {
  if (m.total() <= available) return;
  const double particles = m.particles + m.host, sums = m.field_sums + m.analysis;
  // The part that drives it, and the key that sets that part.
  std::string key;
  if (m.lists >= std::max({particles, m.cells, sums}))
    key = fmt::format("scene key 'numerics.skin' = {:g} m ({:.3g} particle diameters)",
                      s.setup.skin(), s.setup.skin() / s.setup.max_diameter());
  else if (sums >= std::max(particles, m.cells))
    key = fmt::format("scene keys 'numerics.bin_size' = {:g} m x 'output.blocks' = {}",
                      s.bin_size_m, s.run.blocks);
  else if (m.cells >= particles)
    key = fmt::format(
        "scene keys 'domain.width' x 'domain.length' = {:g} m x {:g} m in cells "
        "of 'numerics.skin' + a diameter",
        s.setup.box.length(0), s.setup.box.length(1));
  else
    key = fmt::format(
        "scene keys 'domain.width' x 'domain.length' at 'inflow.area_fraction' = {:g} "
        "(about {:.3g} particles)",
        s.inflow.area_fraction, double(s.capacity_estimate()));
  throw UserError(fmt::format(
      "{}: the run needs about {} of memory (particles {}, neighbour lists {}, cells {}, field "
      "sums {}, host copies {}, final analysis {}), more than the {} available to it "
      "(MemAvailable, ulimit -v); make the scene smaller",
      key, gb(m.total()), gb(m.particles), gb(m.lists), gb(m.cells), gb(m.field_sums), gb(m.host),
      gb(m.analysis), gb(available)));
}

}  // namespace granshock
