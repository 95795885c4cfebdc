// The LIGGGHTS `hooke` contact law (docs/design.md, "Contact models"; docs/contact_model.md,
// "Linear spring-dashpot"; LIGGGHTS documentation, "gran model hooke"): the linear
// spring-dashpot (spring_dashpot.hpp) whose constant stiffness gives, at the characteristic
// impact speed V (contact.characteristic_velocity, hooke_parameters.hpp), the same peak
// overlap as the Hertz law (Johnson, Contact Mechanics, 1985, eq. 11.23):
//   kn = 16/15 sqrt(R*) Y* (15 m* V^2 / (16 sqrt(R*) Y*))^(1/5),   kt = kn.
#pragma once

#include <cmath>

#include "core/contact_settings.hpp"
#include "core/pair_properties.hpp"
#include "core/variant_names.hpp"
#include "kernels/models/spring_dashpot.hpp"
#include "models/hooke_parameters.hpp"

namespace granshock {

struct HookeStiffness {
  static double of(const PairProperties& p, const ContactOptions& o) {
    const double sqrt_r = std::sqrt(p.radius_star);
    const double v = HookeParameters::characteristic_velocity(o);
    return 16.0 / 15.0 * sqrt_r * p.youngs_star *
           std::pow(15.0 * p.mass_star * v * v / (16.0 * sqrt_r * p.youngs_star), 0.2);
  }
};

struct HookeModel : SpringDashpot<HookeStiffness> {
  static constexpr const char* name = choice_name(ContactModelKind::hooke);
  static constexpr ContactModelKind kind = ContactModelKind::hooke;
  using Parameters = HookeParameters;
};

}  // namespace granshock
