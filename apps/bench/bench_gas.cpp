// granshock_bench_gas: particle-steps per second of a homogeneous 2-D granular gas in a
// periodic box (the paper's steel/aluminium mixture, d = 1 mm, dt = 5e-7 s), through the
// public solver API only (make_solver / set_particles / advance).
//
// For each (area fraction, particle count): build the gas, warm up, then time
// `repeats` runs of at least `min-seconds` each and print one table row with the
// median, min and max particle-steps per second over the repeats, the neighbour-list
// builds per 1000 steps and the contacts per particle at the end.
//
// Threads: OMP_NUM_THREADS or --kokkos-threads=N (Kokkos 3.4 removes its own
// --kokkos-* arguments before the benchmark's options are parsed).
#include <unistd.h>
#include <CLI/CLI.hpp>
#include <Kokkos_Core.hpp>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "cases/gas/homogeneous_gas.hpp"
#include "core/choice_names.hpp"
#include "core/cpu_model.hpp"
#include "core/process_clock.hpp"
#include "core/solver.hpp"
#include "core/user_error.hpp"
#include "io/atomic_file.hpp"
#include "kernels/device/kokkos_runtime.hpp"

namespace {

struct Options {
  std::vector<int> particles{5000, 32000};
  std::vector<double> phi{0.1};
  int dim = 2;  // 3: spheres in a periodic cube (double precision only)
  std::string precision = granshock::choice_name(granshock::Precision::double_precision);
  int repeats = 5;
  double min_seconds = 1.0;
  int warmup_steps = 300;
  double warmup_seconds = 0.2;
  double restitution = 0.5;
  double sigma = 1.0;
  std::string placement = "lattice";  // or "random" (cases/gas/homogeneous_gas.hpp)
  double dt = 5e-7;
  double skin_d = 0;  // Verlet skin in diameters; 0 keeps the solver's default
  bool exact_list_check = false;
  bool adaptive_skin = false;
  bool two_visit_list = false;
  long steps_per_region = 0;  // 0 keeps the solver's default
  double min_cpu_share = 0.9;
  int retries = 5;
  std::string json_path;
};

struct Row {
  int dim = 2;
  double phi = 0;
  int particles = 0;
  int threads = 0;
  std::string variant;
  double box_length_m = 0;
  long warmup_steps = 0;
  double warmup_seconds = 0;
  std::vector<long> steps;
  std::vector<double> seconds;
  std::vector<double> rates;  // particle-steps per second, one per repeat
  // Process CPU time / (wall time x threads), one per repeat: close to 1 when the
  // benchmark had its cores to itself (OpenMP threads spin between kernels), clearly
  // below 1 when other processes competed for them and the timing is unreliable.
  std::vector<double> cpu_utilisation;
  // Repeats thrown away (and run again) because they got less than --min-cpu-share.
  std::vector<double> rejected_rates, rejected_cpu_utilisation;
  double median = 0, min = 0, max = 0;
  double builds_per_1000_steps = 0;
  double exact_checks_per_1000_steps = 0;  // extra displacement passes (rebuild_watch.hpp)
  double steps_per_region = 0;             // timed steps / parallel regions that ran them
  double skin_at_end_d = 0;                // the skin of the last list, in diameters
  double contacts_per_particle = 0;
  // Resident memory the solver added, from before make_solver to the end of the warm-up
  // (every array allocated and touched), per particle; and what the process gained over
  // the timed repeats (a leak or a growing list would show here).
  double solver_bytes_per_particle = 0;
  double timed_growth_bytes = 0;
};

double median_of(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

std::string kokkos_version() {
  return std::to_string(KOKKOS_VERSION / 10000) + "." + std::to_string(KOKKOS_VERSION / 100 % 100) +
         "." + std::to_string(KOKKOS_VERSION % 100);
}

// The process's resident set (Linux /proc/self/statm), in bytes; 0 where unreadable.
double resident_bytes() {
  std::ifstream statm("/proc/self/statm");
  double size_pages = 0, resident_pages = 0;
  if (!(statm >> size_pages >> resident_pages)) return 0;
  return resident_pages * double(sysconf(_SC_PAGESIZE));
}

// Advances in chunks until both at least `min_steps` steps and `min_seconds` have
// passed; returns (steps, seconds). The solver's rebuild test copies a scalar to the
// host every step, so advance() is synchronous; the fences make that explicit.
std::pair<long, double> run_at_least(granshock::Solver& solver, long chunk, long min_steps,
                                     double min_seconds) {
  Kokkos::fence();
  Kokkos::Timer timer;
  long steps = 0;
  double elapsed = 0;
  do {
    solver.advance(chunk);
    Kokkos::fence();
    steps += chunk;
    elapsed = timer.seconds();
  } while (steps < min_steps || elapsed < min_seconds);
  return {steps, elapsed};
}

Row bench_one(const Options& o, double phi, int n_wanted) {
  granshock::SolverSetup setup = granshock::paper_mixture(o.restitution);
  setup.dim = o.dim;
  setup.dt = o.dt;
  if (o.skin_d > 0) setup.skin_m = o.skin_d * setup.max_diameter();
  setup.exact_list_check = o.exact_list_check;
  setup.adaptive_skin = o.adaptive_skin;
  setup.list_visits_once = !o.two_visit_list;
  if (o.steps_per_region > 0) setup.steps_per_region = o.steps_per_region;
  setup.precision = granshock::parse_choice<granshock::Precision>(o.precision);
  granshock::GasSpec spec;
  spec.particles = n_wanted;
  spec.area_fraction = phi;
  spec.sigma_m_per_s = o.sigma;
  spec.placement =
      o.placement == "random" ? granshock::GasPlacement::random : granshock::GasPlacement::lattice;
  granshock::size_periodic_box(setup, spec);
  const granshock::HostParticles gas = granshock::make_homogeneous_gas(setup, spec);
  const double resident_before = resident_bytes();
  auto solver = granshock::make_solver(setup, gas.size());
  solver->set_particles(gas);

  Row row;
  row.dim = o.dim;
  row.phi = phi;
  row.particles = int(solver->size());
  row.threads = Kokkos::DefaultExecutionSpace().concurrency();
  row.variant = solver->variant();
  row.box_length_m = setup.box.length(0);

  // Warm-up: doubling chunks until warmup_steps steps or warmup_seconds have passed
  // (whichever comes first), but at least two chunks, so that the rate estimate is not
  // the very first step alone.
  {
    Kokkos::fence();
    Kokkos::Timer timer;
    long chunk = 1, chunks = 0;
    while (chunks < 2 ||
           (row.warmup_steps < o.warmup_steps && timer.seconds() < o.warmup_seconds)) {
      solver->advance(chunk);
      Kokkos::fence();
      row.warmup_steps += chunk;
      ++chunks;
      chunk *= 2;
    }
    row.warmup_seconds = timer.seconds();
  }
  const double resident_warm = resident_bytes();
  row.solver_bytes_per_particle = (resident_warm - resident_before) / double(row.particles);
  const double steps_per_second = double(row.warmup_steps) / row.warmup_seconds;
  const long planned = std::max(1L, long(std::ceil(o.min_seconds * steps_per_second)));
  const long chunk = std::max(1L, planned / 10);

  // A repeat during which other processes took part of our cores measures them, not
  // the solver: it is run again, at most `retries` times per case.
  const long builds_before = solver->list_builds();
  const long checks_before = solver->exact_list_checks();
  const long regions_before = solver->step_regions();
  long timed_steps = 0;
  while (int(row.rates.size()) < o.repeats) {
    const double cpu_before = granshock::process_cpu_seconds();
    const auto [steps, seconds] = run_at_least(*solver, chunk, planned, o.min_seconds);
    const double share =
        (granshock::process_cpu_seconds() - cpu_before) / (seconds * double(row.threads));
    const double rate = double(row.particles) * double(steps) / seconds;
    timed_steps += steps;
    if (share < o.min_cpu_share && int(row.rejected_rates.size()) < o.retries) {
      row.rejected_rates.push_back(rate);
      row.rejected_cpu_utilisation.push_back(share);
      continue;
    }
    row.cpu_utilisation.push_back(share);
    row.steps.push_back(steps);
    row.seconds.push_back(seconds);
    row.rates.push_back(rate);
  }
  row.median = median_of(row.rates);
  row.min = *std::min_element(row.rates.begin(), row.rates.end());
  row.max = *std::max_element(row.rates.begin(), row.rates.end());
  row.builds_per_1000_steps =
      1000.0 * double(solver->list_builds() - builds_before) / double(timed_steps);
  row.exact_checks_per_1000_steps =
      1000.0 * double(solver->exact_list_checks() - checks_before) / double(timed_steps);
  row.steps_per_region =
      double(timed_steps) / double(std::max(1L, solver->step_regions() - regions_before));
  row.contacts_per_particle = double(solver->diagnostics().contacts) / double(row.particles);
  row.skin_at_end_d = solver->skin() / setup.max_diameter();
  row.timed_growth_bytes = resident_bytes() - resident_warm;
  return row;
}

void print_table_header() {
  std::printf(
      "| phi | N | threads | variant | median p-steps/s | min | max | "
      "builds/1000 steps | contacts/particle | bytes/particle | growth (kB) |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|---|---|\n");
}

void print_row(const Row& r) {
  std::printf("| %.3g | %d | %d | %s | %.3e | %.3e | %.3e | %.2f | %.4f | %.0f | %.0f |\n", r.phi,
              r.particles, r.threads, r.variant.c_str(), r.median, r.min, r.max,
              r.builds_per_1000_steps, r.contacts_per_particle, r.solver_bytes_per_particle,
              r.timed_growth_bytes / 1024);
  std::fflush(stdout);
}

nlohmann::json to_json(const Row& r) {
  return {{"phi", r.phi},
          {"particles", r.particles},
          {"threads", r.threads},
          {"dim", r.dim},
          {"variant", r.variant},
          {"box_length_m", r.box_length_m},
          {"solver_bytes_per_particle", r.solver_bytes_per_particle},
          {"timed_growth_bytes", r.timed_growth_bytes},
          {"warmup_steps", r.warmup_steps},
          {"warmup_seconds", r.warmup_seconds},
          {"steps", r.steps},
          {"seconds", r.seconds},
          {"particle_steps_per_second", r.rates},
          {"cpu_utilisation", r.cpu_utilisation},
          {"rejected_particle_steps_per_second", r.rejected_rates},
          {"rejected_cpu_utilisation", r.rejected_cpu_utilisation},
          {"median", r.median},
          {"min", r.min},
          {"max", r.max},
          {"list_builds_per_1000_steps", r.builds_per_1000_steps},
          {"exact_list_checks_per_1000_steps", r.exact_checks_per_1000_steps},
          {"steps_per_region", r.steps_per_region},
          {"skin_diameters_at_end", r.skin_at_end_d},
          {"contacts_per_particle", r.contacts_per_particle}};
}

}  // namespace

int main(int argc, char** argv) {
  // Kokkos takes its own --kokkos-* arguments; CLI11 sees the rest, --help included.
  granshock::KokkosRuntime kokkos(argc, argv);

  CLI::App app{
      "granshock_bench_gas: particle-steps per second of a homogeneous granular gas "
      "(paper mixture, periodic box; 2-D disks or, with --dim 3, spheres)"};
  Options o;
  app.add_option("--dim", o.dim, "2: disks in a periodic square; 3: spheres in a periodic cube")
      ->check(CLI::IsMember({2, 3}));
  app.add_option("--particles", o.particles,
                 "particle counts (rounded to a square lattice, cubic with --dim 3)")
      ->delimiter(',')
      ->check(CLI::Range(9, 1 << 30));
  app.add_option("--phi", o.phi,
                 "area fractions, in (0, 0.78); volume fractions with --dim 3, below 0.52")
      ->delimiter(',')
      ->check(CLI::Range(1e-6, 0.78));
  app.add_option("--precision", o.precision, granshock::choice_list<granshock::Precision>())
      ->check(CLI::IsMember(granshock::choice_names<granshock::Precision>()));
  app.add_option("--repeats", o.repeats, "timed repeats per case")->check(CLI::Range(1, 1000));
  app.add_option("--min-seconds", o.min_seconds, "minimum wall time of each repeat (s)")
      ->check(CLI::Range(0.0, 3600.0));
  app.add_option("--warmup-steps", o.warmup_steps,
                 "warm-up ends after this many steps or --warmup-seconds, whichever first")
      ->check(CLI::Range(1, 1 << 30));
  app.add_option("--warmup-seconds", o.warmup_seconds, "warm-up time limit (s)")
      ->check(CLI::Range(0.0, 3600.0));
  app.add_option("--e", o.restitution, "coefficient of restitution, in (0, 1]")
      ->check(CLI::Range(1e-6, 1.0));
  app.add_option("--sigma", o.sigma, "initial velocity standard deviation per component (m/s)")
      ->check(CLI::PositiveNumber);
  app.add_option("--placement", o.placement,
                 "where the particles start: a jittered lattice, or random positions without "
                 "overlap, whose list partners are those of a random gas (up to phi 0.5)")
      ->check(CLI::IsMember({"lattice", "random"}));
  app.add_option("--dt", o.dt, "time step (s); the paper's is 5e-7")->check(CLI::PositiveNumber);
  app.add_option("--skin", o.skin_d,
                 "Verlet-list skin in particle diameters (default: the solver's)")
      ->check(CLI::Range(0.0, 10.0));
  app.add_flag("--exact-list-check", o.exact_list_check,
               "measure every particle's displacement every step instead of bounding it by "
               "the top speed (the same trajectory; to measure what the bound saves)");
  app.add_flag("--adaptive-skin", o.adaptive_skin,
               "let the solver re-choose the skin at each list build, up to --skin "
               "(core/skin_model.hpp)");
  app.add_flag("--two-visit-list", o.two_visit_list,
               "build the Verlet list by counting, then filling (as a device does) instead of "
               "in one visit of the candidates (the same lists; to measure what one visit saves)");
  app.add_option("--steps-per-region", o.steps_per_region,
                 "at most this many steps in one parallel region (1: one region per step; "
                 "default: the solver's, kernels/solver/fused_steps.hpp)")
      ->check(CLI::PositiveNumber);
  app.add_option("--min-cpu-share", o.min_cpu_share,
                 "a repeat whose process CPU time is below this share of wall time x threads "
                 "(other processes competed for the cores) is run again")
      ->check(CLI::Range(0.0, 1.0));
  app.add_option("--retries", o.retries, "most repeats run again per case (see --min-cpu-share)")
      ->check(CLI::Range(0, 1000));
  app.add_option("--json", o.json_path, "write the results as JSON to this file");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  }

