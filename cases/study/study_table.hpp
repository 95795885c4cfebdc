// The study table (docs/study.md, "The study table"): one row per case with its status,
// its axis values, the scene's main parameters and every scalar of its summary.json,
// written as <out>/study.csv and <out>/study.json.
#pragma once

#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "cases/study/study_plan.hpp"

namespace granshock {

// Row status: finished, unfinished (a run directory that did not complete), missing (no run
// yet) or failed (failed in this invocation; `failures` maps the case index to its error).
struct StudyTable {
  std::vector<std::string> columns;
  std::vector<nlohmann::ordered_json> rows;  // column -> value; absent columns are null
};

StudyTable study_table(const StudyPlan& plan, const std::map<int, std::string>& failures);

// summary.json flattened to dotted keys: numbers, booleans and nulls, and the strings of
// keys ending in _reason or _warning; arrays are left out.
void flatten_summary(const nlohmann::json& summary, const std::string& prefix,
                     nlohmann::ordered_json& row);

// <out>/study.csv (an empty cell for null) and <out>/study.json (a list of objects with the
// CSV's columns), each written atomically.
void write_study_table(const std::filesystem::path& out, const StudyTable& table);

}  // namespace granshock
