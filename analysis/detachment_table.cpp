#include "analysis/detachment_table.hpp"

#include <cmath>
#include <cstdio>
#include <limits>
#include <nlohmann/json.hpp>

#include "analysis/csv_cells.hpp"
#include "io/atomic_file.hpp"

namespace granshock {

namespace {

nlohmann::json json_number(double v) {
  return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json();
}

nlohmann::json json_text(const std::string& s) {
  return s.empty() ? nlohmann::json() : nlohmann::json(s);
}

}  // namespace

DetachmentRow detachment_row(const std::filesystem::path& run_dir, const FieldAnalysis& a,
                             double ma_inf_target) {
  DetachmentRow r;
  r.run = run_dir.string();
  r.d_over_particle = a.physics.obstacle ? a.physics.obstacle->width / a.physics.d
                                         : std::numeric_limits<double>::quiet_NaN();
  r.ma_inf_target = ma_inf_target;
  r.ma_inf_measured = a.upstream_inlet.mach;
  r.ma_inf_measured_downstream = a.upstream_downstream.mach;
  r.delta_over_D = a.detachment.delta_over_d;
  r.delta_over_D_err = a.detachment.delta_over_d_err;
  r.phi_peak = a.phi_peak;
  r.shock_angle_deg = a.front.angle_deg;
  r.phi_inf_deviation = a.inflow.phi_deviation;
  r.delta_over_D_reason = a.detachment.reason;
  r.delta_over_D_err_reason = a.detachment.err_reason;
  r.shock_angle_deg_reason = a.front.angle_reason;
  r.inflow_warning = a.inflow.warning;
  constexpr double nan = std::numeric_limits<double>::quiet_NaN();
  for (std::size_t k = 0; k < kFrontDefinitions.size(); ++k) {
    r.by_definition[k] = a.detachments[k].delta_over_d;
    r.by_definition_err[k] = a.detachments[k].delta_over_d_err;
  }
  const FrontDefinition fits[] = {FrontDefinition::temperature_fit, FrontDefinition::density_fit};
  for (std::size_t k = 0; k < 2; ++k) {
    r.fit_w_over_d[k] = of(a.detachments, fits[k]).width / a.physics.d;
    r.fit_w_over_d_err[k] = of(a.detachments, fits[k]).width_err / a.physics.d;
  }
  r.consistent = r.spread = nan;
  if (!a.convergence.verdicts.empty()) {
    const ConvergenceVerdict& v = a.convergence.of(kPrimaryFront);
    if (v.applicable) {
      r.consistent = v.consistent ? 1 : 0;
      r.spread = v.max_deviation / a.physics.obstacle->width;
    }
    r.verdict = v.text;
  }
  return r;
}

void write_detachment_table(const std::filesystem::path& out_dir,
                            const std::vector<DetachmentRow>& rows) {
  std::vector<std::string> header = {"run",
                                     "D_over_d",
                                     "ma_inf_target",
                                     "ma_inf_measured",
                                     "ma_inf_measured_downstream",
                                     "delta_over_D",
                                     "delta_over_D_err",
                                     "phi_peak",
                                     "shock_angle_deg",
                                     "phi_inf_deviation",
                                     "delta_over_D_reason",
                                     "delta_over_D_err_reason",
                                     "shock_angle_deg_reason",
                                     "inflow_warning"};
  for (FrontDefinition d : kFrontDefinitions) {
    header.push_back(std::string("delta_over_D_") + name(d));
    header.push_back(std::string("delta_over_D_") + name(d) + "_err");
  }
  for (const char* n : {"delta_over_D_consistent", "delta_over_D_spread", "delta_over_D_verdict"})
    header.push_back(n);
  for (const char* n : {"w_over_d_temperature_fit", "w_over_d_temperature_fit_err",
                        "w_over_d_density_fit", "w_over_d_density_fit_err"})
    header.push_back(n);
  std::string csv = csv_header(header);
  nlohmann::json table = nlohmann::json::array();
  for (const DetachmentRow& r : rows) {
    std::vector<std::string> cells = {csv_text(r.run)};
    for (double v :
         {r.d_over_particle, r.ma_inf_target, r.ma_inf_measured, r.ma_inf_measured_downstream,
          r.delta_over_D, r.delta_over_D_err, r.phi_peak, r.shock_angle_deg, r.phi_inf_deviation})
      cells.push_back(csv_number(v));
    for (const std::string* text : {&r.delta_over_D_reason, &r.delta_over_D_err_reason,
                                    &r.shock_angle_deg_reason, &r.inflow_warning})
      cells.push_back(text->empty() ? std::string() : csv_text(*text));
    for (std::size_t k = 0; k < kFrontDefinitions.size(); ++k) {
      cells.push_back(csv_number(r.by_definition[k]));
      cells.push_back(csv_number(r.by_definition_err[k]));
    }
    cells.push_back(csv_number(r.consistent));
    cells.push_back(csv_number(r.spread));
    cells.push_back(r.verdict.empty() ? std::string() : csv_text(r.verdict));
    for (std::size_t k = 0; k < 2; ++k) {
      cells.push_back(csv_number(r.fit_w_over_d[k]));
      cells.push_back(csv_number(r.fit_w_over_d_err[k]));
    }
    csv += csv_line(cells);
    table.push_back({{"run", r.run},
                     {"D_over_d", json_number(r.d_over_particle)},
                     {"ma_inf_target", json_number(r.ma_inf_target)},
                     {"ma_inf_measured", json_number(r.ma_inf_measured)},
                     {"ma_inf_measured_downstream", json_number(r.ma_inf_measured_downstream)},
                     {"delta_over_D", json_number(r.delta_over_D)},
                     {"delta_over_D_err", json_number(r.delta_over_D_err)},
                     {"phi_peak", json_number(r.phi_peak)},
                     {"shock_angle_deg", json_number(r.shock_angle_deg)},
                     {"phi_inf_deviation", json_number(r.phi_inf_deviation)},
                     {"delta_over_D_reason", json_text(r.delta_over_D_reason)},
                     {"delta_over_D_err_reason", json_text(r.delta_over_D_err_reason)},
                     {"shock_angle_deg_reason", json_text(r.shock_angle_deg_reason)},
                     {"inflow_warning", json_text(r.inflow_warning)}});
    nlohmann::json& row = table.back();
    for (std::size_t k = 0; k < kFrontDefinitions.size(); ++k) {
      const std::string key = std::string("delta_over_D_") + name(kFrontDefinitions[k]);
      row[key] = json_number(r.by_definition[k]);
      row[key + "_err"] = json_number(r.by_definition_err[k]);
    }
    row["delta_over_D_consistent"] =
        std::isfinite(r.consistent) ? nlohmann::json(r.consistent > 0) : nlohmann::json();
    row["delta_over_D_spread"] = json_number(r.spread);
    row["delta_over_D_verdict"] = json_text(r.verdict);
    row["w_over_d_temperature_fit"] = json_number(r.fit_w_over_d[0]);
    row["w_over_d_temperature_fit_err"] = json_number(r.fit_w_over_d_err[0]);
    row["w_over_d_density_fit"] = json_number(r.fit_w_over_d[1]);
    row["w_over_d_density_fit_err"] = json_number(r.fit_w_over_d_err[1]);
  }
  write_file_atomically(out_dir / "detachment.csv", csv);
  write_file_atomically(out_dir / "detachment.json", table.dump(2) + "\n");
}

}  // namespace granshock
