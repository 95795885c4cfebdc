// A bow-shock scene (docs/design.md, "The bow-shock scene"): the physics (SolverSetup), the inflow,
// and how long to run and what to write. Parsed from TOML by io/scene_file.hpp.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "core/bin_layout.hpp"
#include "core/kinetic_theory.hpp"
#include "core/solver_setup.hpp"

namespace granshock {

// The largest upstream area fraction the inflow can insert (docs/scene_format.md, "The
// inflow"): the batched random insertion into the strip saturates near 0.42 (measured with
// the paper's mixture), below the jamming limit 0.547 of random sequential adsorption of
// discs (Hinrichsen, Feder & Jossang, J. Stat. Phys. 44, 793, 1986) that bounds any such
// method. Requests up to this value are met within a few percent (tests/scene).
inline constexpr double kMaxInflowAreaFraction = 0.4;

// Where inflow.mach is meant (docs/fields.md, "Three upstream Mach numbers"): the Mach
// number of the inserted state (sigma from kinetic theory), or the one measured over the
// first two bin rows, as the paper measures Ma_inf (sigma calibrated before the run).
enum class MachReference { inserted, inlet_bins };
MachReference parse_mach_reference(const std::string& name);  // core/choice_names.hpp
std::string to_string(MachReference m);

struct InflowSpec {
  double area_fraction = 0.1;           // phi_inf, upstream
  double speed_m_per_s = 1.0;           // U, along +y
  std::optional<double> sigma_m_per_s;  // velocity fluctuation per component, or
  std::optional<double> target_mach;    // the upstream Mach number it should give
  MachReference mach_at = MachReference::inserted;
  double strip_m = 2e-3;                // insertion strip y in [0, strip]
  std::vector<double> number_fraction;  // per species, sums to 1

  double sigma = 0;  // the fluctuation used (given, or from target_mach)
};

struct RunControl {
  double duration_s = 1.0;
  double production_start_s = 0.5;  // fields average over [production_start, duration]
  double snapshot_interval_s = 0.1;
  double series_interval_s = 0.01;
  double checkpoint_interval_s = 0.5;
  double progress_interval_s = 2.0;  // wall clock
  long sample_every = 100;           // steps between field samples
  int blocks = 10;                   // production window cut into blocks (error bars)
  std::uint64_t seed = 1;
};

struct Scene {
  std::string name;
  double d_m = 1e-3;  // the length unit "d" of the scene file
  SolverSetup setup;
  InflowSpec inflow;
  RunControl run;
  MassDefinition mass_definition = MassDefinition::mixture_mean;
  double bin_size_m = 3e-3;
  ScatterStrategy field_scatter = ScatterStrategy::automatic;

  long total_steps() const;
  // The fastest relative normal impact the scene can produce: a particle at U + 4 sigma
  // meeting one that rebounded from the obstacle at up to U + 4 sigma.
  double fastest_impact_speed() const;
  // Particles expected in the domain: phi_inf over the area, plus a margin for the
  // dense region in front of the obstacle; the solver's initial capacity.
  std::size_t capacity_estimate() const;
  double capacity_unbounded() const;  // the same estimate, unrounded and unbounded
  // Mean particle mass and the restitution used in the sound speed.
  double mean_mass() const;
  double mean_restitution() const;
  // The mean particle's area (pi d^2 / 4, 2-D) or volume (pi d^3 / 6, 3-D) by number
  // fraction: phi_inf (an area or a volume fraction) over it is the number density upstream.
  double mean_particle_measure() const;
  // The root mean square diameter by number fraction: the d of D/d.
  double mean_particle_diameter() const;
  // The domain's extent across the x-y plane that the particles fill: 1 in 2-D (numbers
  // per area are numbers per area), the thickness box.length(2) in 3-D.
  double depth() const;
  // Particles per unit area of the x-y plane upstream: phi_inf depth / mean_particle_measure().
  double inflow_number_per_area() const;
  // The sigma that gives upstream Mach number `mach` at the inflow's speed and state
  // (core/kinetic_theory.hpp), and the Mach number the scene asks for: inflow.mach, or
  // the one its inflow.sigma gives (sigma is proportional to U / Ma).
  double sigma_at_mach(double mach) const;
  double inflow_mach() const;
};

// Computes inflow.sigma from the given sigma or from target_mach (docs/fields.md).
void resolve_inflow(Scene& scene);

}  // namespace granshock
