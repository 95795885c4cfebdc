// Effective properties of a contact pair (docs/design.md, "Contact models"; LIGGGHTS `hertz`):
//   1/Y* = (1-nu_i^2)/E_i + (1-nu_j^2)/E_j
//   1/G* = 2(2-nu_i)(1+nu_i)/E_i + 2(2-nu_j)(1+nu_j)/E_j
//   1/R* = 1/r_i + 1/r_j,  1/m* = 1/m_i + 1/m_j,  beta = ln e / sqrt(ln^2 e + pi^2)
// The obstacle, like a LIGGGHTS wall, has infinite radius and mass: R* = r_i, m* = m_i.
// Each contact law (kernels/models/) turns these into its own per-pair constants.
#pragma once

#include <string>

#include "core/material.hpp"

namespace granshock {

struct PairProperties {
  std::string name;  // e.g. "steel-aluminium", "steel-obstacle"
  double youngs_star = 0;
  double shear_star = 0;
  double radius_star = 0;
  double mass_star = 0;
  double beta = 0;
  double restitution = 0;
  double friction = 0;
  double min_diameter = 0;  // the smaller particle diameter of the pair, m
};

double damping_beta(double restitution);
PairProperties particle_pair(const Species& a, const Species& b, double restitution,
                             double friction);
PairProperties particle_obstacle(const Species& p, const Material& obstacle, double restitution,
                                 double friction);
// The pair with its Young's and shear moduli divided by `softening` (contact.softening).
PairProperties softened(PairProperties pair, double softening);

}  // namespace granshock
