// The names of what the variant table compiles (docs/design.md, "Names of choices"): the
// contact laws, obstacle shapes and precisions. The scene's keys, `collide`'s options, the
// variant's name in summary.json and Model::name (kernels/models/) all come from these
// tables. Kept apart from core/choice_names.hpp so that the kernels include no more than
// they need, and are not rebuilt when another choice's names change.
#pragma once

#include "core/choice.hpp"
#include "core/contact_settings.hpp"
#include "core/obstacle.hpp"
#include "core/solver_setup.hpp"

namespace granshock {

template <>
struct Choices<ContactModelKind> {
  static constexpr const char* what = "contact model";
  static constexpr ChoiceName<ContactModelKind> table[] = {
      {ContactModelKind::hertz, "hertz",
       "damped Hertz law of LIGGGHTS, e exact at every impact speed (docs/contact_model.md)"},
      {ContactModelKind::hooke, "hooke",
       "linear spring-dashpot of LIGGGHTS, kn from contact.characteristic_velocity "
       "(kernels/models/hooke.hpp)"},
      {ContactModelKind::linear, "linear",
       "linear spring-dashpot with a given stiffness, kn = contact.stiffness "
       "(kernels/models/linear.hpp)"},
  };
};

template <>
struct Choices<ObstacleShape> {
  static constexpr const char* what = "obstacle shape";
  static constexpr ChoiceName<ObstacleShape> table[] = {
      {ObstacleShape::cylinder, "cylinder", "a cylinder with its axis along z"},
      {ObstacleShape::wedge, "wedge", "a symmetric wedge, its tip upstream (a triangular prism)"},
      {ObstacleShape::plate, "plate", "a flat plate or rectangular block facing the flow"},
      {ObstacleShape::square, "square",
       "a square block, a face or (rotated 45 degrees) a corner upstream"},
      {ObstacleShape::sphere, "sphere",
       "a sphere at the middle of the layer (3-D; a quasi-2-D scene's particles meet its cut "
       "through the centre, the cylinder's disk)"},
  };
};

template <>
struct Choices<Precision> {
  static constexpr const char* what = "precision";
  static constexpr ChoiceName<Precision> table[] = {
      {Precision::double_precision, "double", "velocities, forces and the contact law in double"},
      {Precision::single_precision, "single",
       "velocities, forces and the contact law in float; positions stay double"},
  };
};

static_assert(choice_table_is_one_to_one<ContactModelKind>());
static_assert(choice_table_is_one_to_one<ObstacleShape>());
static_assert(choice_table_is_one_to_one<Precision>());

}  // namespace granshock
