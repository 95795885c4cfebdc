// granshock: the command-line program (docs/design.md, "The command-line contract").
#include <fmt/format.h>
#include <fmt/ranges.h>
#include <CLI/CLI.hpp>
#include <Kokkos_Core.hpp>
#include <algorithm>
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <map>
#include <optional>
#include <string>
#include <string_view>

#include "analysis/fields_command.hpp"
#include "apps/granshock/build_info.hpp"
#include "apps/granshock/cpu_check.hpp"
#include "cases/accuracy/accuracy_choice.hpp"
#include "cases/bow_shock/interrupt.hpp"
#include "cases/bow_shock/run_command.hpp"
#include "cases/build_info/build_description.hpp"
#include "cases/collision/head_on_collision.hpp"
#include "cases/dump/from_dump_command.hpp"
#include "cases/export/lammps_export.hpp"
#include "cases/study/study_command.hpp"
#include "cases/tradeoff/tradeoff_command.hpp"
#include "core/allocation_failure.hpp"
#include "core/choice_names.hpp"
#include "core/failure_agreement.hpp"
#include "core/large_blocks.hpp"
#include "core/nearest_name.hpp"
#include "core/quoted_input.hpp"
#include "core/user_error.hpp"
#include "io/hdf5_runtime.hpp"
#include "io/scene_file.hpp"
#include "kernels/device/kokkos_runtime.hpp"
#include "models/law_parameters.hpp"
#include "models/obstacle_shapes.hpp"
#include "parallel/mpi_communicator.hpp"
#include "parallel/mpi_runtime.hpp"

