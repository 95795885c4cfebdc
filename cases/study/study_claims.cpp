#include "cases/study/study_claims.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>

#include "io/atomic_file.hpp"

namespace granshock {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

double number(const nlohmann::ordered_json& row, const std::string& key) {
  const auto it = row.find(key);
  return it != row.end() && it->is_number() ? it->get<double>() : kNaN;
}

struct Case {
  std::string name;
  double d_over_d, mach, delta, delta_err;
  double shock_layer_phi, hot_subsonic, upstream_ma_ratio, wake;
  // Every other scene column ("scene.*"), as text: cases compared along Ma_inf must agree on
  // all but the Mach number and the speed (the paper changes U with Ma), cases compared
  // along D/d on all but D/d. In a sweep study (studies/future_work.toml) the phi, e, ...
  // cases are then not mistaken for points of the Ma_inf or D/d series.
  std::string context_for_mach, context_for_size;
};

// The scene columns of a row except those named, joined as "key=value;".
std::string scene_context(const nlohmann::ordered_json& row,
                          std::initializer_list<const char*> except) {
  std::string context;
  for (const auto& item : row.items()) {
    // (No structured binding: capturing one in the lambda is C++20, and nvcc warns.)
    const std::string& key = item.key();
    if (key.rfind("scene.", 0) != 0) continue;
    if (std::find_if(except.begin(), except.end(), [&](const char* e) { return key == e; }) !=
        except.end())
      continue;
    context += key + "=" + item.value().dump() + ";";
  }
  return context;
}

std::vector<Case> finished_cases(const StudyTable& table) {
  std::vector<Case> cases;
  for (const auto& row : table.rows) {
    if (row.value("status", std::string()) != "finished") continue;
    double mach = number(row, "ma_inf_target");
    if (std::isfinite(mach)) mach = std::stod(fmt::format("{:.3g}", mach));
    cases.push_back(
        {row.value("case", std::string()), number(row, "scene.D_over_d"), mach,
         number(row, "delta_over_D"), number(row, "delta_over_D_err"),
         number(row, "shock_layer_phi_mean"), number(row, "hot_region_subsonic_fraction"),
         number(row, "upstream_ma_peak_over_ma_inf"), number(row, "wake_phi_over_phi_inf"),
         scene_context(row, {"scene.mach", "scene.U"}), scene_context(row, {"scene.D_over_d"})});
  }
  return cases;
}

std::string with_error(double value, double error) {
  if (!std::isfinite(value)) return "n/a";
  return std::isfinite(error) ? fmt::format("{:.3f} +- {:.3f}", value, error)
                              : fmt::format("{:.3f}", value);
}

// Groups of cases sharing `key` and `context`, each sorted by `along`; only finite keys.
// Ordered by key, then context.
template <class Key, class Along>
std::map<std::pair<double, std::string>, std::vector<Case>> groups(const std::vector<Case>& cases,
                                                                   Key key,
                                                                   std::string Case::*context,
                                                                   Along along) {
  std::map<std::pair<double, std::string>, std::vector<Case>> g;
  for (const Case& c : cases)
    if (std::isfinite(key(c)) && std::isfinite(along(c)) && std::isfinite(c.delta))
      g[{key(c), c.*context}].push_back(c);
  for (auto& [k, v] : g)
    std::sort(v.begin(), v.end(),
              [&](const Case& a, const Case& b) { return along(a) < along(b); });
  return g;
}

StudyClaim falls_with_mach(const std::vector<Case>& cases) {
  StudyClaim c{"delta/D falls as Ma_inf rises",
               "at every D/d, delta/D lower at each higher Ma_inf (and by two combined errors)",
               "undetermined", ""};
  int judged = 0, holds = 0, significant = 0;
  const auto by_size = groups(
      cases, [](const Case& x) { return x.d_over_d; }, &Case::context_for_mach,
      [](const Case& x) { return x.mach; });
  for (const auto& [key, group] : by_size) {
    const double d = key.first;
    if (group.size() < 2) continue;
    ++judged;
    bool falls = true, clearly = true;
    std::string line = fmt::format("D/d {:g}:", d);
    for (std::size_t k = 0; k < group.size(); ++k) {
      line += fmt::format(" {} (Ma {:g})", with_error(group[k].delta, group[k].delta_err),
                          group[k].mach);
      if (k == 0) continue;
      // The fall in units of the combined error of the two cases.
      const double fall = group[k - 1].delta - group[k].delta,
                   error = std::hypot(group[k - 1].delta_err, group[k].delta_err);
      line += fmt::format(" [fall {:.2g} errors]", error > 0 ? fall / error : HUGE_VAL);
      if (!(fall > 0)) falls = false;
      if (!(fall > 2 * error)) clearly = false;
    }
    holds += falls;
    significant += falls && clearly;
    c.numbers += (c.numbers.empty() ? "" : "; ") + line;
  }
  if (judged == 0)
    c.numbers = "needs two finished cases with the same D/d and different Ma_inf";
  else if (holds < judged)
    c.verdict = "does not hold";
  else
    c.verdict = significant < judged ? "holds, but not by two errors everywhere" : "holds";
  return c;
}

StudyClaim constant_in_size(const std::vector<Case>& cases) {
  StudyClaim c{"delta/D is nearly constant in D/d at fixed Ma_inf",
               "at every Ma_inf, (max - min) / mean of delta/D <= 20 %", "undetermined", ""};
  int judged = 0, holds = 0;
  for (const auto& [key, group] : groups(
           cases, [](const Case& x) { return x.mach; }, &Case::context_for_size,
           [](const Case& x) { return x.d_over_d; })) {
    if (group.size() < 2) continue;
    const double ma = key.first;
    ++judged;
    double lo = HUGE_VAL, hi = -HUGE_VAL, mean = 0;
    std::string line = fmt::format("Ma {:g}:", ma);
    for (const Case& x : group) {
      lo = std::min(lo, x.delta);
      hi = std::max(hi, x.delta);
      mean += x.delta / static_cast<double>(group.size());
      line += fmt::format(" {} (D/d {:g})", with_error(x.delta, x.delta_err), x.d_over_d);
    }
    const double spread = (hi - lo) / mean;
    holds += spread <= 0.2;
    c.numbers +=
        (c.numbers.empty() ? "" : "; ") + line + fmt::format(", spread {:.1f} %", 100 * spread);
  }
  if (judged > 0)
    c.verdict = holds == judged ? "holds" : "does not hold";
  else
    c.numbers = "needs two finished cases with the same Ma_inf and different D/d";
  return c;
}

// A per-case number against a bound.
StudyClaim per_case(const std::vector<Case>& cases, const std::string& claim,
                    const std::string& criterion, double Case::*member, bool (*passes)(double)) {
  StudyClaim c{claim, criterion, "undetermined", ""};
  int judged = 0, holds = 0;
  for (const Case& x : cases) {
    const double v = x.*member;
    c.numbers += (c.numbers.empty() ? "" : ", ") + x.name + " " +
                 (std::isfinite(v) ? fmt::format("{:.3g}", v) : std::string("n/a"));
    if (!std::isfinite(v)) continue;
    ++judged;
    holds += passes(v);
  }
  if (judged > 0) c.verdict = holds == judged ? "holds" : "does not hold";
  if (cases.empty()) c.numbers = "no finished case";
  return c;
}

}  // namespace

