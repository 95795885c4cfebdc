#include "analysis/fields_output.hpp"

#include <cctype>
#include <cmath>
#include <cstdio>
#include <limits>

#include "analysis/csv_cells.hpp"
#include "core/variant_names.hpp"
#include "io/atomic_file.hpp"
#include "io/fields_xdmf.hpp"
#include "models/obstacle_shapes.hpp"

namespace granshock {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// Dataset names from species names: letters, digits, '_' and '-' kept, the rest '_'.
std::string dataset_name(const std::string& name) {
  std::string out;
  for (char c : name)
    out += std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-' ? c : '_';
  return out;
}

std::vector<std::vector<std::array<double, 2>>> as_arrays(const std::vector<Polyline>& lines) {
  std::vector<std::vector<std::array<double, 2>>> out;
  for (const Polyline& line : lines) {
    out.emplace_back();
    for (const Point2& p : line) out.back().push_back({p.x, p.y});
  }
  return out;
}

nlohmann::json number_or_null(double v) {
  return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json();
}

void add_upstream(FieldsFileContent& c, const std::string& group, const UpstreamState& u) {
  c.attributes.push_back({group, "row_begin", double(u.row_begin)});
  c.attributes.push_back({group, "row_end", double(u.row_end)});
  c.attributes.push_back({group, "bins", double(u.bins)});
  c.attributes.push_back({group, "phi", u.phi});
  c.attributes.push_back({group, "T", u.temperature});
  c.attributes.push_back({group, "uy", u.uy});
  c.attributes.push_back({group, "a", u.sound_speed});
  c.attributes.push_back({group, "Ma", u.mach});
  c.attributes.push_back({group, "Ma_mixture_mean", u.mach_mixture_mean});
  c.attributes.push_back({group, "Ma_paper_sum", u.mach_paper_sum});
  if (!u.determined()) c.text_attributes.push_back({group, "reason", u.reason});
}

void add_flank(FieldsFileContent& c, const std::string& side, const FlankFit& f) {
  c.attributes.push_back({"/front", side + "_points", double(f.points)});
  c.attributes.push_back({"/front", side + "_slope", f.slope});
  c.attributes.push_back({"/front", side + "_intercept", f.intercept});
  c.attributes.push_back({"/front", side + "_angle_deg", f.angle_deg});
  c.attributes.push_back({"/front", side + "_angle_err_deg", f.angle_err_deg});
  c.attributes.push_back({"/front", side + "_region_near", f.region_near});
  c.attributes.push_back({"/front", side + "_region_far", f.region_far});
  if (!f.reason.empty()) c.text_attributes.push_back({"/front", side + "_reason", f.reason});
}

}  // namespace

