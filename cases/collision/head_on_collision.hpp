// `granshock collide`: a head-on impact of two particles, or of a particle on the fixed
// cylinder, run through the same solver variants and kernels as a full simulation.
// It measures what the contact law does at a given time step: the effective
// restitution, the contact duration and the peak overlap.
#pragma once

#include <array>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "core/solver.hpp"
#include "core/solver_setup.hpp"
#include "kernels/models/restitution_calibration.hpp"
#include "kernels/models/time_step_guard.hpp"

namespace granshock {

// Where an impact happens: the point of first contact of two particles, or the
// cylinder's axis, and the axis along which the bodies approach (0 = x, 1 = y). Far from
// the origin (the paper's box spans 0.5 m) it shows what the precision of positions
// costs: docs/design.md, "Particles".
struct ImpactPlace {
  std::array<double, 2> centre = {0, 0};  // m
  int axis = 0;
};

struct CollisionOptions {
  std::string pair = "steel-steel";  // a-b for two particles, a-obstacle for the cylinder
  double speed_m_per_s = 1.0;        // relative normal approach speed
  std::optional<double> dt;          // none: t_c / 100
  double restitution = 0.5;
  ContactModelKind model = ContactModelKind::hertz;
  // The law's parameters by key name (kernels/models/law_parameters.hpp), as the options
  // --<key> gave them: hooke's characteristic_velocity (none: the impact speed), linear's
  // stiffness (required). A key of another law is refused.
  std::map<std::string, std::optional<double>> law_parameters;
  bool limit_force = false;
  Precision precision = Precision::double_precision;
  bool force = false;  // run even past the stable time step
  RestitutionMode restitution_mode = RestitutionMode::continuous;
  // The first contact step overlaps by phase x speed x dt, phase in (0, 1].
  double phase = 1.0;
  ImpactPlace place;
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
};

std::vector<std::string> collision_pair_names();
// Throws UserError for an unknown pair, a non-positive speed or dt, e outside (0, 1], a
// time step past the stable limit or an impact past the contact law's range (peak overlap
// beyond kOverlapRefuse of a diameter) without `force`, a dt that needs more than
// kMaxCollisionSteps steps, or particles that passed through each other.
CollisionResult run_head_on_collision(const CollisionOptions& options);
// The same experiment for species a against species b of any setup, or against its
// obstacle (b = -1), with that setup's contact parameters (its calibrated damping, if any);
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
