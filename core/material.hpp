// Materials and particle species (docs/design.md, "Particles and materials"). SI units throughout.
#pragma once

#include <string>

namespace granshock {

struct Material {
  std::string name;
  double youngs_modulus_pa = 0;
  double poisson_ratio = 0;
  double density_kg_m3 = 0;
};

// The paper's materials (Table 1 and section 2 of the paper; docs/design.md, "Particles and
// materials").
Material steel();
Material aluminium();  // rho = rho_steel / 2.907

struct Species {
  std::string name;
  Material material;
  double diameter_m = 0;

  double radius_m() const { return 0.5 * diameter_m; }
  double mass_kg() const;            // rho pi d^3 / 6 (spheres, also in quasi-2D)
  double moment_of_inertia() const;  // 2/5 m r^2 (solid sphere)
};

}  // namespace granshock
