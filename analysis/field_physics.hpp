// What the field analysis needs to know about a run's scene (docs/design.md, "The bow-shock scene";
// docs/fields.md): the species' masses and diameters, the restitution and mass definition of the
// sound speed, the inflow, the domain and the obstacle. Built from the resolved scene in run.h5.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "core/kinetic_theory.hpp"
#include "core/obstacle.hpp"

namespace granshock {

struct Scene;

struct FieldPhysics {
  int dim = 2;
  std::vector<std::string> species;
  std::vector<double> mass;      // kg, m_a = rho pi d^3 / 6
  std::vector<double> diameter;  // m
  double restitution = 0.5;      // Scene::mean_restitution(): e in F(phi)
  MassDefinition mass_definition = MassDefinition::mixture_mean;
  double d = 1e-3;  // the scene's length unit, m

  // Inflow (docs/design.md, "The bow-shock scene").
  double inflow_speed = 0;     // U, m/s along +y
  double inflow_phi = 0.1;     // phi_inf asked for
  double inflow_sigma = 0;     // velocity fluctuation per component, m/s
  double inflow_strip = 2e-3;  // insertion strip y in [0, strip], m
  std::vector<double> inflow_number_fraction;

  double box_x_lo = 0, box_x_hi = 0, box_y_lo = 0, box_y_hi = 0;  // m; x periodic

  // What the analysis asks of the obstacle, from its shape (models/obstacle_shapes.hpp).
  struct Obstacle {
    double xc = 0, yc = 0;
    double width = 0;  // across the flow: the D of delta/D (docs/fields.md)
    double face = 0;   // y of the upstream face on the stagnation line
    double back = 0;   // y of the downstream face
    granshock::Obstacle body;
    // y of the upstream surface at x, when x lies within the frontal width.
    bool upstream_surface(double x, double& y) const;
  };
  std::optional<Obstacle> obstacle;

  // m_av = sum_a m_a / n_species (the paper's sum_a m_a / 2 for its two species): the
  // mass in the normalised temperature T / (m_av U^2).
  double m_av() const;
  // m in a = sqrt(T/m ...) for local number fractions xi_a (core/kinetic_theory.hpp).
  double sound_speed_mass(MassDefinition def, const std::vector<double>& xi) const;
  // The Mach number the inflow was set up for: U / a with T = m_mean sigma^2 (T_a =
  // m_a sigma^2 for every species), phi = phi_inf, the inflow's number fractions. Equals
  // the scene's inflow.mach when it gave one (sigma follows from it, core/scene.cpp).
  // NaN when sigma = 0 (a cold inflow has no finite Mach number).
  double nominal_mach(MassDefinition def) const;
  // The minimum-image crosswise distance x - xc on the periodic x axis.
  double dx_from_axis(double x) const;
};

FieldPhysics field_physics_from_scene(const Scene& scene);

}  // namespace granshock
