// The `linear` contact law (docs/contact_model.md, "Linear spring-dashpot"; LAMMPS
// documentation, "pair granular", hooke with kn given): the linear spring-dashpot
// (spring_dashpot.hpp) with the stiffness the scene gives, kn = contact.stiffness
// (linear_parameters.hpp) for every pair and for the obstacle, kt = kn, the damping from e.
// Unlike hooke's, kn does not follow the materials: a user matching a LAMMPS or
// LIGGGHTS run that fixed kn gets that kn. Added as the proof that a law is one header
// and its parameters (docs/design.md, "Adding a contact law").
#pragma once

#include "core/contact_settings.hpp"
#include "core/pair_properties.hpp"
#include "core/variant_names.hpp"
#include "kernels/models/spring_dashpot.hpp"
#include "models/linear_parameters.hpp"

namespace granshock {

struct LinearStiffness {
  static double of(const PairProperties&, const ContactOptions& o) {
    return LinearParameters::stiffness(o);
  }
};

struct LinearModel : SpringDashpot<LinearStiffness> {
  static constexpr const char* name = choice_name(ContactModelKind::linear);
  static constexpr ContactModelKind kind = ContactModelKind::linear;
  using Parameters = LinearParameters;
};

}  // namespace granshock