FieldsFileContent fields_file_content(const FieldAnalysis& a) {
  const FieldPhysics& p = a.physics;
  FieldsFileContent c;
  c.nx = a.grid.nx;
  c.ny = a.grid.ny;
  c.x0 = a.grid.x0;
  c.y0 = a.grid.y0;
  c.dx = a.grid.dx;
  c.dy = a.grid.dy;
  if (p.obstacle) {
    const Obstacle& o = p.obstacle->body;
    c.obstacle_outline = outline_points(obstacle_outline(o), o.centre[0], o.centre[1]);
  }

  std::vector<std::string> species;
  for (const std::string& s : p.species) species.push_back(dataset_name(s));
  for (const BinFields::Named& f : a.fields.named(species))
    c.cell_fields.push_back({f.name, f.unit, f.description, *f.values});
  c.cell_flags.push_back(
      {"masked", "1 where the bin is masked (too few particle samples or T <= 0): NaN fields",
       a.fields.masked});

  c.lines.push_back(
      {"sonic", "Ma = 1 iso-lines (marching squares on bin centres)", as_arrays(a.sonic_lines)});
  c.lines.push_back({"shock_threshold",
                     "shock front: phi crosses phi_up + 0.5 (phi_peak - phi_up) per column",
                     as_arrays(a.front.threshold_lines)});
  c.lines.push_back({"shock_max_gradient", "shock front: steepest rise of phi per column",
                     as_arrays(a.front.gradient_lines)});
  c.lines.push_back({"shock_temperature",
                     "shock front: half-rise of the largest rise of T per column (the primary "
                     "definition of delta/D)",
                     as_arrays(a.front.temperature_lines)});

  c.series.push_back({"/front/x", "m", "bin column centres", a.front.x});
  c.series.push_back({"/front/y_threshold", "m", "front position (threshold rule), NaN: no front",
                      a.front.y_threshold});
  c.series.push_back(
      {"/front/y_max_gradient", "m", "front position (maximum gradient)", a.front.y_max_gradient});
  c.series.push_back({"/front/y_temperature", "m",
                      "front position (half-rise of the largest rise of T), NaN: no front",
                      a.front.y_temperature});
  c.series.push_back({"/front/phi_peak", "", "largest phi of the searched rows", a.front.phi_peak});
  c.series.push_back(
      {"/front/threshold", "", "phi_up + fraction (phi_peak - phi_up)", a.front.threshold});
  add_flank(c, "left", a.front.left);
  add_flank(c, "right", a.front.right);
  c.attributes.push_back({"/front", "angle_deg", a.front.angle_deg});
  c.attributes.push_back({"/front", "phi_up", a.phi_up});
  c.attributes.push_back({"/front", "reference_row", double(a.reference_row)});
  if (!a.front.angle_reason.empty())
    c.text_attributes.push_back({"/front", "angle_reason", a.front.angle_reason});

  // The stagnation-line profile.
  const BinFields& pf = a.profile_fields;
  std::vector<double> y(static_cast<std::size_t>(a.profile.ny)), masked(pf.size());
  for (int k = 0; k < a.profile.ny; ++k) y[static_cast<std::size_t>(k)] = a.profile.y_centre(k);
  for (std::size_t k = 0; k < pf.size(); ++k) masked[k] = pf.masked[k];
  c.series.push_back({"/profile/y", "m", "profile bin centres", y});
  c.series.push_back({"/profile/phi", "", "area fraction", pf.phi});
  c.series.push_back({"/profile/T", "J", "mixture temperature", pf.temperature});
  c.series.push_back({"/profile/T_norm", "", "T / (m_av U^2)", pf.temperature_norm});
  c.series.push_back({"/profile/Ma", "", "Mach number (scene's mass definition)", pf.mach});
  c.series.push_back({"/profile/uy", "m s-1", "streamwise velocity", pf.uy});
  c.series.push_back({"/profile/pressure", "N m-1", "tr P / Dim", pf.pressure});
  c.series.push_back(
      {"/profile/mean_count", "", "time-averaged particles in the bin", pf.mean_count});
  c.series.push_back({"/profile/masked", "", "1 where the bin is masked", masked});
  c.series.push_back({"/profile/delta_blocks", "m", "detachment length of each block with samples",
                      a.detachment.delta_blocks});
  const Detachment& d = a.detachment;
  const Detachment& density = of(a.detachments, FrontDefinition::density_threshold);
  const Detachment& temperature = of(a.detachments, FrontDefinition::temperature_jump);
  std::vector<std::pair<std::string, double>> profile_attributes = {
      {"x_lo", a.profile.x0},
      {"x_hi", a.profile.x0 + a.profile.dx},
      {"strip_width", a.strip_width},
      {"y0", a.profile.y0},
      {"dy", a.profile.dy},
      {"from_grid", a.profile_from_grid ? 1.0 : 0.0},
      {"y_shock", d.y_shock},
      {"surface", d.surface},
      {"delta", d.delta},
      {"delta_err", d.delta_err},
      {"delta_over_D", d.delta_over_d},
      {"delta_over_D_err", d.delta_over_d_err},
      {"phi_peak", density.peak},
      {"threshold", density.threshold},
      {"T_peak", temperature.peak},
      {"T_threshold", temperature.threshold},
      {"blocks_used", double(d.blocks_used)}};
  // Every definition's front and delta (docs/fields.md, section 6).
  for (const Detachment& e : a.detachments) {
    const std::string suffix = std::string("_") + name(e.definition);
    profile_attributes.push_back({"y_shock" + suffix, e.y_shock});
    profile_attributes.push_back({"delta" + suffix, e.delta});
    profile_attributes.push_back({"delta_err" + suffix, e.delta_err});
    // The fitted fronts' step, for the figure that draws it (NaN for the other definitions).
    profile_attributes.push_back({"width" + suffix, e.width});
    profile_attributes.push_back({"width_err" + suffix, e.width_err});
    profile_attributes.push_back({"fit_low" + suffix, e.low});
    profile_attributes.push_back({"fit_high" + suffix, std::isfinite(e.width) ? e.peak : kNaN});
    profile_attributes.push_back({"fit_end" + suffix, e.fit_end});
  }
  for (const auto& [attribute, value] : profile_attributes)
    c.attributes.push_back({"/profile", attribute, value});
  c.text_attributes.push_back({"/profile", "primary_definition", name(kPrimaryFront)});
  if (!d.reason.empty()) c.text_attributes.push_back({"/profile", "delta_reason", d.reason});
  if (!d.err_reason.empty())
    c.text_attributes.push_back({"/profile", "delta_err_reason", d.err_reason});

  add_upstream(c, "/upstream/inlet", a.upstream_inlet);
  add_upstream(c, "/upstream/downstream", a.upstream_downstream);

  // Scene facts the figures need, and how the fields were made.
  const bool has_obstacle = p.obstacle.has_value();
  for (const auto& [name, value] : std::vector<std::pair<std::string, double>>{
           {"d", p.d},
           {"U", p.inflow_speed},
           {"m_av", p.m_av()},
           {"restitution", p.restitution},
           {"strip", p.inflow_strip},
           {"box_x_lo", p.box_x_lo},
           {"box_x_hi", p.box_x_hi},
           {"box_y_lo", p.box_y_lo},
           {"box_y_hi", p.box_y_hi},
           {"obstacle_xc", has_obstacle ? p.obstacle->xc : kNaN},
           {"obstacle_yc", has_obstacle ? p.obstacle->yc : kNaN},
           {"obstacle_width", has_obstacle ? p.obstacle->width : kNaN},
           {"obstacle_face", has_obstacle ? p.obstacle->face : kNaN},
           {"obstacle_back", has_obstacle ? p.obstacle->back : kNaN},
           {"blocks", double(a.grid.blocks)},
           {"samples", a.grid.total_samples()},
           {"production_start", a.grid.production_start},
           {"production_end", a.grid.production_end}})
    c.attributes.push_back({"/", name, value});
  c.text_attributes.push_back({"/", "mass_definition", to_string(p.mass_definition)});
  c.text_attributes.push_back(
      {"/", "obstacle_shape", has_obstacle ? choice_name(p.obstacle->body.shape) : "none"});
  std::string names;
  for (const std::string& s : species) names += (names.empty() ? "" : ",") + s;
  c.text_attributes.push_back({"/", "species", names});

  const nlohmann::json summary = summary_keys(a);
  for (const auto& [key, value] : summary.items()) {
    const std::string& name = key;  // a structured binding cannot be captured (C++17)
    auto ends_with = [&name](const std::string& tail) {
      return name.size() > tail.size() &&
             name.compare(name.size() - tail.size(), tail.size(), tail) == 0;
    };
    const bool text_key = ends_with("_reason");
    if (value.is_boolean())
      c.attributes.push_back({"/summary", key, value.get<bool>() ? 1.0 : 0.0});
    else if (value.is_number())
      c.attributes.push_back({"/summary", key, value.get<double>()});
    else if (value.is_string())
      c.text_attributes.push_back({"/summary", key, value.get<std::string>()});
    else if (value.is_null() && !text_key && !ends_with("_warning"))
      c.attributes.push_back({"/summary", key, kNaN});  // an undeterminable number
  }
  return c;
}

