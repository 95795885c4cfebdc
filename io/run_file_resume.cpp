// Resuming run.h5 from a checkpoint: checking that the file is the one the checkpoint was
// written with, and cutting its time-indexed entries back to the checkpoint's step.
#include <fmt/format.h>

#include <algorithm>
#include <string>
#include <vector>

#include "core/user_error.hpp"
#include "io/hdf5_helpers.hpp"
#include "io/run_file.hpp"
#include "io/run_file_growth.hpp"
#include "io/run_file_parts.hpp"

namespace granshock {

using namespace run_file_detail;

namespace {

namespace fs = std::filesystem;
using h5::Handle;

std::string element_path(const std::string& group, const char* name) {
  return group + "/" + name;
}

// Collects the groups below the root that hold a "step" dataset: every time-indexed
// quantity, including any added to the layout later.
herr_t collect_step_groups(hid_t, const char* name, const H5L_info_t*, void* data) {
  const std::string path(name);
  const std::string suffix = "/step";
  if (path.size() > suffix.size() &&
      path.compare(path.size() - suffix.size(), suffix.size(), suffix) == 0) {
    static_cast<std::vector<std::string>*>(data)->push_back(
        "/" + path.substr(0, path.size() - suffix.size()));
  }
  return 0;
}

// Drops the entries of GROUP/{step,time,value} after checkpoint_step. Steps increase
// along the series, so the kept entries are a prefix.
void truncate_after(hid_t file, const std::string& group_path, long checkpoint_step) {
  const std::vector<long> steps = h5::read_dataset<long>(file, group_path + "/step");
  hsize_t keep = 0;
  while (keep < steps.size() && steps[keep] <= checkpoint_step) ++keep;
  for (const char* name : {"step", "time", "value"}) {
    const std::string path = element_path(group_path, name);
    if (!h5::exists(file, path)) continue;
    Handle set = h5::open_dataset(file, path);
    std::vector<hsize_t> dims = h5::shape_of(set.get());
    if (dims.empty() || dims[0] <= keep) continue;
    dims[0] = keep;
    h5::check(H5Dset_extent(set.get(), dims.data()), "truncating '" + path + "'");
  }
}

// The entries of GROUP/step at or before `step`.
struct Entries {
  long up_to = 0;
  long last_step = -1;  // the last of them; -1: none
};

Entries entries_up_to(hid_t file, const std::string& group_path, long step) {
  const std::vector<long> steps = h5::read_dataset<long>(file, group_path + "/step");
  Entries e;
  for (long s : steps) {
    if (s > step) break;
    ++e.up_to;
    e.last_step = s;
  }
  return e;
}

// A resume joins run.h5 to the checkpoint only when the checkpoint was written with this
// file: the same run id, and the frames and rows it recorded, at or before its step.
void check_against_checkpoint(hid_t file, const fs::path& path, long step,
                              const RunFileRecord& checkpoint) {
  // A checkpoint without a record (RunFileRecord::run_id) cannot be checked (and a resume
  // that stopped before writing a checkpoint with a record must be able to start again
  // from it).
  if (checkpoint.run_id.empty()) return;
  const std::string id = read_run_id(file);
  if (checkpoint.run_id != id)
    throw UserError(fmt::format(
        "--resume: '{}' belongs to another run than the checkpoint.h5 beside it (run id "
        "{}, the checkpoint's '{}'); put back the run.h5 of the checkpoint's run, or start "
        "again with --overwrite",
        path.string(), id.empty() ? std::string("none: it is older than run ids") : "'" + id + "'",
        checkpoint.run_id));
  const Entries frames = entries_up_to(file, std::string(kParticles) + "/count", step);
  const Entries rows = entries_up_to(file, std::string(kObservables) + "/particles", step);
  if (frames.up_to == checkpoint.frames && rows.up_to == checkpoint.rows) return;
  const long last = std::max(frames.last_step, rows.last_step);
  throw UserError(fmt::format(
      "--resume: '{}' holds {} snapshot{} and {} time-series row{} up to step {}{}, but the "
      "checkpoint.h5 beside it (step {}) was written when it held {} and {}; it is not the "
      "run.h5 that checkpoint was written with: put that one back, or start again with "
      "--overwrite",
      path.string(), frames.up_to, frames.up_to == 1 ? "" : "s", rows.up_to,
      rows.up_to == 1 ? "" : "s", step,
      last >= 0 ? fmt::format(" (its last at step {})", last) : std::string(), step,
      checkpoint.frames, checkpoint.rows));
}

}  // namespace

RunFile RunFile::open_for_resume(const fs::path& path, long checkpoint_step,
                                 const RunFileRecord& checkpoint) {
  Handle file = open_existing(path, H5F_ACC_RDWR, "resume");
  h5::naming_file_in_errors(path, "resuming", [&] {
    // Every file of format 3 or later was given a run id when it was made: one without is
    // not a file granshock wrote as it stands.
    if (read_format_version(file.get()) >= 3 && read_run_id(file.get()).empty())
      throw UserError(fmt::format(
          "cannot resume '{}': it has no @run_id, which every run file of format 3 holds; it "
          "was edited or damaged: start again with --overwrite",
          path.string()));
    check_against_checkpoint(file.get(), path, checkpoint_step, checkpoint);
  });
  const int dim = h5::naming_file_in_errors(path, "resuming", [&] { return read_dim(file.get()); });
  RunFile run(path, std::move(file), dim);
  run.make_room(run_growth::truncation() + run_growth::attribute(64), "resuming");
  h5::naming_file_in_errors(path, "resuming", [&] {
    const hid_t f = run.file_.get();
    std::vector<std::string> groups;
    h5::check(H5Lvisit(f, H5_INDEX_NAME, H5_ITER_INC, collect_step_groups, &groups),
              "listing the time series");
    for (const std::string& group : groups) truncate_after(f, group, checkpoint_step);
    // A file without a run id (format 1, or 2 written before run ids): from now on its
    // checkpoints record this file.
    if (read_run_id(f).empty()) h5::write_attribute(f, kRunIdAttribute, new_run_id());
  });
  run.flush();
  return run;
}

void RunFile::check_resumable(const fs::path& path, long checkpoint_step,
                              const RunFileRecord& checkpoint) {
  Handle file = open_existing(path, H5F_ACC_RDONLY, "resume");
  h5::naming_file_in_errors(path, "resuming", [&] {
    check_against_checkpoint(file.get(), path, checkpoint_step, checkpoint);
  });
}

}  // namespace granshock
