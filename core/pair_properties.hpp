// Effective properties of a contact pair (DESIGN.md section 2.1, LIGGGHTS `hertz`):
//   1/Y* = (1-nu_i^2)/E_i + (1-nu_j^2)/E_j
//   1/G* = 2(2-nu_i)(1+nu_i)/E_i + 2(2-nu_j)(1+nu_j)/E_j
//   1/R* = 1/r_i + 1/r_j,  1/m* = 1/m_i + 1/m_j,  beta = ln e / sqrt(ln^2 e + pi^2)
// A fixed wall (the obstacle) has infinite radius and mass: R* = r_i, m* = m_i.
#pragma once

#include <limits>
#include <string>

#include "material.hpp"

namespace granshock {

struct PairProperties {
  std::string name;  // e.g. "steel-aluminium", "steel-wall"
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
PairProperties particle_wall(const Species& p, const Material& wall, double restitution,
                             double friction);

// Per-pair constants on the device, arranged so that one contact costs two square roots:
//   kn = 4/3 Y* sqrt(R* dn) = kn_coef sqrt(dn)      Sn = 2 Y* sqrt(R* dn)
//   gn = -2 sqrt(5/6) beta sqrt(Sn m*) = gn_coef dn^(1/4)
//   kt = St = 8 G* sqrt(R* dn) = kt_coef sqrt(dn)
//   gt = -2 sqrt(5/6) beta sqrt(St m*) = gt_coef dn^(1/4)
// The elastic energy of a Hertz contact is U = 8/15 Y* sqrt(R*) dn^(5/2).
template <class Real>
struct HertzCoefficients {
  Real kn_coef;
  Real gn_coef;
  Real kt_coef;
  Real gt_coef;
  Real friction;
  Real normal_force_floor;  // 0 with limit_force (no attraction), -max otherwise
  Real energy_coef;
};

template <class Real>
HertzCoefficients<Real> hertz_coefficients(const PairProperties& p, bool limit_force);

}  // namespace granshock