std::string convergence_csv(const FieldAnalysis& a) {
  std::vector<std::string> header = {"choice", "kind", "size_d"};
  for (FrontDefinition d : kFrontDefinitions) {
    header.push_back(name(d));
    header.push_back(std::string(name(d)) + "_err");
  }
  // The fitted fronts' thickness at each cut, after the deltas.
  for (const char* fit : {"temperature_fit", "density_fit"}) {
    header.push_back(std::string(fit) + "_w_over_d");
    header.push_back(std::string(fit) + "_w_over_d_err");
  }
  std::string csv = csv_header(header);
  for (const ConvergenceChoice& c : a.convergence.choices) {
    std::vector<std::string> cells = {csv_text(c.label), csv_name(c.kind),
                                      csv_number(c.kind == "window" ? kNaN : c.size_d)};
    for (const Detachment& d : c.result) {
      cells.push_back(csv_number(d.delta_over_d));
      cells.push_back(csv_number(d.delta_over_d_err));
    }
    for (FrontDefinition fit : {FrontDefinition::temperature_fit, FrontDefinition::density_fit}) {
      cells.push_back(csv_number(of(c.result, fit).width / a.physics.d));
      cells.push_back(csv_number(of(c.result, fit).width_err / a.physics.d));
    }
    csv += csv_line(cells);
  }
  return csv;
}

