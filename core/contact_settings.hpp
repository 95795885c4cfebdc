// How a scene's particles touch: which contact law (docs/design.md, "Contact models"), its
// options, and the restitution and friction of every pair of species and of each species
// against the obstacle.
#pragma once

#include <array>
#include <string>
#include <vector>

namespace granshock {

// The contact laws granshock compiles; each is a type in kernels/models/ and an entry of
// the variant table (kernels/solver/variant_table.hpp).
enum class ContactModelKind { hertz, hooke, linear };
ContactModelKind parse_contact_model(const std::string& name);  // core/variant_names.hpp
std::string to_string(ContactModelKind model);

// The range of the contact laws, as overlap over the pair's smaller diameter
// (docs/contact_model.md): past kOverlapWarn they lose accuracy; past kOverlapRefuse the
// particles nearly pass through each other, and the law has no meaning. The time-step
// guard applies them to the fastest impact, the checkpoint checks to a stored state.
inline constexpr double kOverlapWarn = 0.05;
inline constexpr double kOverlapRefuse = 0.2;

// The most parameter keys a contact law has (models/law_parameters.hpp).
inline constexpr int kMaxLawParameters = 2;

// What a contact law takes besides the pair's materials and restitution.
struct ContactOptions {
  // Clamp Fn >= 0 (no attraction at the end of a contact). Off by default, as in
  // LIGGGHTS, because only then does the law restore exactly e.
  bool limit_force = false;
  // The law's own parameters in the order of its keys (models/<law>_parameters.hpp:
  // hooke's characteristic velocity, linear's stiffness), read through them
  // (HookeParameters::characteristic_velocity(o), ...); unused by `hertz`.
  std::array<double, kMaxLawParameters> law_parameters{};
};

// How the damping of every pair is chosen (docs/contact_model.md, "Restitution at the
// chosen time step"): `continuous` from e by the law's closed form (LIGGGHTS), exact as
// dt -> 0; `discrete` calibrated at start-up so that the solver's own integrator at the
// run's dt returns e, averaged over the phase of the first contact step.
enum class RestitutionMode { continuous, discrete };
RestitutionMode parse_restitution_mode(const std::string& name);  // core/choice_names.hpp
std::string to_string(RestitutionMode mode);

struct ContactSettings {
  ContactModelKind model = ContactModelKind::hertz;
  ContactOptions options;
  RestitutionMode restitution_mode = RestitutionMode::continuous;
  // discrete: the impact speed the damping is calibrated at (m/s); 0 in a scene means the
  // inflow speed, resolved when the scene is read.
  double calibration_speed_m_per_s = 0;
  // Every Young's modulus (particles and obstacle) divided by this for the contacts
  // (docs/contact_model.md, "Softening"): the collision time grows as softening^(2/5) for
  // Hertz, so dt can grow with it; restitution, masses and sizes are kept. 1: none.
  double softening = 1;
  // discrete, once calibrated (kernels/models/restitution_calibration.hpp): the damping
  // beta every pair runs with, indexed like `restitution`; empty: beta from e.
  std::vector<std::vector<double>> calibrated_beta;
  std::vector<double> obstacle_calibrated_beta;
  // Indexed [species_i][species_j] (symmetric) and [species] for the obstacle.
  std::vector<std::vector<double>> restitution;
  std::vector<std::vector<double>> friction;
  std::vector<double> obstacle_restitution;
  std::vector<double> obstacle_friction;

  static ContactSettings uniform(int n_species, double e, double mu);
  bool has_friction() const;
  // The settings of the species `kept` alone (new index k is old kept[k]), in
  // O(kept.size()^2): one pair's collision must not copy every pair's tables.
  ContactSettings of_species(const std::vector<int>& kept) const;
};

}  // namespace granshock
