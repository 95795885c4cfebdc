#include "cases/accuracy/accuracy_table.hpp"

#include <fmt/format.h>

#include <cmath>
#include <limits>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <sstream>

#include "analysis/json_file.hpp"
#include "core/choice_names.hpp"
#include "core/quoted_input.hpp"
#include "core/user_error.hpp"

namespace granshock {

namespace {

using nlohmann::json;

// Ranges of a case's columns, as a scene's (docs/scene_format.md): a value outside them
// was measured by no run, and used as given it ended in an internal error or a time step
// of 1e-320 s.
constexpr double kMaxDtOverTc = 10;        // past the stable limit of any contact law
constexpr double kMinDtOverTc = 1e-6;      // a million steps per contact
constexpr double kMaxSoftening = 1e9;      // contact.softening
constexpr double kMaxSpeedup = 1e6;        // of one case over another
constexpr double kMaxRate = 1e15;          // particle-steps per second
constexpr double kMaxRelativeError = 1e6;  // e_eff error, differences over the reference

// Every refusal: "accuracy table PATH: WHAT", one line.
class TableFail {
 public:
  explicit TableFail(const std::filesystem::path& path) : path_(path) {}
  [[noreturn]] void operator()(const std::string& why) const {
    throw UserError(fmt::format("accuracy table {}: {}", path_.string(), why));
  }

