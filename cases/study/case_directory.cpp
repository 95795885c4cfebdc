#include "cases/study/case_directory.hpp"

#include "analysis/json_file.hpp"
#include "cases/study/case_record.hpp"
#include "io/run_directory.hpp"
#include "io/run_file.hpp"

namespace granshock {

namespace fs = std::filesystem;

std::string to_string(CaseState state) {
  switch (state) {
    case CaseState::missing:
      return "missing";
    case CaseState::finished:
      return "finished";
    case CaseState::needs_fields:
      return "needs fields";
    case CaseState::resumable:
      return "unfinished";
    case CaseState::restartable:
      return "unfinished";
  }
  return "missing";
}

namespace {

// The steps and wall time a summary reports (0 where it has none).
void take_summary(CaseDirectory& c, nlohmann::json summary) {
  const nlohmann::json steps = summary_value(summary, "steps");
  const nlohmann::json wall = summary_value(summary, "wall_seconds");
  c.steps_done = steps.is_number() ? steps.get<long>() : 0;
  c.wall_seconds = wall.is_number() ? wall.get<double>() : 0.0;
  c.summary = std::move(summary);
}

}  // namespace

CaseDirectory inspect_case_directory(const fs::path& dir) {
  CaseDirectory c;
  std::error_code ec;
  if (!fs::exists(dir / kRunMarker, ec)) return c;  // not (yet) a run directory
  take_summary(c, read_summary(dir));
  if (c.summary.is_object()) {
    if (summary_value(c.summary, "completed") == true) {
      c.state =
          c.summary.contains(kFieldsSummaryKey) ? CaseState::finished : CaseState::needs_fields;
      return c;
    }
  }
  const bool resumable = fs::exists(dir / "checkpoint.h5", ec) && fs::exists(dir / "run.h5", ec);
  c.state = resumable ? CaseState::resumable : CaseState::restartable;
  if (!resumable) c.steps_done = 0;
  return c;
}

CaseDirectory inspect_case_directory(const fs::path& dir, const fs::path& record_dir,
                                     const std::vector<std::string>& overrides) {
  CaseDirectory c = inspect_case_directory(dir);
  if (c.state != CaseState::missing) return c;
  ReadRecord record = read_case_record(record_dir, overrides);
  c.record_refused = record.refused;
  if (record.summary.is_null()) return c;
  c.state = CaseState::finished;
  c.from_record = true;
  take_summary(c, std::move(record.summary));
  return c;
}

}  // namespace granshock