void write_fields_outputs(const FieldAnalysis& a, const std::filesystem::path& dir) {
  const FieldsFileContent content = fields_file_content(a);
  write_fields_file(dir / "fields.h5", content);
  write_fields_xdmf(dir / "fields.xmf", "fields.h5", content);
  write_file_atomically(dir / "detachment_convergence.csv", convergence_csv(a));
}

namespace {

// Every definition's delta/D with its three error estimates (docs/fields.md, section 6).
nlohmann::json detachment_keys(const FieldAnalysis& a) {
  nlohmann::json all = nlohmann::json::object();
  for (const Detachment& d : a.detachments) {
    const double D = a.physics.obstacle ? a.physics.obstacle->width : kNaN;
    nlohmann::json e;
    e["delta_over_D"] = number_or_null(d.delta_over_d);
    e["delta_over_D_err"] = number_or_null(d.delta_over_d_err);
    e["delta_over_D_err_blocks"] = number_or_null(d.err_blocks / D);
    e["delta_over_D_err_merged_pairs"] = number_or_null(d.err_merged_pairs / D);
    e["delta_over_D_err_bootstrap"] = number_or_null(d.err_bootstrap / D);
    e["bootstrap_found"] = d.bootstrap_found;
    e["bootstrap_resamples"] = d.bootstrap_resamples;
    e["blocks_used"] = d.blocks_used;
    if (d.definition == FrontDefinition::temperature_fit ||
        d.definition == FrontDefinition::density_fit) {
      e["w_over_d"] = number_or_null(d.width / a.physics.d);
      e["w_over_d_err"] = number_or_null(d.width_err / a.physics.d);
    }
    e["reason"] = d.reason.empty() ? nlohmann::json() : nlohmann::json(d.reason);
    e["err_reason"] = d.err_reason.empty() ? nlohmann::json() : nlohmann::json(d.err_reason);
    all[name(d.definition)] = e;
  }
  return all;
}

// The convergence table and the primary definition's verdict (detachment_convergence.hpp).
void add_convergence_keys(nlohmann::json& j, const FieldAnalysis& a) {
  const DetachmentConvergence& c = a.convergence;
  const bool judged = !c.verdicts.empty() && c.of(kPrimaryFront).applicable;
  const std::string why = c.verdicts.empty() ? a.detachment.reason : c.of(kPrimaryFront).text;
  j["delta_over_D_consistent"] = judged ? nlohmann::json(c.of(kPrimaryFront).consistent) : nullptr;
  j["delta_over_D_consistent_reason"] = judged ? nlohmann::json() : nlohmann::json(why);
  const double spread =
      judged ? c.of(kPrimaryFront).max_deviation / a.physics.obstacle->width : kNaN;
  j["delta_over_D_spread"] = number_or_null(spread);
  j["delta_over_D_spread_reason"] = judged ? nlohmann::json() : nlohmann::json(why);
  j["delta_over_D_verdict"] = why;
  if (c.verdicts.empty()) return;
  const double D = a.physics.obstacle->width;
  nlohmann::json rows = nlohmann::json::array();
  for (const ConvergenceChoice& choice : c.choices) {
    nlohmann::json row;
    row["choice"] = choice.label;
    row["kind"] = choice.kind;
    row["size_d"] = number_or_null(choice.kind == "window" ? kNaN : choice.size_d);
    for (const Detachment& d : choice.result) {
      row[std::string(name(d.definition))] = number_or_null(d.delta_over_d);
      row[std::string(name(d.definition)) + "_err"] = number_or_null(d.delta_over_d_err);
      if (std::isfinite(d.width)) {
        row[std::string(name(d.definition)) + "_w_over_d"] = d.width / a.physics.d;
        row[std::string(name(d.definition)) + "_w_over_d_err"] =
            number_or_null(d.width_err / a.physics.d);
      }
    }
    rows.push_back(row);
  }
  nlohmann::json verdicts = nlohmann::json::object();
  for (const ConvergenceVerdict& v : c.verdicts)
    verdicts[name(v.definition)] = {
        {"consistent", v.applicable ? nlohmann::json(v.consistent) : nlohmann::json()},
        {"max_deviation_over_D", number_or_null(v.applicable ? v.max_deviation / D : kNaN)},
        {"text", v.text}};
  j["detachment_convergence"] = {{"choices", rows}, {"verdicts", verdicts}};
}

}  // namespace

