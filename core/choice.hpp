// The names of a choice (docs/design.md, "Names of choices"): every enum a user picks by
// name (a scene key, a command-line option) has one table, Choices<Enum>
// (core/choice_names.hpp), of {value, name, description}. Parsing, writing back, the
// scene schema's list, the command line's check and help, and `granshock info` are all
// derived from it, so a name added to the table is accepted and echoed everywhere, and a
// value missing from it fails to compile where its name is asked for.
#pragma once

#include <cstddef>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/user_error.hpp"

namespace granshock {

template <class Enum>
struct ChoiceName {
  Enum value;
  const char* name;         // as a user writes it, in scenes, on the command line and in output
  const char* description;  // one line, for --help and `granshock info`
};

// Specialised once per choice in core/choice_names.hpp with
//   static constexpr const char* what;         // "contact model": the subject of a refusal
//   static constexpr ChoiceName<Enum> table[];  // every value, in the order the docs list them
template <class Enum>
struct Choices;

// The table's name of `value`; a value without an entry is a compile error where this is
// evaluated as a constant (Model::name), a logic_error otherwise.
template <class Enum>
constexpr const char* choice_name(Enum value) {
  for (const ChoiceName<Enum>& c : Choices<Enum>::table)
    if (c.value == value) return c.name;
  throw std::logic_error("a value missing from its Choices table (core/choice_names.hpp)");
}

template <class Enum>
std::vector<std::string> choice_names() {
  std::vector<std::string> names;
  for (const ChoiceName<Enum>& c : Choices<Enum>::table) names.emplace_back(c.name);
  return names;
}

// "hertz, hooke": the names as a refusal lists them.
template <class Enum>
std::string choice_list() {
  std::string list;
  for (const ChoiceName<Enum>& c : Choices<Enum>::table)
    list += (list.empty() ? "" : ", ") + std::string(c.name);
  return list;
}

// "hertz: ...; hooke: ...": every name with its description, for --help.
template <class Enum>
std::string choice_help() {
  std::string help;
  for (const ChoiceName<Enum>& c : Choices<Enum>::table)
    help += (help.empty() ? "" : "; ") + std::string(c.name) + ": " + c.description;
  return help;
}

// The value named `name`; a UserError naming every valid name otherwise.
template <class Enum>
Enum parse_choice(const std::string& name) {
  for (const ChoiceName<Enum>& c : Choices<Enum>::table)
    if (name == c.name) return c.value;
  throw UserError(std::string(Choices<Enum>::what) + " '" + name + "' is not one of " +
                  choice_list<Enum>());
}

// Two names equal as constants (std::string_view's compare is not constexpr for every
// compiler the kernels are built with).
constexpr bool same_name(const char* a, const char* b) {
  std::size_t i = 0;
  for (; a[i] != '\0' && a[i] == b[i]; ++i) {
  }
  return a[i] == b[i];
}

// Whether the table names each value once and gives each name once.
template <class Enum>
constexpr bool choice_table_is_one_to_one() {
  constexpr std::size_t n = sizeof(Choices<Enum>::table) / sizeof(Choices<Enum>::table[0]);
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 1; j < n; ++j)
      if (Choices<Enum>::table[i].value == Choices<Enum>::table[j].value ||
          same_name(Choices<Enum>::table[i].name, Choices<Enum>::table[j].name))
        return false;
  return true;
}

}  // namespace granshock
