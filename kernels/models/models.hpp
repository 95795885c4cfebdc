// The physics a scene can choose, as lists of types (docs/design.md, "Adding a model"):
// the contact laws and the obstacle shapes. The variant table compiles each combination
// (kernels/solver/variant_table.hpp); host code that needs a law's or a shape's formulas
// without a kernel (the time-step guard, the inflow) asks with_contact_model or
// with_obstacle_shape. A new law or shape is one header and one line in each list here.
#pragma once

#include <optional>
#include <stdexcept>

#include "contact_settings.hpp"
#include "models/cylinder.hpp"
#include "models/hertz.hpp"
#include "models/hooke.hpp"
#include "models/no_obstacle.hpp"
#include "obstacle.hpp"

namespace granshock {

// Calls f(Model{}) for the scene's contact law.
template <class F>
decltype(auto) with_contact_model(ContactModelKind kind, F&& f) {
  switch (kind) {
    case ContactModelKind::hertz:
      return f(HertzModel{});
    case ContactModelKind::hooke:
      return f(HookeModel{});
  }
  throw std::logic_error("with_contact_model: unknown contact model");
}

// Calls f(Shape{}) for the scene's obstacle, NoObstacle when it has none.
template <class F>
decltype(auto) with_obstacle_shape(const std::optional<Obstacle>& obstacle, F&& f) {
  if (!obstacle) return f(NoObstacle{});
  switch (obstacle->shape) {
    case ObstacleShape::cylinder:
      return f(CylinderShape{});
  }
  throw std::logic_error("with_obstacle_shape: unknown obstacle shape");
}

}  // namespace granshock