 private:
  const std::filesystem::path& path_;
};

// A member that must be a finite number in [lo, hi], or absent/null when optional.
std::optional<double> number_at(const TableFail& fail, const json& row, const std::string& where,
                                const std::string& key, double lo, double hi, bool required) {
  const auto it = row.find(key);
  if (it == row.end() || it->is_null()) {
    if (required)
      fail(
          fmt::format("{} lacks \"{}\" (a table from before it was recorded: run "
                      "cases/tradeoff/trade_table.py again)",
                      where, key));
    return std::nullopt;
  }
  if (!it->is_number())
    fail(fmt::format("{}: \"{}\" = {} must be a number", where, key, it->dump()));
  const double v = it->get<double>();
  // Subnormal numbers (a dt_over_tc of 1e-320) are below every lower bound here but 0.
  if (!std::isfinite(v) || v < lo || v > hi || (v != 0 && std::abs(v) < 1e-300))
    fail(fmt::format("{}: \"{}\" = {} must be a number in [{:g}, {:g}]", where, key, it->dump(), lo,
                     hi));
  return v;
}

std::string string_at(const TableFail& fail, const json& row, const std::string& where,
                      const std::string& key, const std::string& fallback) {
  const auto it = row.find(key);
  if (it == row.end()) return fallback;
  if (!it->is_string())
    fail(fmt::format("{}: \"{}\" = {} must be a string", where, key, it->dump()));
  return it->get<std::string>();
}

std::vector<std::string> words(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string w; in >> w;) out.push_back(w);
  return out;
}

MeasuredSetting read_setting(const TableFail& fail, const json& row, const std::string& where) {
  MeasuredSetting s;
  s.name = string_at(fail, row, where, "case", "");
  const std::string at = fmt::format("case \"{}\"", s.name);
  s.dt_over_tc = *number_at(fail, row, at, "dt_over_tc", kMinDtOverTc, kMaxDtOverTc, true);
  s.softening = *number_at(fail, row, at, "softening", 1, kMaxSoftening, true);
  s.speedup = *number_at(fail, row, at, "speedup", 1 / kMaxSpeedup, kMaxSpeedup, true);
  s.e_eff_error = *number_at(fail, row, at, "e_eff_error", 0, kMaxRelativeError, true);
  if (!row.contains("e_eff_error_phase_averaged"))
    fail(
        fmt::format("{} lacks \"e_eff_error_phase_averaged\" (a table from before it was "
                    "recorded: add it with cases/tradeoff/phase_averaged_e_eff.py, "
                    "docs/accuracy.md)",
                    at));
  s.e_eff_error_phase_averaged =
      *number_at(fail, row, at, "e_eff_error_phase_averaged", 0, kMaxRelativeError, true);
  s.particle_steps_per_second =
      number_at(fail, row, at, "particle_steps_per_second", 0, kMaxRate, false).value_or(0);
  if (!row.contains("precision"))
    fail(
        fmt::format("{} lacks \"precision\" (a table from before it was recorded: run "
                    "cases/tradeoff/trade_table.py again)",
                    at));
  const std::string precision = string_at(fail, row, at, "precision", "");
  try {
    s.single_precision = parse_choice<Precision>(precision) == Precision::single_precision;
  } catch (const UserError& e) {
    fail(fmt::format("{}: {}", at, e.what()));
  }
  // A table from before the column was recorded measured the continuous mode only.
  const std::string mode =
      string_at(fail, row, at, "restitution_mode", choice_name(RestitutionMode::continuous));
  try {
    s.discrete_restitution = parse_choice<RestitutionMode>(mode) == RestitutionMode::discrete;
  } catch (const UserError& e) {
    fail(fmt::format("{}: {}", at, e.what()));
  }
  s.changed = words(string_at(fail, row, at, "changed", ""));
  return s;
}

// "certified_range": two spans [lo, hi] of positive numbers and the scenes it was shown on.
CertifiedRange read_range(const TableFail& fail, const json& r) {
  const std::string at = "\"certified_range\"";
  if (!r.is_object()) fail(fmt::format("{} = {} must be an object", at, r.dump()));
  CertifiedRange range;
  const auto span = [&](const char* key, double(&out)[2]) {
    const auto it = r.find(key);
    if (it == r.end() || !it->is_array() || it->size() != 2 || !(*it)[0].is_number() ||
        !(*it)[1].is_number())
      fail(fmt::format("{}: \"{}\" must be [lowest, highest]", at, key));
    out[0] = (*it)[0].get<double>();
    out[1] = (*it)[1].get<double>();
    if (!(out[0] > 0) || !(out[1] >= out[0]) || !std::isfinite(out[1]))
      fail(fmt::format("{}: \"{}\" = {} must be positive, lowest first", at, key, it->dump()));
  };
  span("D_over_d", range.obstacle_over_particle);
  span("mach", range.mach);
  const auto shown = r.find("shown_on");
  if (shown == r.end() || !shown->is_array() || shown->empty())
    fail(fmt::format("{}: \"shown_on\" must list the scenes it was shown on", at));
  for (const json& name : *shown) {
    if (!name.is_string()) fail(fmt::format("{}: \"shown_on\" holds {}", at, name.dump()));
    range.shown_on.push_back(name.get<std::string>());
  }
  return range;
}

// A JSON value of the table, quoted in a message (core/quoted_input.hpp).
std::string clip_json(const json& value) {
  return quoted_input(value.dump());
}

// One scene's part of a table (the table itself, or one of its transfer checks): its cases
// by name, and per answer the reference's value and k x noise relative to it.
struct ScenePart {
  std::string name;
  bool version1 = false;
  std::map<std::string, json> by_name;
  std::map<std::string, double> reference_value, relative_noise;
  int noise_seeds = 2;
  double noise_factor = 1;
  double noise_floor = 0;
  std::string noise_floor_by;
};

ScenePart read_part(const TableFail& fail, const json& doc, const std::string& where,
                    bool version1) {
  ScenePart part;
  part.version1 = version1;
  const std::string in = where == "the table" ? "" : where + ": ";
  for (std::size_t k = 0; k < doc["cases"].size(); ++k) {
    const json& row = doc["cases"][k];
    const std::string at = fmt::format("{}cases[{}]", in, k);
    if (!row.is_object()) fail(fmt::format("{} = {} must be an object", at, row.dump()));
    const std::string name = string_at(fail, row, at, "case", "");
    if (name.empty()) fail(fmt::format("{} has no \"case\" name", at));
    if (!part.by_name.emplace(name, row).second)
      fail(fmt::format("{}: case \"{}\" appears twice", at, name));
  }
  for (const char* needed : {"reference", "scene", "seed-2"})
    if (!part.by_name.count(needed)) fail(fmt::format("{}has no case \"{}\"", in, needed));
  if (version1) {
    // "the reference's 4 seeds, RMS over their 6 pairs" or "scene against seed-2".
    const std::string from = doc.value("noise_from", std::string());
    part.noise_seeds = from.find("4 seeds") != std::string::npos ? 4 : 2;
  } else {
    part.noise_seeds = int(number_at(fail, doc, where, "noise_seeds", 2, 1e6, true).value());
    if (!doc.contains("certificate") || !doc["certificate"].is_object())
      fail(in + "has no \"certificate\" (its bound's factor k on the noise)");
    part.noise_factor =
        number_at(fail, doc["certificate"], in + "certificate", "k", 0, 100, true).value();
  }
  // Relative noise of every answer the reference measured; an answer it lacks (no front)
  // bounds nothing.
  const json& reference = part.by_name["reference"];
  for (const std::string& answer : kBudgetAnswers) {
    const auto value =
        number_at(fail, reference, in + "case \"reference\"", answer,
                  -std::numeric_limits<double>::max(), std::numeric_limits<double>::max(), false);
    const auto noise = number_at(fail, doc["noise"], in + "noise", answer, 0,
                                 std::numeric_limits<double>::max(), false);
    if (!value || *value == 0 || !noise) continue;
    part.reference_value[answer] = std::abs(*value);
    part.relative_noise[answer] = part.noise_factor * *noise / std::abs(*value);
    if (part.relative_noise[answer] > part.noise_floor) {
      part.noise_floor = part.relative_noise[answer];
      part.noise_floor_by = answer;
    }
  }
  return part;
}

// Raises s's bound to the row's on this scene part: (|difference| + k x noise) / reference
// per answer (version 1: max(|difference|, noise) / reference), infinite where the row lost
// an answer the reference has; `on` names the scene in bound_by ("" for the table's own).
void raise_bound(const TableFail& fail, const ScenePart& part, const json& row,
                 const std::string& on, MeasuredSetting& s) {
  const std::string at = fmt::format("case \"{}\"{}", s.name, on);
  if (!on.empty()) {
    const auto e = number_at(fail, row, at, "e_eff_error_phase_averaged", 0, 1e6, true);
    if (*e > s.error_bound) {
      s.error_bound = *e;
      s.bound_by = "e_eff (phase-averaged)" + on;
    }
  }
  for (const auto& [answer, ref] : part.reference_value) {
    const auto diff =
        number_at(fail, row, at, "diff." + answer, 0, std::numeric_limits<double>::max(), false);
    const double noise = part.relative_noise.at(answer);
    const double bound = !diff           ? std::numeric_limits<double>::infinity()
                         : part.version1 ? std::max(*diff / ref, noise)
                                         : *diff / ref + noise;
    if (bound > s.error_bound) {
      s.error_bound = bound;
      s.bound_by = answer + on;
    }
  }
}

}  // namespace

