// The physics a scene can choose, as lists of types (docs/design.md, "Adding a contact
// law"): the contact laws, and the obstacle as one compiled body whatever its shape
// (obstacle_body.hpp; the shapes are listed in obstacle_shapes.hpp). The variant table
// compiles each combination (kernels/solver/variant_table.hpp); host code that needs a
// law's formulas without a kernel (the time-step guard) asks with_contact_model. A new
// law is one header, its parameters (if any: <law>_parameters.hpp, listed in
// law_parameters.hpp), its name in core/variant_names.hpp and one entry in ContactLaws here.
#pragma once

#include <optional>
#include <stdexcept>
#include <type_traits>

#include "core/contact_settings.hpp"
#include "core/obstacle.hpp"
#include "core/variant_names.hpp"
#include "kernels/models/contact_law.hpp"
#include "kernels/models/hertz.hpp"
#include "kernels/models/hooke.hpp"
#include "kernels/models/linear.hpp"
#include "kernels/models/no_obstacle.hpp"
#include "kernels/models/obstacle_body.hpp"
#include "models/law_parameters.hpp"
#include "models/obstacle_shapes.hpp"

namespace granshock {

template <class... T>
struct TypeList {};

// Every contact law granshock compiles, each a type of the interface in contact_law.hpp.
using ContactLaws = TypeList<HertzModel, HookeModel, LinearModel>;

namespace models_detail {

template <class... Laws>
constexpr bool every_law_checked(TypeList<Laws...>) {
  return (check_contact_law<Laws>() && ...);
}

// Whether every law's Parameters are what LawParameterSets lists for its kind
// (law_parameters.hpp): the host code reads a law's keys from that list.
template <class... Laws>
constexpr bool every_law_has_its_listed_parameters(TypeList<Laws...>) {
  return (std::is_same_v<typename Laws::Parameters, parameters_of_kind<Laws::kind>> && ...);
}

// How many laws of the list have `kind`.
template <class... Laws>
constexpr int laws_of_kind(ContactModelKind kind, TypeList<Laws...>) {
  return ((Laws::kind == kind ? 1 : 0) + ... + 0);
}

// Whether every name of core/variant_names.hpp has exactly one law: a name without a law
// would be accepted by the scene and refused by the variant table.
constexpr bool every_name_has_one_law() {
  for (const ChoiceName<ContactModelKind>& c : Choices<ContactModelKind>::table)
    if (laws_of_kind(c.value, ContactLaws{}) != 1) return false;
  return true;
}

template <class F, class Law, class... Rest>
decltype(auto) with_law_of_kind(ContactModelKind kind, F& f, TypeList<Law, Rest...>) {
  if constexpr (sizeof...(Rest) == 0) {
    if (kind != Law::kind) throw std::logic_error("with_contact_model: unknown contact model");
    return f(Law{});
  } else {
    if (kind == Law::kind) return f(Law{});
    return with_law_of_kind(kind, f, TypeList<Rest...>{});
  }
}

template <class F, class... Laws>
void each_law(F& f, TypeList<Laws...>) {
  (f(Laws{}), ...);
}

}  // namespace models_detail

static_assert(models_detail::every_law_checked(ContactLaws{}));
static_assert(models_detail::every_law_has_its_listed_parameters(ContactLaws{}),
              "a contact law's Parameters must be listed in LawParameterSets "
              "(models/law_parameters.hpp), the keys the scene reader takes");
static_assert(models_detail::every_name_has_one_law(),
              "every contact model of core/variant_names.hpp needs exactly one law in "
              "ContactLaws (kernels/models/models.hpp)");

// Calls f(Law{}) for every law of ContactLaws, in order (the tests run over the list).
template <class F>
void for_each_contact_law(F&& f) {
  models_detail::each_law(f, ContactLaws{});
}

// Calls f(Model{}) for the scene's contact law.
template <class F>
decltype(auto) with_contact_model(ContactModelKind kind, F&& f) {
  return models_detail::with_law_of_kind(kind, f, ContactLaws{});
}

}  // namespace granshock
