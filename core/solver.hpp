// The interface every compiled solver variant offers to apps and tests. A variant is
// one instantiation of the kernels for what a scene needs (dimension, precision,
// friction, obstacle); make_solver picks it once, at start-up.
#pragma once

#include <array>
#include <cstddef>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "host_particles.hpp"
#include "system_setup.hpp"

namespace granshock {

struct Diagnostics {
  double kinetic_energy = 0;     // translational, 1/2 m v^2 summed
  double rotational_energy = 0;  // 1/2 I omega^2 summed
  double elastic_energy = 0;     // Hertz normal springs: 8/15 Y* sqrt(R*) dn^(5/2)
  long contacts = 0;             // particle pairs plus particle-obstacle contacts
  std::array<double, 3> momentum{0, 0, 0};

  double total_energy() const { return kinetic_energy + rotational_energy + elastic_energy; }
};

class Solver {
 public:
  virtual ~Solver() = default;

  virtual void set_particles(const HostParticles& particles) = 0;
  virtual HostParticles particles() const = 0;  // copies the owned particles to the host
  virtual void advance(long steps) = 0;
  virtual Diagnostics diagnostics() const = 0;
  // Touching particle pairs as (smaller global id, larger global id), sorted.
  virtual std::vector<std::pair<int, int>> contact_pairs() const = 0;

  virtual std::size_t size() const = 0;
  virtual long steps_done() const = 0;
  virtual long list_builds() const = 0;
  virtual double time() const = 0;
  virtual std::string variant() const = 0;  // e.g. "2d/double/frictionless/obstacle/OpenMP"
};

enum class Backend { default_space, serial };

// The one place where a scene's needs select a compiled kernel variant.
std::unique_ptr<Solver> make_solver(const SystemSetup& setup, std::size_t capacity,
                                    Backend backend = Backend::default_space);

}  // namespace granshock
