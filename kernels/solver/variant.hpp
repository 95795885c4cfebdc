// One compiled solver variant: what a scene needs in the inner loop (docs/design.md, "The
// variant table"; in the users' words, model only what the scene requires). Dimension,
// precision, contact law, friction and obstacle shape are template parameters; nothing a
// scene lacks is branched on per pair. The variant table (variant_table.hpp) lists the
// combinations that are compiled.
#pragma once

#include <optional>
#include <string>

#include "core/obstacle.hpp"
#include "core/solver_setup.hpp"
#include "core/variant_names.hpp"

namespace granshock {

template <int Dim_, class Real_, class Model_, bool Friction_, class Obstacle_>
struct Variant {
  static constexpr int dim = Dim_;
  using real = Real_;
  using model = Model_;                        // a contact law of kernels/models/
  static constexpr bool friction = Friction_;  // tangential force, history and rotation
  using obstacle = Obstacle_;                  // an obstacle shape of kernels/models/

  // 3-D is compiled in double precision only: its variants would double the kernels'
  // compile time again, and no 3-D scene has asked for single precision yet
  // (docs/design.md, "The variant table").
  static constexpr bool compiled = Dim_ == 2 || sizeof(Real_) == 8;

  static bool matches(const SolverSetup& s) {
    return s.dim == Dim_ && (s.precision == Precision::single_precision) == (sizeof(Real_) == 4) &&
           s.contacts.model == Model_::kind && s.contacts.has_friction() == Friction_ &&
           Obstacle_::matches(s.obstacle);
  }

  static std::string name() {
    const Precision precision =
        sizeof(Real_) == 4 ? Precision::single_precision : Precision::double_precision;
    return std::to_string(Dim_) + "d/" + choice_name(precision) + "/" + Model_::name + "/" +
           (Friction_ ? "friction" : "frictionless") + "/" + Obstacle_::name;
  }
};

}  // namespace granshock
