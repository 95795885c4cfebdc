// The parameter keys of every contact law, for the host code that reads, checks and
// writes them without the laws' kernels (docs/design.md, "Adding a contact law"): the
// scene schema, collide's options. Plain C++. A law with parameters lists its parameter
// header here; models.hpp checks at compile time that every law of ContactLaws has the
// parameters listed for its kind.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <type_traits>
#include <vector>

#include "core/contact_settings.hpp"
#include "models/hooke_parameters.hpp"
#include "models/law_key.hpp"
#include "models/linear_parameters.hpp"

namespace granshock {

template <class... P>
struct ParameterList {};

using LawParameterSets = ParameterList<HookeParameters, LinearParameters>;

namespace law_parameters_detail {

template <class F>
void with_kind(ContactModelKind, F& f, ParameterList<>) {
  f(NoLawParameters{});
}
template <class F, class P, class... Rest>
void with_kind(ContactModelKind kind, F& f, ParameterList<P, Rest...>) {
  if (kind == P::kind) return f(P{});
  with_kind(kind, f, ParameterList<Rest...>{});
}

template <ContactModelKind K, class List>
struct ParametersOf;
template <ContactModelKind K>
struct ParametersOf<K, ParameterList<>> {
  using type = NoLawParameters;
};
template <ContactModelKind K, class P, class... Rest>
struct ParametersOf<K, ParameterList<P, Rest...>> {
  using type =
      std::conditional_t<P::kind == K, P, typename ParametersOf<K, ParameterList<Rest...>>::type>;
};

template <class F, class... P>
void each(F& f, ParameterList<P...>) {
  (f(P{}), ...);
}

template <class... P>
constexpr bool fits(ParameterList<P...>) {
  return ((P::keys.size() <= std::size_t(kMaxLawParameters)) && ...);
}

}  // namespace law_parameters_detail

// The parameters of the law `K`, listed in LawParameterSets (NoLawParameters if none).
template <ContactModelKind K>
using parameters_of_kind = typename law_parameters_detail::ParametersOf<K, LawParameterSets>::type;

static_assert(law_parameters_detail::fits(LawParameterSets{}),
              "a law has more parameter keys than ContactOptions::law_parameters holds: raise "
              "kMaxLawParameters (core/contact_settings.hpp)");

// Calls f(P{}) with the parameters of the law `kind` (NoLawParameters for a law without).
template <class F>
void with_law_parameters(ContactModelKind kind, F&& f) {
  law_parameters_detail::with_kind(kind, f, LawParameterSets{});
}

// Calls f(P{}) for the parameters of every law that has some.
template <class F>
void for_each_law_parameters(F&& f) {
  law_parameters_detail::each(f, LawParameterSets{});
}

// The index of the key `name` among the keys of the law `kind`; nullopt where it has none
// so named.
inline std::optional<std::size_t> law_key_index(ContactModelKind kind, const std::string& name) {
  std::optional<std::size_t> index;
  with_law_parameters(kind, [&](auto parameters) {
    // A range-for: an index loop compares i < 0 for a law without keys, which nvcc warns of.
    std::size_t i = 0;
    for (const LawKey& key : parameters.keys) {
      if (name == key.name) index = i;
      ++i;
    }
  });
  return index;
}

// The laws with a key `name`, in the order of LawParameterSets (as refusals name them).
inline std::vector<ContactModelKind> laws_with_key(const std::string& name) {
  std::vector<ContactModelKind> laws;
  for_each_law_parameters([&](auto parameters) {
    if (law_key_index(parameters.kind, name)) laws.push_back(parameters.kind);
  });
  return laws;
}

}  // namespace granshock
