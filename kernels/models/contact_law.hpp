// What a contact law is (docs/design.md, "Adding a contact law"): a struct of static
// members, no state, one per law in kernels/models/ (hertz.hpp, hooke.hpp), listed in
// ContactLaws (models.hpp). The solver, the time-step guard and the restitution
// calibration use a law only through the 14 members below; check_contact_law<Law>()
// names the first one a law lacks, at compile time.
//
// Conventions: SI units; n is the unit vector from the partner j to the particle i; the
// overlap dn = r_i + r_j - |x_i - x_j| > 0 while they touch; vn = (v_i - v_j) . n, < 0
// while they approach. A pair's PairProperties (core/pair_properties.hpp) hold Y*, G*,
// R*, m*, the restitution's beta and mu; for the obstacle R* = r_i and m* = m_i.
// Real is float or double, the precision of the kernels (numerics.precision).
//
//   struct Law {
//     // Host. The law's name in scenes (contact.model), on the command line
//     // (collide --model), in output and in the variant's name; written as
//     // choice_name(ContactModelKind::law), its entry in core/variant_names.hpp.
//     static constexpr const char* name;
//     // Host. The enumerator of ContactModelKind (core/contact_settings.hpp) a scene
//     // selects the law by.
//     static constexpr ContactModelKind kind;
//
//     // Per-pair constants, computed once on the host per pair of species and per species
//     // against the obstacle, kept in the force kernel's pair table (solver/pair_table.hpp)
//     // and copied to the device: trivially copyable, Real members only. Must hold
//     // `friction` (mu, the Coulomb limit of the tangential force).
//     template <class Real> struct Coefficients;
//     // What normal() returns: `force`, the normal force in N, signed along n (> 0 pushes
//     // i away from j), and whatever tangential() reuses (hertz keeps sqrt(dn)).
//     template <class Real> struct Normal;
//     // What tangential() returns: `kt` (N/m) and `gt` (kg/s), the stiffness and damping
//     // of the tangential spring with history (tangential_spring.hpp).
//     template <class Real> struct Spring;
//
//     // Host. The constants of one pair (template argument Real given explicitly).
//     template <class Real>
//     static Coefficients<Real> coefficients(const PairProperties&, const ContactOptions&);
//     // Device (KOKKOS_FORCEINLINE_FUNCTION, no host call): the normal force at overlap
//     // dn (m) and normal speed vn (m/s), unclamped. The force kernel calls it for every
//     // contact of every step through clamped_normal (clamped_normal.hpp), which applies
//     // ContactOptions::limit_force for every law.
//     template <class Real>
//     static Normal<Real> normal(const Coefficients<Real>&, Real dn, Real vn);
//     // Device: the tangential spring at the contact normal() just evaluated.
//     template <class Real>
//     static Spring<Real> tangential(const Coefficients<Real>&, const Normal<Real>&);
//     // Device: the elastic energy (J) of one contact at overlap dn (m), for the energy
//     // diagnostics; in double whatever Real is.
//     template <class Real>
//     static double elastic_energy(const Coefficients<Real>&, double dn);
//
//     // Host, for the time-step guard (time_step_guard.hpp) and the restitution
//     // calibration (restitution_calibration.hpp); v is the relative normal impact speed
//     // (m/s), and the damping is the pair's beta.
//     // The duration of a head-on impact at speed v (s).
//     static double collision_time(const PairProperties&, const ContactOptions&, double v);
//     // The largest overlap of an undamped impact at speed v (m).
//     static double peak_overlap(const PairProperties&, const ContactOptions&, double v);
//     // The normal and tangential stiffness (N/m) at that overlap: the linearised law whose
//     // oscillation sets velocity Verlet's stable time step.
//     static double peak_normal_stiffness(const PairProperties&, const ContactOptions&,
//                                         double v);
//     static double peak_tangential_stiffness(const PairProperties&, const ContactOptions&,
//                                             double v);
//     // The damping ratio zeta of the linearised law (dimensionless, >= 0 for 0 < e <= 1).
//     static double damping_ratio(const PairProperties&);
//   };
//
// Each member is detected below (the C++17 detection idiom: std::void_t over the member's
// use, as the kernels use it), so that a law lacking one fails with a message naming it
// rather than deep inside the solver's templates (the messages quote with ', which nvcc
// prints as it is).
#pragma once