namespace {

// Messages are printed on one line, however they were built.
// A message as it reaches stderr: one line, with whatever input it quotes cut and its
// control bytes escaped (core/quoted_input.hpp), whichever code made it.
std::string one_line(std::string text) {
  for (char& c : text)
    if (c == '\n' || c == '\r') c = ' ';
  while (!text.empty() && text.back() == ' ') text.pop_back();
  return granshock::printable_line(text);
}

// An option whose value is a name of Choices<Enum> (core/choice_names.hpp): CLI11 checks
// the name against the table, whose names and descriptions the help lists, and the table
// gives the value.
template <class Enum>
CLI::Option* add_choice_option(CLI::App& cmd, const std::string& flag, Enum& value,
                               const std::string& what) {
  return cmd
      .add_option_function<std::string>(
          flag, [&value](const std::string& name) { value = granshock::parse_choice<Enum>(name); },
          what + " (" + granshock::choice_help<Enum>() + "; default " +
              granshock::choice_name(value) + ")")
      ->check(CLI::IsMember(granshock::choice_names<Enum>()));
}

// The same for a choice whose default depends on other options: `value` stays empty unless
// the option is given, and the help says the default as `default_is` does.
template <class Enum>
CLI::Option* add_choice_option(CLI::App& cmd, const std::string& flag, std::optional<Enum>& value,
                               const std::string& what, const std::string& default_is) {
  return cmd
      .add_option_function<std::string>(
          flag, [&value](const std::string& name) { value = granshock::parse_choice<Enum>(name); },
          what + " (" + granshock::choice_help<Enum>() + "; default " + default_is + ")")
      ->check(CLI::IsMember(granshock::choice_names<Enum>()));
}

void add_collide_command(CLI::App& app, granshock::CollisionOptions& o,
                         std::optional<granshock::ImpactLine>& along) {
  auto* cmd = app.add_subcommand("collide",
                                 "head-on collision of two particles or a particle and "
                                 "the fixed obstacle (a cylinder unless --shape); prints JSON");
  cmd->add_option("--pair", o.pair,
                  "steel-steel | steel-aluminium | aluminium-aluminium | steel-obstacle | "
                  "aluminium-obstacle")
      ->required();
  cmd->add_option("--speed", o.speed_m_per_s, "relative normal impact speed (m/s)")->required();
  cmd->add_option("--dt", o.dt, "time step (s); default t_c/100");
  cmd->add_option("--e", o.restitution, "coefficient of restitution, in [0.01, 1]; default 0.5");
  add_choice_option(*cmd, "--model", o.model, "contact law");
  // One option per law parameter key (models/law_parameters.hpp), as in scenes.
  granshock::for_each_law_parameters([&](auto parameters) {
    for (const granshock::LawKey& k : parameters.keys) {
      const bool speed = k.fallback == granshock::LawKey::Default::inflow_speed;
      cmd->add_option(granshock::key_option(k.name), o.law_parameters[k.name],
                      fmt::format("{}: {}, {}; {}", granshock::choice_name(parameters.kind),
                                  k.meaning, k.type, speed ? "default --speed" : "required"));
    }
  });
  add_choice_option(*cmd, "--shape", o.shape,
                    "the obstacle's shape, for an -obstacle pair (docs/scene_format.md, "
                    "\"Obstacle shapes\")",
                    "cylinder");
  // One option per size key of the shapes (models/obstacle_shapes.hpp), as in scenes; a key
  // that several shapes share is one option.
  granshock::for_each_obstacle_shape([&](auto shape) {
    for (const granshock::ShapeKey& k : shape.keys) {
      if (o.shape_sizes.count(k.name)) continue;
      std::vector<std::string> owners;
      for (const granshock::ObstacleShape owner : granshock::shapes_with_key(k.name))
        owners.push_back(granshock::choice_name(owner));
      cmd->add_option(
          granshock::key_option(k.name), o.shape_sizes[k.name],
          fmt::format("--shape {}: {}, in {}; default {:g}", fmt::join(owners, " or "), k.meaning,
                      granshock::collision_shape_range(k), granshock::collision_shape_size(k)));
    }
  });
  cmd->add_flag("--limit-force", o.limit_force,
                "clamp the normal force at zero (no attraction at the end of contact)");
  add_choice_option(*cmd, "--precision", o.precision, "arithmetic of the contact");
  cmd->add_flag("--force", o.force, "run even when dt is past the stable limit");
  add_choice_option(*cmd, "--restitution-mode", o.restitution_mode,
                    "how the damping is found; discrete calibrates it at this speed and dt");
  cmd->add_option("--phase", o.phase,
                  "the first contact step overlaps by phase x speed x dt, in (0, 1]; default 1");
  cmd->add_option("--at", o.place.centre,
                  "X,Y: where the impact happens (m; for the obstacle its centre), e.g. 0.5,0 "
                  "at the far edge of the paper's 500 d box; default 0,0")
      ->delimiter(',');
  add_choice_option(*cmd, "--along", along, "the line of impact",
                    "x for two particles, y (the flow's, onto the upstream surface) for the "
                    "obstacle");
}

// --no-figures of run, fields, study and tradeoff (analysis/figure_switch.hpp).
void add_no_figures_flag(CLI::App& cmd, bool& figures) {
  cmd.add_flag_callback(
      "--no-figures", [&figures] { figures = false; },
      "write every output but the PNG figures (also GRANSHOCK_FIGURES=0); a last line "
      "names the command that draws them later");
}

// --stop-after-steps of run and study, --slice-steps of run: CLI11's message when it is not a
// positive count.
std::string positive_step_count(const std::string& steps) {
  return std::strtol(steps.c_str(), nullptr, 10) >= 1
             ? std::string()
             : std::string("must be a positive number of steps");
}

// --case of study: a whole number that fits (CLI11 would saturate 1e30 to LONG_MAX); the
// study, once read, says which numbers are its cases.
std::string whole_case_number(const std::string& text) {
  errno = 0;
  char* end = nullptr;
  std::strtol(text.c_str(), &end, 10);
  return !text.empty() && *end == '\0' && errno == 0
             ? std::string()
             : text + " is not a case number (0, 1, 2, ...)";
}

// The first argument, where it names no command ("granshock runn"): CLI11 said only "A
// subcommand is required". Names it, with the command it looks like and the commands.
std::string unknown_command(CLI::App& app, int argc, char** argv) {
  if (argc < 2 || argv[1][0] == '-') return {};
  const std::string typed = argv[1];
  std::vector<std::string> names;
  for (const CLI::App* command : app.get_subcommands({})) names.push_back(command->get_name());
  if (std::find(names.begin(), names.end(), typed) != names.end()) return {};
  const std::string nearest = granshock::nearest_name(typed, names);
  return fmt::format("unknown command {}{}; the commands are {} (see granshock --help)",
                     granshock::quoted_input(typed),
                     nearest.empty() ? "" : " (did you mean '" + nearest + "'?)",
                     fmt::join(names, ", "));
}

// An input that must exist (a run directory, a dump file, a map), named as the user gave it:
// CLI11's own check said "dirs: Path does not exist".
CLI::Validator existing_input(const std::string& what) {
  return CLI::Validator(
      [what](std::string& path) {
        std::error_code ec;
        return std::filesystem::exists(std::filesystem::symlink_status(path, ec))
                   ? std::string()
                   : granshock::quoted_input(path, 1024) + " does not exist: " + what;
      },
      "PATH");
}

// --accuracy: the budget as parse_error_budget reads it, refused at once, so that an empty
// value is not taken for no budget at all.
std::string error_budget(const std::string& text) {
  try {
    granshock::parse_error_budget(text);
    return std::string();
  } catch (const granshock::UserError& e) {
    // CLI11 names the option before the message.
    const std::string why = e.what(), flag = "--accuracy ";
    return why.compare(0, flag.size(), flag) == 0 ? why.substr(flag.size()) : why;
  }
}

// --accuracy and --accuracy-table, which means nothing without it (run, study).
template <class Options>
void add_accuracy_options(CLI::App& cmd, Options& o, const std::string& budget_help,
                          const std::string& table_help) {
  CLI::Option* budget = cmd.add_option("--accuracy", o.accuracy, budget_help)->check(error_budget);
  cmd.add_option("--accuracy-table", o.accuracy_table, table_help)
      ->check(CLI::ExistingFile)
      ->needs(budget);
}

void add_run_command(CLI::App& app, granshock::RunOptions& o) {
  auto* cmd = app.add_subcommand("run", "simulate a bow-shock scene and write its run directory");
  cmd->add_option("scene", o.scene_file, "scene file (TOML)")->required();
  cmd->add_option("--out", o.out_dir, "run directory (default: runs/<scene name>)")
      ->check([](const std::string& dir) {
        return dir.empty() ? std::string("the directory name is empty") : std::string();
      });
  cmd->add_option("--set", o.overrides,
                  "override a scene key, e.g. --set inflow.mach=13.7 (repeatable)");
  cmd->add_flag("--overwrite", o.overwrite, "replace an existing run directory");
  cmd->add_flag("--resume", o.resume, "continue the run in --out from its last checkpoint");
  cmd->add_flag("--force", o.force, "run even when dt is past the stable limit");
  cmd->add_option("--stop-after-steps", o.stop_after_steps,
                  "write a checkpoint and stop after this many steps (for batch-job time limits)")
      ->check(positive_step_count);
  cmd->add_option("--slice-steps", o.slice_steps,
                  "advance between progress checks in slices of at most this many steps, "
                  "not about 0.25 s of wall time (for instruction counts under valgrind, "
                  "docs/benchmarks.md); the results are the same bit for bit")
      ->check(positive_step_count);
  cmd->add_flag("--quiet", o.quiet, "no progress lines");
  add_choice_option(*cmd, "--balance", o.balance,
                    "under mpirun: where the slab boundaries lie (docs/parallel.md); the "
                    "results are the same bit for bit");
  add_choice_option(*cmd, "--slabs", o.slabs,
                    "under mpirun: the axis each process's slab of cell rows lies along "
                    "(docs/parallel.md); the results are the same bit for bit");
  add_choice_option(*cmd, "--backend-switch", o.backend_switch,
                    "one process on several threads: whether the run moves to one thread "
                    "while another process is busy on the machine (docs/benchmarks.md, \"A "
                    "busy machine\"); the results are the same bit for bit");
  add_choice_option(*cmd, "--thread-shares", o.thread_shares,
                    "one process on several threads, small scenes: how the threads share the "
                    "particles (docs/benchmarks.md, \"Threads on a small scene\"); the results "
                    "are the same bit for bit");
  add_choice_option(*cmd, "--snapshot-output", o.snapshot_output,
                    "under mpirun: how snapshots reach run.h5 (docs/parallel.md); the files "
                    "are the same bit for bit");
  cmd->add_flag("--dry-run", o.dry_run,
                "check the scene and the output directory, print the resolved scene, write "
                "nothing");
  add_accuracy_options(*cmd, o,
                       "error budget, e.g. 2%: choose dt, stiffness softening and precision from "
                       "a measured trade table (docs/accuracy.md) and say what was chosen",
                       "the trade.json of `granshock tradeoff` to choose from (default: the "
                       "paper case's, docs/results/certificate/d50_u2375)");
  add_no_figures_flag(*cmd, o.figures);
}

void add_fields_command(CLI::App& app, std::vector<std::filesystem::path>& dirs,
                        std::filesystem::path& out, granshock::FieldsCommandOptions& o,
                        granshock::FromDumpOptions& dump) {
  auto* cmd = app.add_subcommand("fields",
                                 "recompute fields, figures and summary from DIR/run.h5; "
                                 "with several DIRs also the delta/D table and figure");
  cmd->add_option("DIR", dirs, "run directories (with --from-dump: the dump files, in time order)")
      ->required()
      ->check(existing_input("granshock fields reads run directories (with --from-dump, dump "
                             "files)"));
  cmd->add_option("--from-dump", dump.format,
                  "analyse the particles of another code's dump files instead of run "
                  "directories: lammps | liggghts (needs --map and --out; docs/fields.md)")
      ->check(CLI::IsMember({"lammps", "liggghts"}));
  cmd->add_option("--map", dump.map,
                  "with --from-dump: the scene and the atom types' species (TOML)")
      ->check(existing_input("the map is a scene file with a [dump] table (docs/fields.md)"));
  cmd->add_option("--out", out,
                  "where to write (required with several DIRs): a new or empty directory, or "
                  "one granshock fields wrote before");
  add_no_figures_flag(*cmd, o.figures);
}

void add_export_command(CLI::App& app, granshock::ExportOptions& o) {
  auto* cmd = app.add_subcommand(
      "export", "write a run's snapshots as a LAMMPS dump custom text file (OVITO, read_dump)");
  cmd->add_option("DIR", o.run_dir, "run directory")
      ->required()
      ->check(existing_input("granshock export reads a run directory"));
  cmd->add_option("--lammps-dump", o.lammps_dump,
                  "the dump to write: id type x y z vx vy vz radius, ids and types from 1")
      ->required();
  cmd->add_option("--map", o.map,
                  "also write the map `granshock fields --from-dump` needs for the dump");
  cmd->add_flag("--quiet", o.quiet, "no result line on stdout");
}

void add_study_command(CLI::App& app, granshock::StudyOptions& o) {
  auto* cmd = app.add_subcommand(
      "study",
      "run a parameter study: every case of STUDY.toml into its own run directory, "
      "then the study table and figures (docs/study.md)");
  cmd->add_option("study", o.study_file, "study file (TOML)")->required();
  cmd->add_option("--out", o.out_dir,
                  "study directory (default: the study file's out, else "
                  "runs/<study name>)");
  cmd->add_option("--set", o.overrides,
                  "override a scene key in every case, after the study file's [study] set, e.g. "
                  "--set time.duration=2.0 (repeatable)");
  cmd->add_option_function<long>(
         "--case", [&o](const long& k) { o.only_case = k; },
         "run only case K (0-based; for Slurm array tasks)")
      ->check(whole_case_number);
  cmd->add_flag("--collect", o.collect,
                "build the table and figures from the finished cases; run nothing");
  add_accuracy_options(*cmd, o,
                       "error budget, e.g. 5%: each case's dt, stiffness softening and "
                       "precision chosen from a measured trade table for its own scene "
                       "(docs/study.md)",
                       "the trade.json to choose from (default: the paper case's)");
  cmd->add_option_function<std::string>(
         "--emit",
         [&o](const std::string& name) {
           o.emit = granshock::parse_choice<granshock::BatchScript>(name);
         },
         "write a batch script into the study directory instead of running (" +
             granshock::choice_help<granshock::BatchScript>() + ")")
      ->check(CLI::IsMember(granshock::choice_names<granshock::BatchScript>()));
  cmd->add_flag("--dry-run", o.dry_run,
                "check every case, list them with their overrides and expected cost; write "
                "nothing");
  cmd->add_option("--stop-after-steps", o.stop_after_steps,
                  "the running case writes a checkpoint and stops after this many steps, and "
                  "the study with it")
      ->check(positive_step_count);
  cmd->add_flag("--quiet", o.quiet, "no progress lines from the runs");
  add_no_figures_flag(*cmd, o.figures);
}

void add_tradeoff_command(CLI::App& app, granshock::TradeoffOptions& o) {
  auto* cmd = app.add_subcommand(
      "tradeoff",
      "run a scene at a reference (dt = t_c/100) and at one cheaper setting per case, then "
      "the table of speed-up against every difference and its noise (docs/accuracy.md)");
  cmd->add_option("scene", o.scene_file, "scene file (TOML)")->required();
  cmd->add_option("--out", o.out_dir, "study directory (default: runs/tradeoff_<scene name>)");
  cmd->add_option("--set", o.overrides,
                  "override a scene key in every case, e.g. --set time.duration=0.1 (repeatable)");
  cmd->add_flag("--collect", o.collect, "build the table from the finished cases; run nothing");
  cmd->add_flag("--dry-run", o.dry_run,
                "list the cases with their overrides and expected cost; write nothing");
  cmd->add_flag("--quiet", o.quiet, "no progress lines from the runs");
  add_no_figures_flag(*cmd, o.figures);
}

// `granshock fields`, and without figures the note of how to draw them later.
int run_fields_command(const std::vector<std::filesystem::path>& dirs,
                       const std::filesystem::path& out, const granshock::FieldsCommandOptions& o,
                       granshock::FromDumpOptions dump) {
  if (dump.format.empty() && !dump.map.empty())
    throw granshock::UserError("--map is the map of --from-dump, which is not given");
  const bool from_dump = !dump.format.empty();
  int code = 0;
  if (from_dump) {
    dump.files = dirs;
    dump.out = out;
    code = granshock::from_dump_command(dump, o);
  } else {
    for (const std::filesystem::path& dir : dirs)
      if (std::filesystem::is_regular_file(dir))
        throw granshock::UserError("'" + dir.string() +
                                   "' is a file, not a run directory (a LAMMPS or LIGGGHTS dump "
                                   "is read with --from-dump lammps|liggghts --map MAP.toml)");
    code = granshock::fields_command(dirs, out, o);
  }
  if (o.figures) return code;
  std::vector<std::string> redraw{"granshock", "fields"};
  if (from_dump)
    redraw.insert(redraw.end(), {"--from-dump", dump.format, "--map", dump.map.string()});
  for (const std::filesystem::path& dir : dirs) redraw.push_back(dir.string());
  if (!out.empty()) redraw.insert(redraw.end(), {"--out", out.string()});
  std::cerr << granshock::figures_skipped_note(redraw) << "\n";
  return code;
}

}  // namespace

