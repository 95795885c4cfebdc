#include "accuracy_table.hpp"

#include <fmt/format.h>

#include <cmath>
#include <limits>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <sstream>

#include "json_file.hpp"
#include "user_error.hpp"

namespace granshock {

namespace {

using nlohmann::json;

std::optional<double> number_at(const json& row, const std::string& key) {
  const auto it = row.find(key);
  if (it == row.end() || !it->is_number()) return std::nullopt;
  return it->get<double>();
}

std::vector<std::string> words(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string w; in >> w;) out.push_back(w);
  return out;
}

}  // namespace

AccuracyTable read_accuracy_table(const std::filesystem::path& path) {
  const auto fail = [&](const std::string& why) {
    return UserError(fmt::format("accuracy table {}: {}", path.string(), why));
  };
  std::error_code ec;
  if (!std::filesystem::exists(path, ec))
    throw fail("cannot be read (make one with `granshock tradeoff SCENE.toml`)");
  JsonFile file = read_json_file(path);
  if (file.value.is_discarded()) throw fail("is not JSON: " + file.error);
  json doc = std::move(file.value);
  if (!doc.contains("cases") || !doc["cases"].is_array() || !doc.contains("noise"))
    throw fail("has no \"cases\" and \"noise\" (not a trade.json of granshock tradeoff)");

  std::map<std::string, json> by_name;
  for (const json& row : doc["cases"])
    if (row.contains("case") && row["case"].is_string()) by_name[row["case"]] = row;
  for (const char* needed : {"reference", "scene", "seed-2"})
    if (!by_name.count(needed)) throw fail(fmt::format("has no case \"{}\"", needed));
  const json& reference = by_name["reference"];

  AccuracyTable table;
  table.source = path;
  // Relative noise of every answer the reference measured; an answer it lacks (no front)
  // bounds nothing.
  std::map<std::string, double> reference_value, relative_noise;
  for (const std::string& answer : kBudgetAnswers) {
    const auto value = number_at(reference, answer);
    const auto noise = number_at(doc["noise"], answer);
    if (!value || *value == 0 || !noise) continue;
    reference_value[answer] = std::abs(*value);
    relative_noise[answer] = *noise / std::abs(*value);
    if (relative_noise[answer] > table.noise_floor) {
      table.noise_floor = relative_noise[answer];
      table.noise_floor_by = answer;
    }
  }

  for (const json& row : doc["cases"]) {
    MeasuredSetting s;
    s.name = row.value("case", "");
    const auto dt_over_tc = number_at(row, "dt_over_tc");
    const auto softening = number_at(row, "softening");
    const auto speedup = number_at(row, "speedup");
    const auto e_eff = number_at(row, "e_eff_error");
    if (!dt_over_tc || !softening || !speedup || !e_eff || !row.contains("precision"))
      throw fail(fmt::format(
          "case \"{}\" lacks dt_over_tc, softening, precision, speedup or e_eff_error (a table "
          "from before they were recorded: run cases/tradeoff/trade_table.py again)",
          s.name));
    s.changed = words(row.value("changed", ""));
    s.dt_over_tc = *dt_over_tc;
    s.softening = *softening;
    s.single_precision = row["precision"] == "single";
    s.speedup = *speedup;
    s.e_eff_error = *e_eff;
    s.error_bound = s.e_eff_error;
    s.bound_by = "e_eff";
    for (const auto& [answer, ref] : reference_value) {
      const auto diff = number_at(row, "diff." + answer);
      const double bound = diff ? std::max(*diff / ref, relative_noise[answer])
                                : std::numeric_limits<double>::infinity();
      if (bound > s.error_bound) {
        s.error_bound = bound;
        s.bound_by = answer;
      }
    }
    table.settings.push_back(s);
  }
  return table;
}

}  // namespace granshock
