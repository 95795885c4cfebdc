// What a scene needs compiled into the inner loop (DESIGN.md section 5). Each
// combination is a separate instantiation; nothing the scene lacks is branched on
// per pair.
#pragma once

#include <string>

namespace granshock {

template <int Dim_, class Real_, bool Friction_, bool Obstacle_>
struct SceneTraits {
  static constexpr int dim = Dim_;
  using real = Real_;
  static constexpr bool friction = Friction_;  // tangential force, history and rotation
  static constexpr bool obstacle = Obstacle_;  // the fixed-cylinder contact

  static_assert(Dim_ == 2 || Dim_ == 3, "granshock kernels are 2-D or 3-D");
  static_assert(Dim_ == 2 || !Friction_,
                "friction with rotation is implemented for quasi-2-D scenes only");

  static std::string name() {
    return std::to_string(Dim_) + "d/" + (sizeof(Real_) == 4 ? "single" : "double") + "/" +
           (Friction_ ? "friction" : "frictionless") + "/" +
           (Obstacle_ ? "obstacle" : "no-obstacle");
  }
};

}  // namespace granshock