AccuracyTable read_accuracy_table(const std::filesystem::path& path) {
  const TableFail fail(path);
  std::error_code ec;
  if (!std::filesystem::exists(std::filesystem::symlink_status(path, ec)))
    fail("cannot be read: no such file (make one with `granshock tradeoff SCENE.toml`)");
  // Bounded size and nesting (analysis/json_file.hpp), a regular file only.
  JsonFile file = read_json_file(path, "accuracy table");
  if (file.value.is_discarded()) fail("is not JSON: " + file.error);
  json doc = std::move(file.value);
  if (!doc.is_object() || !doc.contains("cases") || !doc["cases"].is_array() ||
      !doc.contains("noise") || !doc["noise"].is_object())
    fail("has no \"cases\" and \"noise\" (not a trade.json of granshock tradeoff)");
  // The layout's version (cases/tradeoff/trade_table.py writes it): a table of another
  // version may mean other things by the same keys.
  const bool version1 = doc.contains("table") && doc["table"] == kTradeTableVersion1;
  if (!doc.contains("table") || (doc["table"] != kTradeTableVersion && !version1))
    fail(
        fmt::format("is {}, not \"{}\" (\"table\"): make it again with this granshock's "
                    "`granshock tradeoff`",
                    doc.contains("table") ? "of version " + clip_json(doc["table"])
                                          : std::string("of no version"),
                    kTradeTableVersion));

  const ScenePart base = read_part(fail, doc, "the table", version1);
  AccuracyTable table;
  table.source = path;
  table.noise_seeds = base.noise_seeds;
  table.noise_factor = base.noise_factor;
  table.noise_floor = base.noise_floor;
  table.noise_floor_by = base.noise_floor_by;
  if (doc.contains("certified_range")) table.range = read_range(fail, doc["certified_range"]);
  // Transfer checks (cases/tradeoff/transfer_table.py): the same settings on other scenes,
  // each bounded by its own reference and noise.
  std::vector<ScenePart> transfers;
  if (doc.contains("transfers")) {
    if (version1 || !doc["transfers"].is_array()) fail("\"transfers\" must be a list");
    for (std::size_t t = 0; t < doc["transfers"].size(); ++t) {
      const json& part = doc["transfers"][t];
      const std::string where = fmt::format("transfers[{}]", t);
      if (!part.is_object() || !part.contains("cases") || !part["cases"].is_array() ||
          !part.contains("noise") || !part["noise"].is_object())
        fail(where + " has no \"cases\" and \"noise\"");
      transfers.push_back(read_part(fail, part, where, false));
      transfers.back().name = string_at(fail, part, where, "shown_on", where);
      const ScenePart& last = transfers.back();
      table.noise_seeds = std::min(table.noise_seeds, last.noise_seeds);
      if (last.noise_floor > table.noise_floor) {
        table.noise_floor = last.noise_floor;
        table.noise_floor_by = last.noise_floor_by + " on " + last.name;
      }
    }
  }

  for (std::size_t k = 0; k < doc["cases"].size(); ++k) {
    const json& row = doc["cases"][k];
    MeasuredSetting s = read_setting(fail, row, fmt::format("cases[{}]", k));
    // e_eff averaged over the phase of the first contact step: one phase is one impact,
    // 16 % off at the paper's dt where the average is 3 % off (docs/accuracy.md).
    s.error_bound = s.e_eff_error_phase_averaged;
    s.bound_by = "e_eff (phase-averaged)";
    raise_bound(fail, base, row, "", s);
    for (const ScenePart& part : transfers) {
      const auto match = part.by_name.find(s.name);
      if (match == part.by_name.end()) {
        s.error_bound = std::numeric_limits<double>::infinity();
        s.bound_by = "not measured on " + part.name;
        break;
      }
      raise_bound(fail, part, match->second, " on " + part.name, s);
    }
    table.settings.push_back(s);
  }
  return table;
}

}  // namespace granshock