#include <type_traits>
#include <utility>

#include "core/contact_settings.hpp"
#include "core/pair_properties.hpp"
#include "core/variant_names.hpp"

namespace granshock {
namespace contact_law_detail {

template <class Law, class Real>
using CoefficientsOf = typename Law::template Coefficients<Real>;

// trait<Law, Real>::value: whether the expression (the member's use) compiles.
#define GRANSHOCK_CONTACT_LAW_MEMBER(trait, ...) \
  template <class Law, class Real, class = void> \
  struct trait : std::false_type {};             \
  template <class Law, class Real>               \
  struct trait<Law, Real, std::void_t<decltype(__VA_ARGS__)>> : std::true_type {};

GRANSHOCK_CONTACT_LAW_MEMBER(has_name, std::declval<const char*&>() = Law::name)
GRANSHOCK_CONTACT_LAW_MEMBER(has_kind, std::declval<ContactModelKind&>() = Law::kind)
GRANSHOCK_CONTACT_LAW_MEMBER(has_coefficients_type,
                             std::declval<CoefficientsOf<Law, Real>&>().friction)
GRANSHOCK_CONTACT_LAW_MEMBER(has_normal_type,
                             std::declval<typename Law::template Normal<Real>&>().force)
GRANSHOCK_CONTACT_LAW_MEMBER(has_spring_type,
                             (std::declval<typename Law::template Spring<Real>&>().kt,
                              std::declval<typename Law::template Spring<Real>&>().gt))
GRANSHOCK_CONTACT_LAW_MEMBER(
    has_coefficients,
    std::declval<CoefficientsOf<Law, Real>&>() = Law::template coefficients<Real>(
        std::declval<const PairProperties&>(), std::declval<const ContactOptions&>()))
GRANSHOCK_CONTACT_LAW_MEMBER(
    has_normal,
    std::declval<Real&>() =
        Law::normal(std::declval<const CoefficientsOf<Law, Real>&>(), Real(), Real()).force)
GRANSHOCK_CONTACT_LAW_MEMBER(
    has_tangential,
    std::declval<Real&>() =
        Law::tangential(std::declval<const CoefficientsOf<Law, Real>&>(),
                        Law::normal(std::declval<const CoefficientsOf<Law, Real>&>(), Real(),
                                    Real()))
            .kt)
GRANSHOCK_CONTACT_LAW_MEMBER(has_elastic_energy,
                             std::declval<double&>() = Law::elastic_energy(
                                 std::declval<const CoefficientsOf<Law, Real>&>(), 0.0))
GRANSHOCK_CONTACT_LAW_MEMBER(has_collision_time, std::declval<double&>() = Law::collision_time(
                                                     std::declval<const PairProperties&>(),
                                                     std::declval<const ContactOptions&>(), 0.0))
GRANSHOCK_CONTACT_LAW_MEMBER(has_peak_overlap, std::declval<double&>() = Law::peak_overlap(
                                                   std::declval<const PairProperties&>(),
                                                   std::declval<const ContactOptions&>(), 0.0))
GRANSHOCK_CONTACT_LAW_MEMBER(has_peak_normal_stiffness,
                             std::declval<double&>() = Law::peak_normal_stiffness(
                                 std::declval<const PairProperties&>(),
                                 std::declval<const ContactOptions&>(), 0.0))
GRANSHOCK_CONTACT_LAW_MEMBER(has_peak_tangential_stiffness,
                             std::declval<double&>() = Law::peak_tangential_stiffness(
                                 std::declval<const PairProperties&>(),
                                 std::declval<const ContactOptions&>(), 0.0))
GRANSHOCK_CONTACT_LAW_MEMBER(has_damping_ratio, std::declval<double&>() = Law::damping_ratio(
                                                    std::declval<const PairProperties&>()))

#undef GRANSHOCK_CONTACT_LAW_MEMBER

// The members of one precision, each assertion naming the member it misses.
template <class Law, class Real>
constexpr bool check_members() {
  static_assert(has_coefficients_type<Law, Real>::value,
                "a contact law needs 'template <class Real> struct Coefficients' with a "
                "'friction' member (kernels/models/contact_law.hpp)");
  static_assert(has_normal_type<Law, Real>::value,
                "a contact law needs 'template <class Real> struct Normal' with a 'force' "
                "member (kernels/models/contact_law.hpp)");
  static_assert(has_spring_type<Law, Real>::value,
                "a contact law needs 'template <class Real> struct Spring' with 'kt' and "
                "'gt' members (kernels/models/contact_law.hpp)");
  static_assert(has_coefficients<Law, Real>::value,
                "a contact law needs 'template <class Real> static Coefficients<Real> "
                "coefficients(const PairProperties&, const ContactOptions&)' "
                "(kernels/models/contact_law.hpp)");
  static_assert(has_normal<Law, Real>::value,
                "a contact law needs 'static Normal<Real> normal(const Coefficients<Real>&, "
                "Real dn, Real vn)', a device function (kernels/models/contact_law.hpp)");
  static_assert(has_tangential<Law, Real>::value,
                "a contact law needs 'static Spring<Real> tangential(const "
                "Coefficients<Real>&, const Normal<Real>&)', a device function "
                "(kernels/models/contact_law.hpp)");
  static_assert(has_elastic_energy<Law, Real>::value,
                "a contact law needs 'static double elastic_energy(const Coefficients<Real>&, "
                "double dn)', a device function (kernels/models/contact_law.hpp)");
  return true;
}

}  // namespace contact_law_detail

// True, or a compile error naming the member Law lacks (used in models.hpp for every law
// of ContactLaws).
template <class Law>
constexpr bool check_contact_law() {
  using namespace contact_law_detail;
  static_assert(has_name<Law, double>::value,
                "a contact law needs 'static constexpr const char* name' "
                "(kernels/models/contact_law.hpp)");
  static_assert(has_kind<Law, double>::value,
                "a contact law needs 'static constexpr ContactModelKind kind' "
                "(kernels/models/contact_law.hpp)");
  static_assert(has_collision_time<Law, double>::value,
                "a contact law needs 'static double collision_time(const PairProperties&, "
                "const ContactOptions&, double v)' (kernels/models/contact_law.hpp)");
  static_assert(has_peak_overlap<Law, double>::value,
                "a contact law needs 'static double peak_overlap(const PairProperties&, "
                "const ContactOptions&, double v)' (kernels/models/contact_law.hpp)");
  static_assert(has_peak_normal_stiffness<Law, double>::value,
                "a contact law needs 'static double peak_normal_stiffness(const "
                "PairProperties&, const ContactOptions&, double v)' "
                "(kernels/models/contact_law.hpp)");
  static_assert(has_peak_tangential_stiffness<Law, double>::value,
                "a contact law needs 'static double peak_tangential_stiffness(const "
                "PairProperties&, const ContactOptions&, double v)' "
                "(kernels/models/contact_law.hpp)");
  static_assert(has_damping_ratio<Law, double>::value,
                "a contact law needs 'static double damping_ratio(const PairProperties&)' "
                "(kernels/models/contact_law.hpp)");
  static_assert(check_members<Law, float>() && check_members<Law, double>());
  if constexpr (has_name<Law, double>::value && has_kind<Law, double>::value)
    static_assert(same_name(Law::name, choice_name(Law::kind)),
                  "a contact law's name must be its ContactModelKind's name in "
                  "core/variant_names.hpp: write name = choice_name(kind)");
  return true;
}

}  // namespace granshock
