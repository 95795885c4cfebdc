#include "cases/dump/from_dump_command.hpp"

#include <cmath>
#include <iostream>
#include <limits>
#include <nlohmann/json.hpp>
#include <sstream>

#include "analysis/field_analysis.hpp"
#include "analysis/fields_output.hpp"
#include "analysis/figures.hpp"
#include "analysis/summary_json.hpp"
#include "cases/dump/dump_sums.hpp"
#include "core/user_error.hpp"
#include "io/fields_directory.hpp"

namespace granshock {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
const char* const kNoVirial =
    "a particle dump holds no contact forces, so the collisional pressure is not measured";

void drop_collisional(BinFields& f) {
  for (std::vector<double>* v :
       {&f.p_col_xx, &f.p_col_xy, &f.p_col_yx, &f.p_col_yy, &f.pressure, &f.eos_deviation})
    v->assign(v->size(), kNaN);
}

std::string number(double v) {
  if (!std::isfinite(v)) return "n/a";
  std::ostringstream s;
  s.precision(3);
  s << v;
  return s.str();
}

}  // namespace

void drop_collisional_pressure(FieldAnalysis& a) {
  drop_collisional(a.fields);
  drop_collisional(a.profile_fields);
  a.eos.dilute_mean = a.eos.dense_mean = a.eos.dilute_mean_abs = a.eos.dense_mean_abs = kNaN;
  a.eos.dilute_bins = a.eos.dense_bins = 0;
  a.eos.dilute_reason = a.eos.dense_reason = kNoVirial;
}

int from_dump_command(const FromDumpOptions& d, const FieldsCommandOptions& o) {
  const DumpFormat format = parse_dump_format(d.format);
  if (d.files.empty())
    throw UserError("granshock fields --from-dump " + d.format + " needs at least one dump file");
  if (d.map.empty())
    throw UserError(
        "granshock fields --from-dump needs --map MAP.toml (the scene and the atom "
        "types' species; docs/fields.md, \"Fields from LAMMPS or LIGGGHTS dumps\")");
  if (d.out.empty())
    throw UserError("granshock fields --from-dump needs --out DIR (where the fields go)");

  // Everything is read and analysed before anything is written.
  const DumpMap map = load_dump_map(d.map);
  FieldsDirectory::check(d.out, FieldsOutput::one_run);
  DumpSums sums = sum_dump_frames(map, format, d.files);
  FieldAnalysis a = analyse_fields(map.scene.scene, std::move(sums.grid), std::move(sums.profile));
  drop_collisional_pressure(a);
  // The steadiness check on the dump's own series, its clock counted from the flow's start.
  a.series = sums.series;
  a.steadiness =
      assess_steadiness(a.series, a.grid.production_start - map.flow_start,
                        a.grid.production_end - map.flow_start, a.physics, a.convergence);
  set_target_mach(a, a.ma_target, map.scene.scene.inflow.mach_at == MachReference::inlet_bins);

  nlohmann::json base = nlohmann::json::object();
  base["source"] = to_string(format) + " dump";
  base["dump_format"] = d.format;
  nlohmann::json names = nlohmann::json::array();
  for (const auto& f : d.files) names.push_back(f.string());
  base["dump_files"] = names;
  base["dump_map"] = d.map.string();
  base["dump_frames_read"] = sums.frames_read;
  base["dump_frames_used"] = sums.frames_used;
  base["scene"] = map.scene.scene.name;
  nlohmann::json keys = summary_keys(a);
  nlohmann::json warnings = nlohmann::json::array();
  if (!a.steadiness.warning.empty()) warnings.push_back(a.steadiness.warning);
  if (!a.inflow.warning.empty()) warnings.push_back(a.inflow.warning);
  for (const std::string& w : sums.warnings) warnings.push_back(w);
  keys["warnings"] = warnings;

  const FieldsDirectory out = FieldsDirectory::claim(d.out, FieldsOutput::one_run);
  write_fields_outputs(a, d.out);
  write_summary_json(d.out / "summary.json", base, keys);
  if (o.figures) {
    require_plotting_python();
    plot_run_figures(d.out / "fields.h5", d.out / "figures");
  }
  for (const auto& w : warnings)
    std::cerr << "granshock: warning: " << w.get<std::string>() << "\n";
  if (!o.quiet)
    std::cout << "granshock fields: " << sums.frames_used << " of " << sums.frames_read << " "
              << to_string(format) << " dump frames in the production window; Ma_inf "
              << number(a.inflow.ma_measured)
              << " (measured); delta/D = " << number(a.detachment.delta_over_d)
              << (std::isfinite(a.detachment.delta_over_d)
                      ? " +- " + number(a.detachment.delta_over_d_err)
                      : " (" + a.detachment.reason + ")")
              << "; results in " << d.out.string() << "\n";
  return 0;
}

}  // namespace granshock
