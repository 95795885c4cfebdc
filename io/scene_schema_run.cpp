// The scene schema's sections of the run's schedule: [time] and [output]
// (io/scene_schema_parts.hpp).
#include <fmt/format.h>

#include <cstdint>
#include <string>

#include "core/user_error.hpp"
#include "io/scene_schema_parts.hpp"
#include "io/table_reader.hpp"

namespace granshock::scene_toml::schema_detail {

namespace {

// More blocks than this only divide the production window into noise (and memory).
constexpr long kMaxBlocks = 10000;

// ---- [time] ------------------------------------------------------------------------------

const Key kTimeKeys[] = {
    {"dt",
     "number (s)",
     {"s",
      "`> 0`; at most the stable limit (unless `--force`); `time.duration` / dt from 1 to 1e12 "
      "steps",
      "required", "the time step (scene_format.md, \"The time-step guard for scenes\")"},
     [](TableReader& r, Reading& st, const std::string& k) { st.s.setup.dt = r.positive(k); },
     [](const Writing& w, toml::table& t, const std::string& k) { t.insert(k, w.s.setup.dt); }},
    {"duration",
     "number (s)",
     {"s", "`> 0`; at least one step", "required", "simulated time"},
     [](TableReader& r, Reading& st, const std::string& k) { st.s.run.duration_s = r.positive(k); },
     [](const Writing& w, toml::table& t, const std::string& k) {
       t.insert(k, w.s.run.duration_s);
     }},
    {"production_start",
     "number (s)",
     {"s", "`[0, time.duration)`", "`time.duration / 2`", "fields average over [start, duration]"},
     [](TableReader& r, Reading& st, const std::string& k) {
       const double duration = st.s.run.duration_s;
       const double start = st.s.run.production_start_s = r.number(k, 0.5 * duration);
       // Both keys named, time.duration first: the window is empty when either is wrong,
       // and a --resume that shortens time.duration meets this before the checkpoint.
       if (!(start >= 0 && start < duration))
         throw UserError(fmt::format(
             "scene keys 'time.duration' = {} s and '{}' = {} s: the production window "
             "[production_start, duration) is empty; time.production_start must be in [0, {})",
             duration, r.key(k), start, duration));
     },
     [](const Writing& w, toml::table& t, const std::string& k) {
       t.insert(k, w.s.run.production_start_s);
     }},
};

// ---- [output] ----------------------------------------------------------------------------

const Key kOutputKeys[] = {
    {"snapshot_interval",
     "number (s)",
     {"s", "`> 0`; at most 1e5 snapshots", "`time.duration / 10`", "particle snapshots in run.h5"},
     [](TableReader& r, Reading& st, const std::string& k) {
       st.s.run.snapshot_interval_s = r.positive(k, st.s.run.duration_s / 10);
     },
     [](const Writing& w, toml::table& t, const std::string& k) {
       t.insert(k, w.s.run.snapshot_interval_s);
     }},
    {"series_interval",
     "number (s)",
     {"s", "`> 0`; at most 1e7 rows", "`time.duration / 200`", "time-series rows"},
     [](TableReader& r, Reading& st, const std::string& k) {
       st.s.run.series_interval_s = r.positive(k, st.s.run.duration_s / 200);
     },
     [](const Writing& w, toml::table& t, const std::string& k) {
       t.insert(k, w.s.run.series_interval_s);
     }},
    {"checkpoint_interval",
     "number (s)",
     {"s", "`> 0`; at most 1e5 checkpoints", "`time.duration / 5`",
      "checkpoint.h5 (also at the end and on SIGINT/SIGTERM)"},
     [](TableReader& r, Reading& st, const std::string& k) {
       st.s.run.checkpoint_interval_s = r.positive(k, st.s.run.duration_s / 5);
     },
     [](const Writing& w, toml::table& t, const std::string& k) {
       t.insert(k, w.s.run.checkpoint_interval_s);
     }},
    {"progress_interval",
     "number (s)",
     {"s (wall clock)", "`[0.01, 1e9]`", "`2`", "wall-clock seconds between progress lines"},
     [](TableReader& r, Reading& st, const std::string& k) {
       st.s.run.progress_interval_s = r.number_within(k, kProgressInterval.lo, kProgressInterval.hi,
                                                      2.0, kProgressInterval.why);
     },
     [](const Writing& w, toml::table& t, const std::string& k) {
       t.insert(k, w.s.run.progress_interval_s);
     }},
    {"sample_every",
     "integer",
     {"steps", "`>= 1`; enough samples (scene_format.md, \"Field sampling\")", "`100`",
      "steps between field samples"},
     [](TableReader& r, Reading& st, const std::string& k) {
       st.s.run.sample_every = r.integer_at_least(k, 1, 100);
     },
     [](const Writing& w, toml::table& t, const std::string& k) {
       t.insert(k, std::int64_t(w.s.run.sample_every));
     }},
    {"blocks",
     "integer",
     {"", "`[2, 10000]`; enough samples (scene_format.md, \"Field sampling\")", "`10`",
      "the production window is cut into this many blocks for error bars"},
     [](TableReader& r, Reading& st, const std::string& k) {
       const long blocks = r.integer_at_least(k, 2, 10);
       if (blocks > kMaxBlocks)
         fail(r.key(k), std::to_string(blocks),
              fmt::format("must be at most {} (each block keeps its own bin sums)", kMaxBlocks));
       st.s.run.blocks = int(blocks);
     },
     [](const Writing& w, toml::table& t, const std::string& k) {
       t.insert(k, std::int64_t(w.s.run.blocks));
     }},
};

}  // namespace

const Table kTime = table("time", kTimeKeys);
const Table kOutput = table("output", kOutputKeys);

}  // namespace granshock::scene_toml::schema_detail