  try {
    // Fail before minutes of benchmarking, not after, when the JSON cannot be written.
    if (!o.json_path.empty()) {
      const auto dir = std::filesystem::absolute(o.json_path).parent_path();
      if (!std::filesystem::is_directory(dir))
        throw granshock::UserError("--json " + o.json_path + ": directory " + dir.string() +
                                   " does not exist");
    }
    const int threads = Kokkos::DefaultExecutionSpace().concurrency();
    granshock::SolverSetup mixture = granshock::paper_mixture(o.restitution);
    if (o.skin_d > 0) mixture.skin_m = o.skin_d * mixture.max_diameter();
    const double skin_d = mixture.skin() / mixture.max_diameter();
    std::printf("# granshock_bench_gas: Kokkos %s, backend %s, %d threads, %s precision\n",
                kokkos_version().c_str(), Kokkos::DefaultExecutionSpace::name(), threads,
                o.precision.c_str());
    std::printf("# CPU: %s\n", granshock::cpu_model_name().c_str());
    std::printf(
        "# paper mixture (steel/aluminium, d = 1 mm), e = %g, dt = %g s, sigma = %g m/s, "
        "skin %g d%s, %s start, %d repeats of >= %g s each\n",
        o.restitution, o.dt, o.sigma, skin_d, o.adaptive_skin ? " (adaptive, the largest)" : "",
        o.placement.c_str(), o.repeats, o.min_seconds);
    print_table_header();
    std::fflush(stdout);

    nlohmann::json results = nlohmann::json::array();
    for (const double phi : o.phi)
      for (const int n : o.particles) {
        const Row row = bench_one(o, phi, n);
        print_row(row);
        if (o.adaptive_skin)
          std::printf("# phi %g, N %d: adaptive skin at the end %.3f d\n", phi, row.particles,
                      row.skin_at_end_d);
        const double worst =
            *std::min_element(row.cpu_utilisation.begin(), row.cpu_utilisation.end());
        if (!row.rejected_rates.empty())
          std::fprintf(stderr,
                       "granshock_bench_gas: note: phi %g, N %d: %zu repeat(s) run again because "
                       "other processes took part of the cores\n",
                       row.phi, row.particles, row.rejected_rates.size());
        if (worst < o.min_cpu_share)
          std::fprintf(stderr,
                       "granshock_bench_gas: warning: phi %g, N %d: a repeat got only %.0f%% of "
                       "%d threads' CPU time; other processes competed, timings unreliable\n",
                       row.phi, row.particles, 100 * worst, row.threads);
        results.push_back(to_json(row));
      }

    if (!o.json_path.empty()) {
      nlohmann::json doc = {{"benchmark", "homogeneous_gas_2d"},
                            {"kokkos", kokkos_version()},
                            {"backend", Kokkos::DefaultExecutionSpace::name()},
                            {"threads", threads},
                            {"cpu", granshock::cpu_model_name()},
                            {"precision", o.precision},
                            {"restitution", o.restitution},
                            {"dt_s", o.dt},
                            {"sigma_m_per_s", o.sigma},
                            {"skin_diameters", skin_d},
                            {"list_visits", o.two_visit_list ? 2 : 1},
                            {"repeats", o.repeats},
                            {"min_seconds", o.min_seconds},
                            {"min_cpu_share", o.min_cpu_share},
                            {"results", results}};
      granshock::write_file_atomically(o.json_path, doc.dump(2) + "\n");
    }
  } catch (const granshock::UserError& e) {
    std::cerr << "granshock_bench_gas: error: " << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "granshock_bench_gas: internal error: " << e.what() << "\n";
    return 3;
  }
  return 0;
}
