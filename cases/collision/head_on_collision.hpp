// `granshock collide`: a head-on impact of two particles, or of a particle on the fixed
// obstacle (any shape of models/obstacle_shapes.hpp, a cylinder unless --shape says
// otherwise), run through the same solver variants and kernels as a full simulation.
// It measures what the contact law does at a given time step: the effective
// restitution, the contact duration and the peak overlap.
#pragma once

#include <array>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "core/obstacle.hpp"
#include "core/solver.hpp"
#include "core/solver_setup.hpp"
#include "kernels/models/restitution_calibration.hpp"
#include "kernels/models/time_step_guard.hpp"
#include "models/shape_key.hpp"

namespace granshock {

// Where an impact happens: the point of first contact of two particles, or the
// obstacle's centre (a cylinder's axis), and the axis along which the bodies approach
// (0 = x, 1 = y). Far from the origin (the paper's box spans 0.5 m) it shows what the
// precision of positions costs: docs/design.md, "Particles".
struct ImpactPlace {
  std::array<double, 2> centre = {0, 0};  // m
  int axis = 0;
};

// CollisionOptions' line of impact when none is given: x for two particles; y for the
// obstacle, the flow's line, so that the particle strikes the upstream surface on the
// axis as the flow of a scene does (models/obstacle_shapes.hpp).
inline constexpr int kImpactAxisOfThePair = -1;

struct CollisionOptions {
  std::string pair = "steel-steel";  // a-b for two particles, a-obstacle for the obstacle
  double speed_m_per_s = 1.0;        // relative normal approach speed
  std::optional<double> dt;          // none: t_c / 100
  double restitution = 0.5;
  ContactModelKind model = ContactModelKind::hertz;
  // The law's parameters by key name (models/law_parameters.hpp), as the options
  // --<key> gave them: hooke's characteristic_velocity (none: the impact speed), linear's
  // stiffness (required). A key of another law is refused.
  std::map<std::string, std::optional<double>> law_parameters;
  bool limit_force = false;
  Precision precision = Precision::double_precision;
  bool force = false;  // run even past the stable time step
  RestitutionMode restitution_mode = RestitutionMode::continuous;
  // The first contact step overlaps by phase x speed x dt, phase in (0, 1].
  double phase = 1.0;
  ImpactPlace place = {{0, 0}, kImpactAxisOfThePair};
  // The obstacle of an -obstacle pair: its shape (none: the cylinder) and its size keys
  // by name (models/obstacle_shapes.hpp), as the options --<key> gave them; a size not
  // given is collision_shape_size's. A size of another shape, or either of them with two
  // particles, is refused.
  std::optional<ObstacleShape> shape;
  std::map<std::string, std::optional<double>> shape_sizes;
};

inline constexpr double kMaxCollisionSteps = 1e7;
// The fastest impact and characteristic velocity collide takes (m/s), as a scene's speeds
// (docs/scene_format.md): past hypervelocity no granular contact law applies, and at
// 1e308 m/s the collision time underflowed to a time step of 0 s.
inline constexpr double kMaxCollisionSpeed = 1e4;
// The impact's place must resolve a step's drift: its position's rounding (double) at
// most this fraction of the relative drift speed x dt; past it e_eff degrades, and at
// 1e9 m the particles did not move at all.
inline constexpr double kPlaceResolution = 1e-3;
// The largest length of an obstacle collide takes (m): the collision's box reaches from
// the obstacle's centre past its upstream surface, and at 1 m (1000 particle diameters,
// twice the paper's 500 d box) its cells already number tens of thousands.
inline constexpr double kMaxCollisionObstacleSize = 1.0;
// How far the obstacle's normal where the particle strikes it may turn from the line of
// impact (its sine): the rebound along the line is then e cos^2 - sin^2, within 2e-10 of
// the head-on one, below what collide prints.
inline constexpr double kHeadOnNormal = 1e-5;

struct CollisionResult {
  std::string pair;
  double speed = 0;
  double dt = 0;
  double t_c = 0;
  double e_in = 0;
  double e_eff = 0;      // post/pre normal relative speed
  double t_contact = 0;  // s, from overlap zero crossings interpolated between steps
  double max_overlap = 0;
  double phase = 1.0;
  ImpactPlace place;
  double beta = 0;  // the damping the collision ran with
  long steps = 0;
  bool limit_force = false;
  std::string model;
  std::string variant;
  TimeStepAssessment time_step;
  OverlapAssessment overlap;                   // the Hertz peak overlap predicted at this speed
  std::optional<PairCalibration> calibration;  // restitution_mode = discrete
  // An impact on the obstacle: the obstacle (shape, sizes, centre at the place), the point
  // of its surface the particle struck, and what is there: "flat face", "corner" (a
  // wedge's apex) or "curved surface" (a cylinder's), from the shape's outline.
  std::optional<Obstacle> obstacle;
  std::array<double, 2> struck_at = {0, 0};
  std::string struck;
};

std::vector<std::string> collision_pair_names();
// The option that sets a law's or a shape's key: --characteristic-velocity for
// characteristic_velocity, --half-angle for half_angle.
std::string key_option(const char* key);
// The size collide gives an obstacle's key that no option sets: the key's own default
// where it has one, else 10 particle diameters for a length (the cylinder's D, and the
// scale of every shape alike) or the middle of an angle's range (a wedge's 45 degrees).
double collision_shape_size(const ShapeKey& key);
// What collide accepts for the key, as its help and refusals say: "[0.001, 1] m" or
// "(0, 90) degrees".
std::string collision_shape_range(const ShapeKey& key);
// Throws UserError for an unknown pair, a non-positive speed or dt, e outside (0, 1], a
// time step past the stable limit or an impact past the contact law's range (peak overlap
// beyond kOverlapRefuse of a diameter) without `force`, a dt that needs more than
// kMaxCollisionSteps steps, or particles that passed through each other; for a shape or
// a size with two particles, a size of another shape or out of its range, or an obstacle
// whose surface on the line of impact is not across it (a slanted face: docs/design.md,
// "collide").
CollisionResult run_head_on_collision(const CollisionOptions& options);
// The same experiment for species a against species b of any setup, or against its
// obstacle's material (b = -1) as a cylinder of 10 d_max, whatever the setup's shape
// (the contact law is the same for every shape), with that setup's contact parameters
// (its calibrated damping, if any);
// dt = 0 picks t_c/100. The first contact step overlaps by phase x speed x dt. The serial
// backend gives the same numbers bit for bit (docs/design.md, "The solver") without a parallel
// region per step, for the many small collisions of summary.json.
CollisionResult collide_species(const SolverSetup& setup, int a, int b, double speed, double dt,
                                bool force, double phase = 1.0, const ImpactPlace& place = {},
                                Backend backend = Backend::default_space);
std::string to_json(const CollisionResult& r);
// One pair's damping calibration (restitution_calibration.hpp), as `collide` and
// summary.json's `restitution_calibration` print it.
nlohmann::json to_json(const PairCalibration& calibration, double calibration_speed);

}  // namespace granshock