namespace {

nlohmann::json reason_or_null(const std::string& reason) {
  return reason.empty() ? nlohmann::json() : nlohmann::json(reason);
}

nlohmann::json trend_keys(const HalvesTrend& t) {
  return {{"rows", t.rows},
          {"first_half_mean", number_or_null(t.first_mean)},
          {"second_half_mean", number_or_null(t.second_mean)},
          {"scatter", number_or_null(t.scatter)},
          {"drift_over_scatter", number_or_null(t.drift_over_scatter)},
          {"relative_drift", number_or_null(t.relative_drift)},
          {"steady", t.determined ? nlohmann::json(t.steady) : nlohmann::json()},
          {"reason", reason_or_null(t.reason)}};
}

// `steady`, `steady_warning` and the checks behind them (docs/fields.md, section 12).
void add_steadiness_keys(nlohmann::json& j, const Steadiness& s) {
  j["steady"] = s.steady;
  j["steady_warning"] = reason_or_null(s.warning);
  const FrontHalves& f = s.front;
  j["steadiness"] = {{"window_start_s", s.window_start},
                     {"window_end_s", s.window_end},
                     {"flow_through_time_s", number_or_null(s.flow_through_time)},
                     {"washout_time_s", number_or_null(s.washout_time)},
                     {"start_after_washout", s.start_after_washout},
                     {"particles", trend_keys(s.particles)},
                     {"kinetic_energy", trend_keys(s.kinetic_energy)},
                     {"delta_over_D_halves",
                      {{"first_half", number_or_null(f.first_over_D)},
                       {"first_half_err", number_or_null(f.first_err)},
                       {"second_half", number_or_null(f.second_over_D)},
                       {"second_half_err", number_or_null(f.second_err)},
                       {"shift_over_error", number_or_null(f.shift_over_error)},
                       {"steady", f.determined ? nlohmann::json(f.steady) : nlohmann::json()},
                       {"reason", reason_or_null(f.reason)}}}};
}

}  // namespace

