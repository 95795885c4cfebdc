#include "core/material.hpp"

#include <cmath>

namespace granshock {

Material steel() {
  return {"steel", 210e9, 0.303, 7850.0};
}
Material aluminium() {
  return {"aluminium", 69e9, 0.33, 7850.0 / 2.907};
}

double Species::mass_kg() const {
  return material.density_kg_m3 * M_PI * diameter_m * diameter_m * diameter_m / 6.0;
}
double Species::moment_of_inertia() const {
  return 0.4 * mass_kg() * radius_m() * radius_m();
}

}  // namespace granshock
