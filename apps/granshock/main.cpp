// granshock: the command-line program (DESIGN.md section 3).
#include <CLI/CLI.hpp>
#include <Kokkos_Core.hpp>
#include <cstdio>
#include <iostream>
#include <map>

#include "build_info.hpp"
#include "head_on_collision.hpp"
#include "kokkos_runtime.hpp"
#include "user_error.hpp"

namespace {

void add_collide_command(CLI::App& app, granshock::CollisionOptions& o, std::string& precision) {
  auto* cmd = app.add_subcommand("collide", "head-on collision of two particles or a particle and "
                                            "the fixed cylinder; prints JSON");
  cmd->add_option("--pair", o.pair,
                  "steel-steel | steel-aluminium | aluminium-aluminium | steel-wall | "
                  "aluminium-wall")
      ->required();
  cmd->add_option("--speed", o.speed_m_per_s, "relative normal impact speed (m/s)")->required();
  cmd->add_option("--dt", o.dt, "time step (s); default t_c/100");
  cmd->add_option("--e", o.restitution, "coefficient of restitution, in (0, 1]; default 0.5");
  cmd->add_flag("--limit-force", o.limit_force,
                "clamp the normal force at zero (no attraction at the end of contact)");
  cmd->add_option("--precision", precision, "double | single")
      ->check(CLI::IsMember({"double", "single"}));
  cmd->add_flag("--force", o.force, "run even when dt is past the stable limit");
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"granshock: GPU-portable DEM for granular gas dynamics"};
  app.require_subcommand(1);
  app.allow_extras(false);
  granshock::CollisionOptions collide;
  std::string precision = "double";
  add_collide_command(app, collide, precision);
  auto* info = app.add_subcommand("info", "version, Kokkos backends and threads, build options");

  // Kokkos takes its own --kokkos-* arguments; CLI11 sees the rest.
  granshock::KokkosRuntime kokkos(argc, argv);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  }
  try {
    if (info->parsed()) {
      std::cout << granshock::build_info_json() << "\n";
    } else if (app.got_subcommand("collide")) {
      collide.precision =
          precision == "single" ? granshock::Precision::single : granshock::Precision::dual;
      const auto result = granshock::run_head_on_collision(collide);
      if (result.time_step.verdict != granshock::TimeStepAssessment::Verdict::ok)
        std::cerr << "granshock: warning: " << result.time_step.message << "\n";
      std::cout << granshock::to_json(result) << "\n";
    }
  } catch (const granshock::UserError& e) {
    std::cerr << "granshock: error: " << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "granshock: internal error: " << e.what() << "\n";
    return 3;
  }
  return 0;
}
