#include "cases/tradeoff/tradeoff_plan.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "cases/bow_shock/run_checks.hpp"
#include "core/choice_names.hpp"

namespace granshock {

namespace {

std::vector<std::string> with(std::vector<std::string> a, const std::string& b) {
  a.insert(a.begin(), b);
  return a;
}

}  // namespace

std::vector<TradeCase> tradeoff_cases(const Scene& s) {
  const TimeStepAssessment guard = assess_time_step(s);
  const double tc = guard.t_c, dt = s.setup.dt, d = s.setup.max_diameter();
  std::vector<TradeCase> cases = {{"reference", overrides_at_dt(s, tc / 100)},
                                  {"dt-tc50", overrides_at_dt(s, tc / 50)},
                                  {"dt-tc25", overrides_at_dt(s, tc / 25)},
                                  {"scene", overrides_at_dt(s, dt)},
                                  {"dt-tc6", overrides_at_dt(s, tc / 6)},
                                  {"dt-stable", overrides_at_dt(s, 0.95 * guard.dt_stable)}};
  for (const double f : {10.0, 100.0, 1000.0})
    cases.push_back({fmt::format("soft-{:g}", f), with(overrides_at_dt(s, dt * std::pow(f, 0.4)),
                                                       fmt::format("contact.softening={:g}", f))});
  // The discrete restitution mode removes the time step's bias of e_eff; with softening it
  // may be the cheapest setting within a budget (docs/accuracy.md).
  const std::string discrete =
      fmt::format("contact.restitution_mode=\"{}\"", choice_name(RestitutionMode::discrete));
  cases.push_back({"discrete", {discrete}});
  for (const double f : {10.0, 100.0, 1000.0})
    cases.push_back({fmt::format("soft-{:g}-discrete", f),
                     with(with(overrides_at_dt(s, dt * std::pow(f, 0.4)), discrete),
                          fmt::format("contact.softening={:g}", f))});
  const double window_mid = 0.5 * (s.run.production_start_s + s.run.duration_s);
  const std::string single = choice_name(Precision::single_precision);
  cases.push_back({single, {fmt::format("numerics.precision=\"{}\"", single)}});
  cases.push_back({"skin-0.1", {fmt::format("numerics.skin={:.6g}", 0.1 * d)}});
  cases.push_back({"skin-0.6", {fmt::format("numerics.skin={:.6g}", 0.6 * d)}});
  // Four times sparser, or as sparse as the window allows (10 samples per block).
  const double window_steps = (s.run.duration_s - s.run.production_start_s) / dt;
  const long sparsest = std::max(s.run.sample_every, long(window_steps / (10.0 * s.run.blocks)));
  cases.push_back(
      {"sample-sparse",
       {fmt::format("output.sample_every={}", std::min(4 * s.run.sample_every, sparsest))}});
  cases.push_back({"window-half", {fmt::format("time.production_start={:.6g}", window_mid)}});
  // The noise: the scene as given with three more seeds, four in all (trade_table.py).
  for (int k = 2; k <= kNoiseSeeds; ++k)
    cases.push_back(
        {fmt::format("seed-{}", k), {fmt::format("scene.seed={}", s.run.seed + k - 1)}});
  for (int k = 2; k <= kReferenceSeeds; ++k)
    cases.push_back(
        {fmt::format("reference-seed-{}", k),
         with(overrides_at_dt(s, tc / 100), fmt::format("scene.seed={}", s.run.seed + k - 1))});
  return cases;
}

std::string tradeoff_study_toml(const std::string& name, const std::filesystem::path& scene_file,
                                const std::vector<std::string>& overrides,
                                const std::vector<TradeCase>& cases) {
  // TOML basic strings: the overrides hold quotes ("single"), escaped here.
  const auto quoted = [](const std::string& text) {
    std::string out = "\"";
    for (const char c : text) {
      if (c == '"' || c == '\\') out += '\\';
      out += c;
    }
    return out + "\"";
  };
  const auto list = [&](const std::vector<std::string>& items) {
    std::string out = "[";
    for (std::size_t k = 0; k < items.size(); ++k) out += (k ? ", " : "") + quoted(items[k]);
    return out + "]";
  };
  std::string toml =
      "# Written by `granshock tradeoff` (docs/accuracy.md): the reference and one cheaper\n"
      "# setting per case.\n\n[study]\nname = " +
      quoted(name) + "\nbase = " + quoted(std::filesystem::absolute(scene_file).string()) +
      "\nmode = \"list\"\n" + (overrides.empty() ? "" : "set = " + list(overrides) + "\n");
  for (const TradeCase& c : cases)
    toml += "\n[[case]]\nname = " + quoted(c.name) + "\nset = " + list(c.overrides) + "\n";
  return toml;
}

}  // namespace granshock