nlohmann::json summary_keys(const FieldAnalysis& a) {
  nlohmann::json j;
  // Every number that can be undeterminable comes with KEY_reason: null when KEY is a
  // number, else one line saying why KEY is null (docs/fields.md).
  auto put = [&j](const std::string& key, double value, const std::string& reason) {
    j[key] = number_or_null(value);
    if (std::isfinite(value))
      j[key + "_reason"] = nullptr;
    else
      j[key + "_reason"] = reason.empty() ? "not a finite number" : reason;
  };
  const UpstreamState &inlet = a.upstream_inlet, &beyond = a.upstream_downstream;
  const Detachment& d = a.detachment;
  const InflowCheck& in = a.inflow;
  put("ma_inf_target", a.ma_target, a.ma_target_reason);
  put("ma_inf_measured", inlet.mach, inlet.reason);
  put("ma_inf_measured_downstream", beyond.mach, beyond.reason);
  put("phi_inf_measured", inlet.phi, inlet.reason);
  put("phi_inf_measured_downstream", beyond.phi, beyond.reason);
  put("phi_inf_measured_downstream_err", a.phi_up_err, a.phi_up_err_reason);
  j["phi_inf_target"] = number_or_null(in.phi_target);
  put("phi_inf_deviation", in.phi_deviation, in.phi_deviation_reason);
  put("ma_inf_deviation", in.ma_deviation, in.ma_deviation_reason);
  j["ma_inf_deviation_rows"] = in.ma_rows;
  j["inflow_phi_short"] = in.phi_short;
  j["inflow_warning"] = in.warning.empty() ? nlohmann::json() : nlohmann::json(in.warning);
  put("delta_over_D", d.delta_over_d, d.reason);
  put("delta_over_D_err", d.delta_over_d_err, d.err_reason);
  put("detachment_length_m", d.delta, d.reason);
  j["detachment_blocks"] = d.blocks_used;
  j["delta_definition"] = name(kPrimaryFront);
  j["detachment"] = detachment_keys(a);
  add_convergence_keys(j, a);
  put("phi_peak", a.phi_peak, a.phi_peak_reason);
  const FlowFeatures& features = a.features;
  put("shock_layer_phi_mean", features.shock_layer_phi_mean, features.shock_layer_reason);
  put("hot_region_subsonic_fraction", features.hot_subsonic_fraction, features.hot_reason);
  j["hot_region_bins"] = features.hot_bins;
  put("upstream_ma_peak", features.upstream_ma_peak, features.upstream_ma_reason);
  put("upstream_ma_peak_over_ma_inf", features.upstream_ma_peak_over_inf,
      features.upstream_ma_reason);
  put("wake_phi_over_phi_inf", features.wake_phi_over_phi_up, features.wake_reason);
  put("shock_angle_deg", a.front.angle_deg, a.front.angle_reason);
  put("shock_angle_deg_left", a.front.left.angle_deg, a.front.left.reason);
  put("shock_angle_deg_right", a.front.right.angle_deg, a.front.right.reason);
  put("eos_deviation_dilute", a.eos.dilute_mean, a.eos.dilute_reason);
  put("eos_deviation_dense", a.eos.dense_mean, a.eos.dense_reason);
  j["eos_bins_dilute"] = a.eos.dilute_bins;
  j["eos_bins_dense"] = a.eos.dense_bins;
  j["mass_definition"] = to_string(a.physics.mass_definition);
  long masked = 0;
  for (int m : a.fields.masked) masked += m;
  j["fields_masked_bins"] = masked;
  j["fields_bins"] = static_cast<long>(a.fields.size());
  add_steadiness_keys(j, a.steadiness);
  return j;
}

}  // namespace granshock