#if defined(__ELF__)
// SIGINT and SIGTERM are held from before the shared libraries initialise (MPI, HDF5 and
// Kokkos take milliseconds before main): an executable's .preinit_array runs right after
// the dynamic loader, before any library's constructor.
extern "C" void granshock_hold_interrupts_at_load(int, char**, char**) {
  granshock::hold_interrupts();
  // Also before the static constructors of the solver's code (this executable's
  // .init_array), which a -march=native build compiles for its build machine's CPU.
  granshock::exit_unless_this_cpu_runs_the_build();
}
__attribute__((section(".preinit_array"), used)) static void (*const hold_interrupts_at_load)(
    int, char**, char**) = granshock_hold_interrupts_at_load;
#endif

int main(int argc, char** argv) {
  // First (again, where .preinit_array is not): a signal while MPI and Kokkos start waits
  // until the command is known (cases/bow_shock/interrupt.hpp).
  granshock::hold_interrupts();
  // Before any of the solver's code, which may use instructions this CPU lacks (again,
  // where .preinit_array is not).
  granshock::exit_unless_this_cpu_runs_the_build();
  granshock::keep_large_blocks();  // before the first large allocation (core/large_blocks.hpp)
  CLI::App app{"granshock: GPU-portable DEM for granular gas dynamics"};
  app.set_version_flag("--version", granshock::version_line(),
                       "print the version, commit and build, and exit");
  app.require_subcommand(1);
  app.allow_extras(false);
  granshock::CollisionOptions collide;
  std::optional<granshock::ImpactLine> along;
  add_collide_command(app, collide, along);
  granshock::RunOptions run;
  add_run_command(app, run);
  std::vector<std::filesystem::path> field_dirs;
  std::filesystem::path field_out;
  granshock::FieldsCommandOptions field_options;
  granshock::FromDumpOptions field_dump;
  add_fields_command(app, field_dirs, field_out, field_options, field_dump);
  granshock::StudyOptions study;
  add_study_command(app, study);
  granshock::ExportOptions export_options;
  add_export_command(app, export_options);
  granshock::TradeoffOptions tradeoff;
  add_tradeoff_command(app, tradeoff);
  auto* info = app.add_subcommand("info", "version, Kokkos backends and threads, build options");
  auto* keys = app.add_subcommand(
      "keys",
      "every scene-file key with its type, unit, accepted values, default and meaning, as "
      "the Markdown table of docs/scene_keys.md");

  // Writes past a file-size limit fail with EFBIG, reported like a full disk, instead of
  // killing the process (SIGXFSZ).
  std::signal(SIGXFSZ, SIG_IGN);
  granshock::h5::keep_exit_free_of_hdf5();
  // Kokkos takes its own --kokkos-* arguments; CLI11 sees the rest (--help included:
  // device/kokkos_runtime.hpp).
  // MPI before Kokkos, which may bind devices by MPI rank.
  std::optional<granshock::MpiRuntime> mpi;
  std::optional<granshock::KokkosRuntime> kokkos;
  try {
    mpi.emplace(argc, argv);
  } catch (const std::exception& e) {
    std::cerr << "granshock: error: cannot start MPI: " << one_line(e.what()) << "\n";
    return 5;
  }
  try {
    kokkos.emplace(argc, argv);
  } catch (const std::exception& e) {
    std::cerr << "granshock: error: cannot start Kokkos on this machine: " << one_line(e.what())
              << "\n";
    return 5;
  }
  // CLI11 takes an empty value for a missing one; say what is wrong instead.
  for (int k = 1; k < argc; ++k) {
    const std::string arg = argv[k];
    if (arg == "--out=" || (arg == "--out" && k + 1 < argc && argv[k + 1][0] == '\0')) {
      std::cerr << "granshock: error: --out: the directory name is empty\n";
      return 2;
    }
  }
  if (const std::string unknown = unknown_command(app, argc, argv); !unknown.empty()) {
    std::cerr << "granshock: error: " << unknown << "\n";
    return 2;
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return app.exit(e);  // --help
    // One line and exit code 2, like every other user error (docs/stability.md, "Exit codes").
    std::cerr << "granshock: error: " << one_line(e.what()) << " (see granshock "
              << (app.get_subcommands().empty() ? std::string("")
                                                : app.get_subcommands()[0]->get_name() + " ")
              << "--help)\n";
    return 2;
  }
  // A run stops at a safe point with a message, from its very start (docs/output_format.md,
  // "Signals"); the other commands end as signals end them (a study catches them once it
  // runs its cases: cases/study/study_runner.cpp).
  if (app.got_subcommand("run"))
    granshock::catch_interrupts();
  else
    granshock::release_interrupts();
  // Only `run` divides a scene among processes; the other commands would each do the whole
  // job N times into the same place. Every rank decides alike and returns, so none waits
  // for another; rank 0 alone says why.
  const bool several = mpi->size() > 1;
  if (several && !info->parsed() && !keys->parsed() && !app.got_subcommand("run")) {
    if (mpi->rank() == 0)
      std::cerr << "granshock: error: started as " << mpi->size()
                << " MPI processes, but `granshock " << app.get_subcommands()[0]->get_name()
                << "` runs in one process (only `granshock run` divides a scene among processes: "
                   "docs/parallel.md); run it without mpirun and set the threads with "
                   "OMP_NUM_THREADS\n";
    return 2;
  }
  // How a failure ends the program on several processes (failure_agreement.hpp). A
  // failure every rank meets at the same step (from global sums) is said by rank 0 and
  // ends every rank alike. Any other is said by the rank that met it (after an agreement,
  // the others threw PeerFailed and stay quiet); unless agreed on, it ends the whole job,
  // so that no rank waits for this one in a collective operation.
  const auto leave = [&](int code, const std::string& message, bool met_by_every_rank) {
    const bool speaks = !several || (met_by_every_rank ? mpi->rank() == 0 : true);
    if (speaks)
      std::cerr << (mpi->rank() == 0 ? "" : fmt::format("[rank {}] ", mpi->rank())) << message
                << "\n";
    if (several && !met_by_every_rank && !granshock::failure_agreed()) {
      std::cerr.flush();
      mpi->abort(code);
    }
    return code;
  };
  try {
    if (app.got_subcommand("run")) {
      if (!several) return granshock::run_scene(run);
      const granshock::MpiCommunicator world;
      return granshock::run_scene(run, world);
    }
    if (app.got_subcommand("fields"))
      return run_fields_command(field_dirs, field_out, field_options, field_dump);
    if (app.got_subcommand("study")) return granshock::study_command(study);
    if (app.got_subcommand("export")) return granshock::export_command(export_options);
    if (app.got_subcommand("tradeoff")) return granshock::tradeoff_command(tradeoff);
    if (info->parsed()) {
      if (mpi->rank() == 0) std::cout << granshock::build_info_json(mpi->size()) << "\n";
    } else if (keys->parsed()) {
      if (mpi->rank() == 0) std::cout << granshock::scene_keys_table();
    } else if (app.got_subcommand("collide")) {
      if (along) collide.place.axis = int(*along);
      const auto result = granshock::run_head_on_collision(collide);
      if (result.time_step.verdict != granshock::TimeStepAssessment::Verdict::ok)
        std::cerr << "granshock: warning: " << result.time_step.message << "\n";
      if (result.overlap.verdict != granshock::TimeStepAssessment::Verdict::ok)
        std::cerr << "granshock: warning: " << result.overlap.message << "\n";
      std::cout << granshock::to_json(result) << "\n";
    }
  } catch (const granshock::PeerFailed& e) {
    return e.exit_code();  // another rank failed and said why
  } catch (const granshock::NumericalFailure& e) {
    // From global sums: every rank meets it at the same step.
    return leave(4, "granshock: error: " + one_line(e.what()), true);
  } catch (const granshock::UserError& e) {
    return leave(2, "granshock: error: " + one_line(e.what()), false);
  } catch (const std::bad_alloc& e) {
    return leave(
        2,
        "granshock: error: not enough memory (" + one_line(e.what()) + "); make the scene smaller",
        false);
  } catch (const std::exception& e) {
    // Kokkos reports an allocation it could not make as a runtime_error.
    if (const auto memory = granshock::allocation_failure(e.what()))
      return leave(2, "granshock: error: " + *memory, false);
    return leave(3, "granshock: internal error: " + one_line(e.what()), false);
  }
  return 0;
}
