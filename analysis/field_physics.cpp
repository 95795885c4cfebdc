#include "analysis/field_physics.hpp"

#include <cmath>
#include <limits>

#include "core/scene.hpp"
#include "core/user_error.hpp"
#include "models/obstacle_shapes.hpp"

namespace granshock {

double FieldPhysics::m_av() const {
  double m = 0;
  for (double ma : mass) m += ma;
  return m / static_cast<double>(mass.size());
}

double FieldPhysics::sound_speed_mass(MassDefinition def, const std::vector<double>& xi) const {
  return granshock::sound_speed_mass(def, mass, xi);
}

double FieldPhysics::nominal_mach(MassDefinition def) const {
  if (!(inflow_sigma > 0)) return std::numeric_limits<double>::quiet_NaN();
  double m_mean = 0;
  for (std::size_t a = 0; a < mass.size(); ++a) m_mean += inflow_number_fraction[a] * mass[a];
  const double temperature = m_mean * inflow_sigma * inflow_sigma;
  const double a = sound_speed(temperature, sound_speed_mass(def, inflow_number_fraction),
                               inflow_phi, restitution, dim);
  return inflow_speed / a;
}

double FieldPhysics::dx_from_axis(double x) const {
  const double width = box_x_hi - box_x_lo;
  const double xc = obstacle ? obstacle->xc : 0.5 * (box_x_lo + box_x_hi);
  double dx = x - xc;
  if (width > 0) dx -= width * std::round(dx / width);
  return dx;
}

bool FieldPhysics::Obstacle::upstream_surface(double x, double& y) const {
  return obstacle_upstream_surface(body, x, y);
}

FieldPhysics field_physics_from_scene(const Scene& s) {
  FieldPhysics p;
  p.dim = s.setup.dim;
  for (const Species& sp : s.setup.species) {
    p.species.push_back(sp.name);
    p.mass.push_back(sp.mass_kg());
    p.diameter.push_back(sp.diameter_m);
  }
  p.restitution = s.mean_restitution();
  p.mass_definition = s.mass_definition;
  p.d = s.d_m;
  p.inflow_speed = s.inflow.speed_m_per_s;
  p.inflow_phi = s.inflow.area_fraction;
  p.inflow_sigma = s.inflow.sigma;
  p.inflow_strip = s.inflow.strip_m;
  p.inflow_number_fraction = s.inflow.number_fraction;
  p.box_x_lo = s.setup.box.lo[0];
  p.box_x_hi = s.setup.box.hi[0];
  p.box_y_lo = s.setup.box.lo[1];
  p.box_y_hi = s.setup.box.hi[1];
  if (const auto& o = s.setup.obstacle)
    p.obstacle = FieldPhysics::Obstacle{o->centre[0],
                                        o->centre[1],
                                        obstacle_frontal_width(*o),
                                        obstacle_upstream_face(*o),
                                        obstacle_downstream_face(*o),
                                        *o};
  return p;
}

}  // namespace granshock
