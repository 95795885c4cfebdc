// The parameters of the `hooke` law (kernels/models/hooke.hpp; docs/contact_model.md,
// "Linear spring-dashpot"): the impact speed at which its constant stiffness gives the
// Hertz law's peak overlap (LIGGGHTS' characteristicVelocity). Plain C++: the scene reader
// reads the keys from here (models/law_key.hpp).
#pragma once

#include <array>

#include "core/contact_settings.hpp"
#include "models/law_key.hpp"

namespace granshock {

struct HookeParameters {
  static constexpr ContactModelKind kind = ContactModelKind::hooke;
  static constexpr std::array<LawKey, 1> keys{{
      {"characteristic_velocity", "number (m/s)",
       "the impact speed at which kn gives Hertz's peak overlap (LIGGGHTS' "
       "characteristicVelocity)",
       1e-6, 1e4, "from a micrometre per second to hypervelocity", LawKey::Default::inflow_speed},
  }};

  static double characteristic_velocity(const ContactOptions& o) { return o.law_parameters[0]; }
  static void set_characteristic_velocity(ContactOptions& o, double value) {
    o.law_parameters[0] = value;
  }
};

}  // namespace granshock