std::vector<StudyClaim> check_paper_claims(const StudyTable& table) {
  const std::vector<Case> cases = finished_cases(table);
  return {
      falls_with_mach(cases),
      constant_in_size(cases),
      per_case(cases, "phi is about 0.5 between shock and obstacle",
               "shock-layer mean phi on the stagnation line in [0.35, 0.65] in every case",
               &Case::shock_layer_phi, [](double v) { return v >= 0.35 && v <= 0.65; }),
      per_case(cases, "the hot region behind the shock is subsonic",
               "at least half of the hot bins on the stagnation strip at Ma < 1 in every case",
               &Case::hot_subsonic, [](double v) { return v >= 0.5; }),
      per_case(cases, "the local Ma upstream of the shock exceeds Ma_inf (the gas cools)",
               "largest Ma ahead of the front / Ma_inf at the inlet > 1 in every case",
               &Case::upstream_ma_ratio, [](double v) { return v > 1; }),
      per_case(cases, "the wake is nearly empty",
               "phi within one diameter behind the cylinder < 0.2 phi_inf in every case",
               &Case::wake, [](double v) { return v < 0.2; }),
  };
}

void write_claims(const std::filesystem::path& out, const std::vector<StudyClaim>& claims) {
  std::string md = "| claim | criterion | verdict | numbers |\n|---|---|---|---|\n";
  nlohmann::json j = nlohmann::json::array();
  for (const StudyClaim& c : claims) {
    md += fmt::format("| {} | {} | {} | {} |\n", c.claim, c.criterion, c.verdict, c.numbers);
    j.push_back({{"claim", c.claim},
                 {"criterion", c.criterion},
                 {"verdict", c.verdict},
                 {"numbers", c.numbers}});
  }
  write_file_atomically(out / "claims.md", md);
  write_file_atomically(out / "claims.json", j.dump(2) + "\n");
}

}  // namespace granshock
