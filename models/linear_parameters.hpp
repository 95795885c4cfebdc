// The parameters of the `linear` law (kernels/models/linear.hpp; docs/contact_model.md,
// "Linear spring-dashpot"): its normal stiffness kn, given (LAMMPS' `pair granular hooke
// kn`), the same for every pair. Plain C++: the scene reader reads the keys from here
// (models/law_key.hpp).
#pragma once

#include <array>

#include "core/contact_settings.hpp"
#include "models/law_key.hpp"

namespace granshock {

struct LinearParameters {
  static constexpr ContactModelKind kind = ContactModelKind::linear;
  static constexpr std::array<LawKey, 1> keys{{
      {"stiffness", "number (N/m)",
       "the normal stiffness kn of every pair and of the obstacle; kt = kn", 1e-3, 1e12,
       "from a soft foam to past a stiff steel contact (about 1e9 N/m for 1 mm spheres)"},
  }};

  static double stiffness(const ContactOptions& o) { return o.law_parameters[0]; }
  static void set_stiffness(ContactOptions& o, double value) { o.law_parameters[0] = value; }
};

}  // namespace granshock
