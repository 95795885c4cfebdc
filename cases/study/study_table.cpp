#include "cases/study/study_table.hpp"

#include <toml++/toml.h>

#include <set>

#include "analysis/csv_cells.hpp"
#include "cases/study/case_directory.hpp"
#include "io/atomic_file.hpp"
#include "models/obstacle_shapes.hpp"

namespace granshock {

namespace {

using Row = nlohmann::ordered_json;

bool kept_string(const std::string& key) {
  for (const char* tail : {"_reason", "_warning"}) {
    const std::string t = tail;
    if (key.size() >= t.size() && key.compare(key.size() - t.size(), t.size(), t) == 0) return true;
  }
  return false;
}

nlohmann::json axis_cell(const StudySpec& spec, const StudyCase& c, std::size_t a) {
  if (c.axis_value[a] < 0) return nullptr;
  const AxisValue& v = spec.axes[a].values[std::size_t(c.axis_value[a])];
  return v.number ? nlohmann::json(*v.number) : nlohmann::json(v.text);
}

// The scene's main parameters (docs/study.md, "The study table").
void scene_columns(const PlannedCase& c, Row& row) {
  const Scene& s = c.scene;
  // D: the obstacle's frontal width (docs/fields.md).
  row["scene.D_over_d"] = s.setup.obstacle
                              ? nlohmann::json(obstacle_frontal_width(*s.setup.obstacle) / s.d_m)
                              : nlohmann::json();
  row["scene.U"] = s.inflow.speed_m_per_s;
  row["scene.phi_inf"] = s.inflow.area_fraction;
  row["scene.mach"] = s.inflow.target_mach ? nlohmann::json(*s.inflow.target_mach) : nullptr;
  row["scene.mach_at"] = to_string(s.inflow.mach_at);
  const toml::table resolved = toml::parse(c.resolved);
  row["scene.restitution"] = resolved.at_path("contact.restitution").value<double>().value_or(0.0);
  std::map<std::string, double> by_material;
  for (std::size_t a = 0; a < s.setup.species.size(); ++a)
    by_material[s.setup.species[a].material.name] += s.inflow.number_fraction[a];
  for (const auto& [material, fraction] : by_material)
    row["scene.number_fraction." + material] = fraction;
  row["scene.dt"] = s.setup.dt;
  row["scene.duration"] = s.run.duration_s;
  row["scene.production_start"] = s.run.production_start_s;
  // The settings an error budget chose for the case (docs/study.md, "An error budget").
  if (c.accuracy_choice.is_null()) return;
  for (const char* key : {"case", "certified", "error_bound", "bound_by", "dt_over_tc", "softening",
                          "precision", "speedup_over_scene"})
    row[std::string("accuracy.") + key] = c.accuracy_choice.at(key);
}

std::string csv_cell(const nlohmann::ordered_json& v) {
  if (v.is_null()) return "";
  if (v.is_boolean()) return v.get<bool>() ? "true" : "false";
  if (v.is_number_integer()) return v.dump();
  if (v.is_number()) return csv_number(v.get<double>());
  return csv_text(v.get<std::string>());
}

}  // namespace

void flatten_summary(const nlohmann::json& j, const std::string& prefix, Row& row) {
  for (const auto& [key, value] : j.items()) {
    const std::string name = prefix.empty() ? key : prefix + "." + key;
    if (value.is_object())
      flatten_summary(value, name, row);
    else if (value.is_number() || value.is_boolean() || value.is_null())
      row[name] = value;
    else if (value.is_string() && kept_string(key))
      row[name] = value;
  }
}

StudyTable study_table(const StudyPlan& plan, const std::map<int, std::string>& failures) {
  StudyTable t;
  std::vector<std::string> lead = {"case", "index", "status", "source", "wall_seconds"};
  for (const StudyAxis& a : plan.spec.axes) lead.push_back("axis." + a.name);
  std::vector<std::string> scene_cols;
  std::set<std::string> summary_cols;
  for (const PlannedCase& c : plan.cases) {
    Row row;
    const CaseDirectory dir = inspect_planned_case(plan, c);
    const auto failure = failures.find(c.spec.index);
    row["case"] = c.spec.name;
    row["index"] = c.spec.index;
    row["status"] = failure != failures.end()          ? "failed"
                    : dir.state == CaseState::finished ? "finished"
                    : dir.state == CaseState::missing  ? "missing"
                                                       : "unfinished";
    // Where a finished case's numbers come from: its run directory or its record alone.
    row["source"] = dir.state != CaseState::finished ? nlohmann::json()
                    : dir.from_record                ? nlohmann::json("record")
                                                     : nlohmann::json("run");
    row["wall_seconds"] = dir.summary.is_object() ? nlohmann::json(dir.wall_seconds) : nullptr;
    for (std::size_t a = 0; a < plan.spec.axes.size(); ++a)
      row["axis." + plan.spec.axes[a].name] = axis_cell(plan.spec, c.spec, a);
    Row scene;
    scene_columns(c, scene);
    for (const auto& [key, value] : scene.items()) {
      if (std::find(scene_cols.begin(), scene_cols.end(), key) == scene_cols.end())
        scene_cols.push_back(key);
      row[key] = value;
    }
    row["error"] = failure != failures.end() ? nlohmann::json(failure->second) : nullptr;
    if (dir.state == CaseState::finished) {
      Row summary;
      flatten_summary(dir.summary, "", summary);
      for (const auto& [key, value] : summary.items()) {
        if (key == "wall_seconds") continue;
        summary_cols.insert(key);
        row[key] = value;
      }
    }
    t.rows.push_back(std::move(row));
  }
  t.columns = lead;
  t.columns.insert(t.columns.end(), scene_cols.begin(), scene_cols.end());
  t.columns.push_back("error");
  t.columns.insert(t.columns.end(), summary_cols.begin(), summary_cols.end());
  for (Row& row : t.rows) {
    Row ordered;
    for (const std::string& col : t.columns) ordered[col] = row.contains(col) ? row[col] : nullptr;
    row = std::move(ordered);
  }
  return t;
}

void write_study_table(const std::filesystem::path& out, const StudyTable& t) {
  std::string csv = csv_header(t.columns);
  nlohmann::ordered_json json = nlohmann::ordered_json::array();
  for (const Row& row : t.rows) {
    std::vector<std::string> cells;
    for (const std::string& column : t.columns) cells.push_back(csv_cell(row[column]));
    csv += csv_line(cells);
    json.push_back(row);
  }
  write_file_atomically(out / "study.csv", csv);
  write_file_atomically(out / "study.json", json.dump(2) + "\n");
}

}  // namespace granshock
