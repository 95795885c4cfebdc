#include "cases/study/study_cases.hpp"

#include <fmt/format.h>

#include <map>

#include "core/user_error.hpp"

namespace granshock {

namespace {

std::string file_of(const StudySpec& s) {
  return "study file '" + s.file.string() + "'";
}

std::string key_of(const std::string& assignment) {
  return assignment.substr(0, assignment.find('='));
}

// A case made of one value per axis (-1: the axis is not part of it), named by joining the
// values' labels with '_'.
StudyCase combine(const StudySpec& s, const std::vector<int>& picks) {
  StudyCase c;
  c.axis_value = picks;
  for (std::size_t a = 0; a < s.axes.size(); ++a) {
    if (picks[a] < 0) continue;
    const AxisValue& v = s.axes[a].values[std::size_t(picks[a])];
    c.name += (c.name.empty() ? "" : "_") + v.label;
    c.overrides.insert(c.overrides.end(), v.overrides.begin(), v.overrides.end());
  }
  return c;
}

// In a product or a list every case takes a value of every axis: two axes setting the
// same key would silently override each other.
void refuse_shared_keys(const StudySpec& s) {
  if (s.mode == StudyMode::sweep) return;
  std::map<std::string, std::string> owner;
  for (const StudyAxis& axis : s.axes)
    for (const AxisValue& v : axis.values)
      for (const std::string& o : v.overrides) {
        const auto [it, fresh] = owner.emplace(key_of(o), axis.name);
        if (!fresh && it->second != axis.name)
          throw UserError(fmt::format(
              "{}: axes '{}' and '{}' both set '{}'; in mode \"{}\" every case takes a value of "
              "each axis, so one would override the other",
              file_of(s), it->second, axis.name, key_of(o), to_string(s.mode)));
      }
}

void check_count(const StudySpec& s, double count) {
  if (count > double(kMaxStudyCases))
    throw UserError(fmt::format("{}: {:.0f} cases, more than the {} a study may have", file_of(s),
                                count, kMaxStudyCases));
}

std::vector<StudyCase> axis_cases(const StudySpec& s) {
  std::vector<StudyCase> cases;
  const std::size_t n_axes = s.axes.size();
  if (n_axes == 0) return cases;
  if (s.mode == StudyMode::product) {
    double count = 1;
    for (const StudyAxis& a : s.axes) count *= double(a.values.size());
    check_count(s, count);
    std::vector<int> picks(n_axes, 0);  // an odometer, the first axis turning slowest
    for (;;) {
      cases.push_back(combine(s, picks));
      std::size_t a = n_axes;
      while (a > 0 && ++picks[a - 1] == int(s.axes[a - 1].values.size())) picks[--a] = 0;
      if (a == 0) break;
    }
  } else if (s.mode == StudyMode::list) {
    const std::size_t n = s.axes[0].values.size();
    for (const StudyAxis& a : s.axes)
      if (a.values.size() != n)
        throw UserError(fmt::format(
            "{}: in mode \"list\" every axis needs as many values: '{}' has {}, '{}' has {}",
            file_of(s), s.axes[0].name, n, a.name, a.values.size()));
    for (std::size_t k = 0; k < n; ++k)
      cases.push_back(combine(s, std::vector<int>(n_axes, int(k))));
  } else {
    for (std::size_t a = 0; a < n_axes; ++a)
      for (std::size_t k = 0; k < s.axes[a].values.size(); ++k) {
        std::vector<int> picks(n_axes, -1);
        picks[a] = int(k);
        cases.push_back(combine(s, picks));
      }
  }
  return cases;
}

void number_and_check_names(const StudySpec& s, std::vector<StudyCase>& cases) {
  std::map<std::string, int> first;
  for (std::size_t k = 0; k < cases.size(); ++k) {
    cases[k].index = int(k);
    if (!is_safe_name(cases[k].name))
      throw UserError(fmt::format(
          "{}: case {} is named '{}', which cannot name a directory and a scene (1-64 of "
          "A-Z a-z 0-9 . _ -); give its values shorter labels",
          file_of(s), k,
          cases[k].name.size() > 80 ? cases[k].name.substr(0, 80) + "..." : cases[k].name));
    const auto [it, fresh] = first.emplace(cases[k].name, int(k));
    if (!fresh)
      throw UserError(
          fmt::format("{}: cases --case {} and --case {} are both named '{}'; give their values "
                      "(or [[case]] entries) "
                      "distinct labels",
                      file_of(s), it->second, k, cases[k].name));
  }
}

}  // namespace

std::vector<StudyCase> expand_cases(const StudySpec& s) {
  refuse_shared_keys(s);
  std::vector<StudyCase> cases = axis_cases(s);
  check_count(s, double(cases.size() + s.cases.size()));
  for (const ExplicitCase& e : s.cases) {
    StudyCase c;
    c.name = e.name;
    c.overrides = e.overrides;
    c.axis_value.assign(s.axes.size(), -1);
    cases.push_back(c);
  }
  number_and_check_names(s, cases);
  return cases;
}

std::vector<StudyCase> merge_base_cases(const StudySpec& s, std::vector<StudyCase> cases,
                                        const std::vector<bool>& same_as_base) {
  if (s.mode != StudyMode::sweep) return cases;
  std::vector<StudyCase> out;
  int base = -1;
  for (std::size_t k = 0; k < cases.size(); ++k) {
    const bool from_axis = k < cases.size() - s.cases.size();
    if (!from_axis || !same_as_base[k]) {
      out.push_back(cases[k]);
      continue;
    }
    if (base < 0) {
      base = int(out.size());
      out.push_back(cases[k]);
      out.back().name = kSweepBaseName;
      out.back().overrides.clear();
      continue;
    }
    for (std::size_t a = 0; a < s.axes.size(); ++a)
      if (cases[k].axis_value[a] >= 0)
        out[std::size_t(base)].axis_value[a] = cases[k].axis_value[a];
  }
  number_and_check_names(s, out);
  return out;
}

std::string overrides_text(const std::vector<std::string>& overrides) {
  std::string text;
  for (const std::string& o : overrides) text += (text.empty() ? "" : " ") + o;
  return text.empty() ? std::string("(the base scene)") : text;
}

}  // namespace granshock
