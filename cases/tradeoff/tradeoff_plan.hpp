// The cases of `granshock tradeoff SCENE.toml` (docs/accuracy.md): a reference at the most
// accurate settings and one cheaper setting per case, each a list of `--set` overrides of
// the scene, made into a study file that `granshock study` runs.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "cases/accuracy/dt_overrides.hpp"  // overrides_at_dt
#include "core/scene.hpp"

namespace granshock {

// The seeds of the scene as given whose spread is the noise of every comparison
// (docs/accuracy.md, "The certificate"), and of the reference whose second seed checks the
// bias of the scene's setting on other particles.
inline constexpr int kNoiseSeeds = 4;
inline constexpr int kReferenceSeeds = 2;

struct TradeCase {
  std::string name;
  std::vector<std::string> overrides;  // "key=value", after the scene's own
};

// From the scene's collision time t_c and stable limit at its fastest impact (the guard):
//   reference    dt = t_c/100, double, the materials as given
//   dt-tc50, dt-tc25, scene (the scene's dt), dt-tc6, dt-stable (0.95 of the limit)
//   soft-10, soft-100, soft-1000: contact.softening = F at the scene's dt x F^(2/5)
//   discrete, soft-F-discrete: the same with contact.restitution_mode = "discrete"
//   single, skin-0.1, skin-0.6 (in d_max), sample-sparse (fields sampled 4 times more
//   rarely, or as rarely as 10 samples per block allow), window-half
//   seed-2 .. seed-4: the scene with other seeds; with "scene", the kNoiseSeeds runs whose
//   spread is the noise (trade_table.py)
//   reference-seed-2: the reference with the second seed (the bias on other particles)
// Every case samples the fields at the scene's interval in simulated time (sample_every
// scaled with 1/dt, at least 1), so that only the setting named changes.
std::vector<TradeCase> tradeoff_cases(const Scene& scene);

// The study file of those cases: base = the scene file (absolute), [study] set = the
// command line's overrides, mode "list" with one [[case]] each.
std::string tradeoff_study_toml(const std::string& name, const std::filesystem::path& scene_file,
                                const std::vector<std::string>& overrides,
                                const std::vector<TradeCase>& cases);

}  // namespace granshock
