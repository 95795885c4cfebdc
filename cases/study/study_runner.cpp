#include "cases/study/study_runner.hpp"

#include <fmt/format.h>

#include <chrono>
#include <iostream>
#include <new>

#include "analysis/fields_command.hpp"
#include "cases/bow_shock/interrupt.hpp"
#include "cases/bow_shock/run_command.hpp"
#include "cases/study/case_directory.hpp"
#include "cases/study/case_record.hpp"
#include "cases/study/study_cost.hpp"
#include "cases/study/study_preflight.hpp"
#include "cases/study/study_rate.hpp"
#include "core/user_error.hpp"

namespace granshock {

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t) {
  return std::chrono::duration<double>(Clock::now() - t).count();
}

// The study's clock and its ETA: the expected particle-steps of the cases still to run over
// the rate measured on the cases run so far (expected particle-steps per wall second, so
// that the estimate's error in the particle count cancels), or the study's prior rate.
class StudyProgress {
 public:
  StudyProgress(const StudyPlan& plan, std::size_t total)
      : total_(total), start_(Clock::now()), prior_(study_rate(plan)) {}

  void before(std::size_t position, const PlannedCase& c, const CaseDirectory& dir,
              double remaining) const {
    std::string what = "starting";
    if (dir.state == CaseState::resumable)
      what = fmt::format("resuming at step {} of {}", dir.steps_done, c.scene.total_steps());
    std::cerr << fmt::format(
        "granshock study: case {}/{} {} (--case {}): {}; {}; {:.3g} particle-steps; elapsed {}, "
        "{}\n",
        position + 1, total_, c.spec.name, c.spec.index, overrides_text(c.spec.overrides), what,
        expected_particle_steps(c.scene, dir.steps_done), duration_text(seconds_since(start_)),
        eta(remaining));
  }

  void after(std::size_t position, const PlannedCase& c, const std::string& outcome, double seconds,
             double remaining) const {
    std::cerr << fmt::format("granshock study: case {}/{} {}: {} in {}; elapsed {}, {}\n",
                             position + 1, total_, c.spec.name, outcome, duration_text(seconds),
                             duration_text(seconds_since(start_)), eta(remaining));
  }

  void measured(double particle_steps, double seconds) {
    particle_steps_ += particle_steps;
    seconds_ += seconds;
  }

 private:
  std::string eta(double remaining) const {
    if (remaining <= 0) return "nothing left to run";
    if (seconds_ > 0 && particle_steps_ > 0) {
      const double rate = particle_steps_ / seconds_;
      return fmt::format("study ETA {} ({:.3g} particle-steps left at {:.3g}/s measured)",
                         duration_text(remaining / rate), remaining, rate);
    }
    return fmt::format("study ETA ~{} ({:.3g} particle-steps left at {:.3g}/s, {})",
                       duration_text(remaining / prior_.particle_steps_per_second), remaining,
                       prior_.particle_steps_per_second, prior_.source);
  }

  std::size_t total_;
  Clock::time_point start_;
  StudyRate prior_;
  double particle_steps_ = 0, seconds_ = 0;
};

// Runs one case as `granshock run` with the action its directory calls for. Returns the
// run's exit code; throws what the run throws.
int run_case(const StudyPlan& plan, const PlannedCase& c, const CaseAction& a,
             const StudyRunOptions& o) {
  if (a.state == CaseState::needs_fields) {
    fields_command({c.dir}, {}, FieldsCommandOptions{o.figures, o.quiet});
    return 0;
  }
  RunOptions run;
  run.scene_file = plan.spec.base;
  run.out_dir = c.dir;
  run.overrides = run_overrides(plan.spec, c);
  run.accuracy_choice = c.accuracy_choice;  // its overrides are in the case's own
  run.resume = a.resume;
  run.overwrite = a.overwrite;
  run.stop_after_steps = o.stop_after_steps;
  run.quiet = o.quiet;
  run.figures = o.figures;
  return run_scene(run);
}

// The case's failure as one line, or "" when it ran (its exit code in `code`).
std::string try_case(const StudyPlan& plan, const PlannedCase& c, const CaseAction& a,
                     const StudyRunOptions& o, int& code) {
  try {
    code = run_case(plan, c, a, o);
    return {};
  } catch (const NumericalFailure& e) {
    return std::string("the run failed numerically: ") + e.what();
  } catch (const UserError& e) {
    return e.what();
  } catch (const std::bad_alloc& e) {
    return std::string("not enough memory (") + e.what() + ")";
  } catch (const std::exception& e) {
    return std::string("internal error: ") + e.what();
  }
}

}  // namespace

