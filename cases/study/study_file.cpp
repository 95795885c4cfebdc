// Reading a study file (docs/study.md, "The study file"): the tables and their keys. The
// values of the axes are turned into overrides by axis_values.cpp.
#include "cases/study/study_file.hpp"

#include <fmt/format.h>

#include <toml++/toml.h>
#include <cctype>
#include <cstring>
#include <set>

#include "cases/study/axis_values.hpp"
#include "core/shell_text.hpp"
#include "core/user_error.hpp"
#include "io/regular_file.hpp"

namespace granshock {

namespace fs = std::filesystem;

namespace {

// The keys a table accepts; any other ends the reading with the accepted ones listed.
void check_keys(const toml::table& table, const std::set<std::string>& accepted,
                const std::string& where) {
  for (const auto& [key, node] : table) {
    if (accepted.count(std::string(key.str()))) continue;
    std::string list;
    for (const std::string& a : accepted) list += (list.empty() ? "" : ", ") + a;
    throw UserError(fmt::format("{}: unknown key '{}' (accepted: {})", where, key.str(), list));
  }
}

std::string required_string(const toml::table& table, const std::string& key,
                            const std::string& where) {
  const toml::node* n = table.get(key);
  if (!n) throw UserError(fmt::format("{}: '{}' is required", where, key));
  if (!n->is_string()) throw UserError(fmt::format("{}: '{}' must be a string", where, key));
  return n->as_string()->get();
}

std::string safe_name_or_fail(const std::string& name, const std::string& what,
                              const std::string& where) {
  if (!is_safe_name(name))
    throw UserError(
        fmt::format("{}: {} '{}' must be 1-64 of A-Z a-z 0-9 . _ - and not start with '.' or '-'",
                    where, what, name.size() > 80 ? name.substr(0, 80) + "..." : name));
  return name;
}

StudyMode parse_mode(const toml::table& study, const std::string& where) {
  const toml::node* n = study.get("mode");
  if (!n) return StudyMode::product;
  const std::string mode = n->value<std::string>().value_or("");
  if (mode == "product") return StudyMode::product;
  if (mode == "list" || mode == "zip") return StudyMode::list;
  if (mode == "sweep") return StudyMode::sweep;
  throw UserError(fmt::format(
      "{}: mode must be \"product\" (every combination of the axes), \"list\" or \"zip\" (the "
      "k-th values together) or \"sweep\" (each axis alone around the base scene)",
      where));
}

const toml::array* array_of_tables(const toml::table& root, const std::string& key,
                                   const std::string& where) {
  const toml::node* n = root.get(key);
  if (!n) return nullptr;
  const toml::array* a = n->as_array();
  if (!a || !a->is_array_of_tables())
    throw UserError(fmt::format("{}: '{}' must be written as [[{}]] tables", where, key, key));
  return a;
}

StudyAxis read_axis(const toml::table& t, int index, const std::string& file) {
  std::string where = fmt::format("{}: [[axis]] {}", file, index + 1);
  check_keys(t, {"name", "key", "values"}, where);
  StudyAxis axis;
  axis.name = safe_name_or_fail(required_string(t, "name", where), "axis name", where);
  where += " ('" + axis.name + "')";
  const toml::node* values = t.get("values");
  if (!values || !values->is_array())
    throw UserError(fmt::format("{}: 'values' is required: an array of values", where));
  if (values->as_array()->empty())
    throw UserError(fmt::format("{}: 'values' is empty; an axis needs at least one value", where));
  const toml::node* key = t.get("key");
  if (key && !key->is_string())
    throw UserError(fmt::format("{}: 'key' must be a string naming a scene key", where));
  int k = 0;
  for (const toml::node& v : *values->as_array()) {
    const std::string at = fmt::format("{} value {}", where, ++k);
    if (key) {
      axis.values.push_back(shorthand_value(axis.name, key->as_string()->get(), v, at));
    } else if (const toml::table* table = v.as_table()) {
      axis.values.push_back(table_value(*table, at));
    } else {
      throw UserError(fmt::format(
          "{}: without 'key', every value must be a table of overrides with a label, e.g. "
          "{{ label = \"u1\", inflow.velocity = 1.0, inflow.mach = 5.9 }}",
          at));
    }
  }
  return axis;
}

std::vector<std::string> read_set(const toml::table& t, const std::string& where) {
  std::vector<std::string> out;
  const toml::node* set = t.get("set");
  if (!set) return out;
  const toml::array* a = set->as_array();
  if (!a || !a->is_homogeneous<std::string>())
    throw UserError(fmt::format(
        "{}: 'set' must be an array of \"key=value\" strings, as --set takes them", where));
  for (const toml::node& s : *a) {
    const std::string text = s.as_string()->get();
    if (text.find('=') == std::string::npos || text[0] == '=')
      throw UserError(
          fmt::format("{}: set '{}': expected key=value (e.g. inflow.mach=13.7)", where, text));
    out.push_back(text);
  }
  return out;
}

ExplicitCase read_case(const toml::table& t, int index, const std::string& file) {
  std::string where = fmt::format("{}: [[case]] {}", file, index + 1);
  check_keys(t, {"name", "set"}, where);
  ExplicitCase c;
  c.name = safe_name_or_fail(required_string(t, "name", where), "case name", where);
  c.overrides = read_set(t, where + " ('" + c.name + "')");
  return c;
}

SlurmSettings read_slurm(const toml::table& root, const std::string& file) {
  SlurmSettings s;
  const toml::node* n = root.get("slurm");
  if (!n) return s;
  const std::string where = file + ": [slurm]";
  if (!n->is_table()) throw UserError(where + ": must be a table");
  const toml::table& t = *n->as_table();
  check_keys(t, {"cpus_per_task", "options"}, where);
  if (const toml::node* c = t.get("cpus_per_task")) {
    const auto v = c->value_exact<int64_t>();
    if (!v || *v < 1 || *v > 4096)
      throw UserError(where + ": cpus_per_task must be a whole number from 1 to 4096");
    s.cpus_per_task = int(*v);
  }
  if (const toml::node* o = t.get("options")) {
    const toml::array* a = o->as_array();
    if (!a || !a->is_homogeneous<std::string>())
      throw UserError(where +
                      ": options must be an array of strings, e.g. [\"--partition=short\"]");
    for (const toml::node& opt : *a) {
      const std::string text = opt.as_string()->get();
      if (text.rfind("--", 0) != 0 || has_control_character(text))
        throw UserError(
            fmt::format("{}: option {} must be one sbatch option starting with --, without control "
                        "characters (it is written on an #SBATCH line)",
                        where, shell_quote(text)));
      s.options.push_back(text);
    }
  }
  return s;
}

}  // namespace

std::string to_string(StudyMode mode) {
  switch (mode) {
    case StudyMode::product:
      return "product";
    case StudyMode::list:
      return "list";
    case StudyMode::sweep:
      return "sweep";
  }
  return "product";
}

StudySpec parse_study(const std::string& text, const fs::path& path) {
  const std::string file = "study file '" + path.string() + "'";
  toml::table root;
  try {
    root = toml::parse(text, path.string());
  } catch (const toml::parse_error& e) {
    throw UserError(fmt::format("{}:{}:{}: not valid TOML: {}", file, e.source().begin.line,
                                e.source().begin.column, std::string(e.description())));
  }
  check_keys(root, {"study", "axis", "case", "slurm"}, file);
  const toml::table* study = root.get_as<toml::table>("study");
  if (!study) throw UserError(file + ": needs a [study] table with name and base");
  const std::string where = file + ": [study]";
  check_keys(*study, {"name", "base", "out", "mode", "set", "records"}, where);

  StudySpec s;
  s.file = path;
  s.name = safe_name_or_fail(required_string(*study, "name", where), "name", where);
  const fs::path base = required_string(*study, "base", where);
  s.base = (base.is_absolute() ? base : path.parent_path() / base).lexically_normal();
  s.out = study->contains("out") ? fs::path(required_string(*study, "out", where))
                                 : fs::path("runs") / s.name;
  if (s.out.empty()) throw UserError(where + ": out is empty");
  if (study->contains("records")) {
    const fs::path records = required_string(*study, "records", where);
    if (records.empty()) throw UserError(where + ": records is empty");
    s.records = (records.is_absolute() ? records : path.parent_path() / records).lexically_normal();
  }
  s.mode = parse_mode(*study, where);
  s.common = read_set(*study, where);
  if (const toml::array* axes = array_of_tables(root, "axis", file))
    for (std::size_t k = 0; k < axes->size(); ++k)
      s.axes.push_back(read_axis(*axes->get(k)->as_table(), int(k), file));
  if (const toml::array* cases = array_of_tables(root, "case", file))
    for (std::size_t k = 0; k < cases->size(); ++k)
      s.cases.push_back(read_case(*cases->get(k)->as_table(), int(k), file));
  s.slurm = read_slurm(root, file);

  std::set<std::string> names;
  for (const StudyAxis& a : s.axes)
    if (!names.insert(a.name).second)
      throw UserError(fmt::format("{}: two axes are named '{}'", file, a.name));
  if (s.axes.empty() && s.cases.empty())
    throw UserError(file + ": defines no case: give [[axis]] tables or [[case]] entries");
  return s;
}

StudySpec load_study_file(const fs::path& path) {
  const std::string text = read_regular_file(path, "study file", kMaxStudyFileBytes);
  return parse_study(text, path);
}

}  // namespace granshock
