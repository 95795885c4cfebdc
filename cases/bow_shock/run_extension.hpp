// What a --resume may change of the scene its checkpoint ran (docs/scene_format.md,
// "Extending a run"): the run's end (time.duration) and its production window
// (time.production_start), as long as the checkpoint's field sums stay exactly those an
// uninterrupted run of the new scene holds at the checkpoint's step. The resumed run then
// continues bitwise as that run. Every other key must be the checkpoint's. The changes are
// recorded in run.h5 (/scene/extensions, docs/output_format.md).
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/scene.hpp"
#include "io/run_file.hpp"

namespace granshock {

struct RunExtension {
  long step = 0;  // the checkpoint's
  double time = 0;
  double duration_before = 0, duration_after = 0;
  double production_start_before = 0, production_start_after = 0;
  // The new window starts at or after the checkpoint: the earlier window's samples (and
  // sums) are dropped.
  long samples_dropped = 0;
  // >= 0: the new window samples the checkpoint's step, which the earlier one did not (its
  // end): the resumed run takes that sample, into this block, before it goes on.
  int catch_up_block = -1;

  bool changes() const {
    return duration_before != duration_after || production_start_before != production_start_after;
  }
};

// Of the scene keys that differ from the checkpoint's, those a resume may not change.
std::vector<std::string> keys_fixed_on_resume(const std::vector<std::string>& differing);

// `before`: the checkpoint's scene; `after`: this leg's, differing at most in the keys
// above; `step`: the checkpoint's, whose samples per block are before's. Throws UserError,
// one line naming the key and why, where the change would not continue the run as an
// uninterrupted run of `after`: a duration that ends by the checkpoint, a production window
// whose samples by then are not the ones the checkpoint holds (docs/scene_format.md).
RunExtension plan_extension(const Scene& before, const Scene& after, long step);

// The log's line about an extension.
std::string extension_note(const RunExtension& e);

// run.h5 as this leg continues it: its scene replaced by this leg's where they differ, the
// extensions recorded after the checkpoint's step dropped (a later leg redoes them) and
// `e` appended when it changes anything. Returns the extensions the file then lists, for
// summary.json (empty: none).
nlohmann::json record_extension(RunFile& file, const std::string& scene_as_given,
                                const std::string& scene_resolved, const RunExtension& e);

}  // namespace granshock