void record_case(const StudyPlan& plan, const PlannedCase& c) {
  try {
    write_case_record(c.dir, c.record_dir,
                      CaseRecordOrigin{plan.spec.name, plan.spec.file.string(), c.spec.name,
                                       c.spec.index, run_overrides(plan.spec, c)});
  } catch (const UserError& e) {
    std::cerr << fmt::format("granshock study: warning: case {}: no record: {}\n", c.spec.name,
                             e.what());
  }
}

StudyRunResult run_study_cases(const StudyPlan& plan, const std::vector<std::size_t>& selected,
                               const StudyRunOptions& o) {
  StudyRunResult result;
  StudyProgress progress(plan, selected.size());
  // Expected particle-steps still to run, case by case, from the directories as they are.
  std::vector<double> left(selected.size(), 0.0);
  for (std::size_t p = 0; p < selected.size(); ++p) {
    const CaseDirectory dir = inspect_planned_case(plan, plan.cases[selected[p]]);
    if (dir.state != CaseState::finished && dir.state != CaseState::needs_fields)
      left[p] = expected_particle_steps(plan.cases[selected[p]].scene, dir.steps_done);
  }
  auto remaining = [&left](std::size_t from) {
    double sum = 0;
    for (std::size_t p = from; p < left.size(); ++p) sum += left[p];
    return sum;
  };

  catch_interrupts();  // from here a signal stops the study between cases or in a run
  for (std::size_t p = 0; p < selected.size(); ++p) {
    const PlannedCase& c = plan.cases[selected[p]];
    if (const int sig = interrupt_signal(); sig != 0) {
      std::cerr << fmt::format(
          "granshock study: interrupted before case {}/{} {}; run the study again to continue\n",
          p + 1, selected.size(), c.spec.name);
      result.exit_code = 128 + sig;
      result.stopped = true;
      return result;
    }
    const CaseDirectory dir = inspect_planned_case(plan, c);
    const CaseAction action = action_for(dir.state);
    if (dir.state == CaseState::finished) {
      std::cerr << fmt::format(
          "granshock study: case {}/{} {}: finished before{}, skipped\n", p + 1, selected.size(),
          c.spec.name,
          dir.from_record ? " (its record in " + c.record_dir.string() + ")" : std::string());
      continue;
    }
    if (!dir.record_refused.empty())
      std::cerr << fmt::format("granshock study: case {}/{} {}: {}\n", p + 1, selected.size(),
                               c.spec.name, dir.record_refused);
    progress.before(p, c, dir, remaining(p));
    const auto start = Clock::now();
    int code = 0;
    const std::string failure = try_case(plan, c, action, o, code);
    const double seconds = seconds_since(start);
    const CaseDirectory after = inspect_planned_case(plan, c);
    if (!failure.empty() && after.state == CaseState::finished) {
      // Finished, fields and summary written; what failed came after them (the figures
      // of a machine without matplotlib, say).
      std::cerr << fmt::format("granshock study: warning: case {}/{} {}: {}\n", p + 1,
                               selected.size(), c.spec.name, failure);
    } else if (!failure.empty()) {
      result.failures[c.spec.index] = failure;
      std::cerr << fmt::format("granshock study: case {}/{} {} failed: {}\n", p + 1,
                               selected.size(), c.spec.name, failure);
      left[p] = 0;
      progress.after(p, c, "failed", seconds, remaining(p + 1));
      continue;
    }
    // The particle-steps this leg ran, on the plan's count (a resumed case ran the rest).
    const double ran = expected_particle_steps(c.scene, dir.steps_done) -
                       expected_particle_steps(c.scene, after.steps_done);
    if (ran > 0) progress.measured(ran, seconds);
    left[p] =
        after.state == CaseState::finished ? 0 : expected_particle_steps(c.scene, after.steps_done);
    if (code != 0 || after.state != CaseState::finished) {
      progress.after(p, c, code != 0 ? "interrupted" : "stopped", seconds, remaining(p));
      std::cerr << fmt::format(
          "granshock study: {} in case {}/{} {} at step {} of {}; run the study again to "
          "continue it\n",
          code != 0 ? "interrupted" : "stopped", p + 1, selected.size(), c.spec.name,
          after.steps_done, c.scene.total_steps());
      result.exit_code = code;
      result.stopped = true;
      return result;
    }
    progress.after(p, c, "finished", seconds, remaining(p + 1));
    record_case(plan, c);
  }
  return result;
}

}  // namespace granshock
