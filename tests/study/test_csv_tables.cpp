// The CSV tables granshock writes (analysis/csv_cells.hpp; docs/output_format.md, "CSV
// tables"): study.csv, detachment.csv and detachment_convergence.csv read back field by field,
// by a reader of RFC 4180 here and by Python's csv module, with commas, quotes, CR and LF in
// the header names and the cells (a material named "st,eel" shifted every column of
// study.csv).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <nlohmann/json.hpp>
#include <optional>
#include <sstream>

#include "analysis/csv_cells.hpp"
#include "analysis/detachment_table.hpp"
#include "analysis/fields_output.hpp"
#include "cases/study/study_table.hpp"
#include "scene_fixtures.hpp"

using namespace granshock;
using granshock::testing::TempDir;
namespace fs = std::filesystem;

namespace {

using Table = std::vector<std::vector<std::string>>;

const std::string kHostile = "st,eel \"q\" a\r\nb\nc";

std::string read(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// RFC 4180: fields separated by ',', records by LF (or CRLF); a quoted field may hold ',',
// CR, LF and "" for a quote.
Table read_csv(const std::string& text) {
  Table rows(1);
  std::string field;
  bool quoted = false, was_quoted = false;
  for (std::size_t k = 0; k < text.size(); ++k) {
    const char c = text[k];
    if (quoted) {
      if (c == '"' && k + 1 < text.size() && text[k + 1] == '"')
        field += '"', ++k;
      else if (c == '"')
        quoted = false;
      else
        field += c;
    } else if (c == '"') {
      EXPECT_TRUE(field.empty() && !was_quoted) << "a quote inside an unquoted field";
      quoted = was_quoted = true;
    } else if (c == ',') {
      rows.back().push_back(field);
      field.clear();
      was_quoted = false;
    } else if (c == '\n' || (c == '\r' && k + 1 < text.size() && text[k + 1] == '\n')) {
      if (c == '\r') ++k;
      rows.back().push_back(field);
      field.clear();
      was_quoted = false;
      rows.emplace_back();
    } else {
      field += c;
    }
  }
  EXPECT_FALSE(quoted) << "an unterminated quoted field";
  if (rows.back().empty() && field.empty()) rows.pop_back();
  return rows;
}

// The same file as Python's csv module reads it, or nullopt without a Python 3.
std::optional<Table> read_csv_with_python(const fs::path& csv, const fs::path& json) {
  const std::string command =
      "python3 -c 'import csv, json, sys; json.dump(list(csv.reader(open(sys.argv[1], "
      "newline=\"\"))), open(sys.argv[2], \"w\"))' '" +
      csv.string() + "' '" + json.string() + "' 2>/dev/null";
  if (std::system("python3 -c 'import csv, json' 2>/dev/null") != 0) return std::nullopt;
  EXPECT_EQ(std::system(command.c_str()), 0);
  return nlohmann::json::parse(read(json)).get<Table>();
}

void expect_read_back(const fs::path& csv, const Table& expected) {
  const std::string text = read(csv);
  EXPECT_EQ(read_csv(text), expected) << text;
  if (const auto python = read_csv_with_python(csv, csv.string() + ".json")) {
    EXPECT_EQ(*python, expected) << "Python's csv module reads it otherwise:\n" << text;
  }
}

}  // namespace

TEST(CsvTables, FieldsAreQuotedOnlyWhereRfc4180NeedsItAndTextAlways) {
  EXPECT_EQ(csv_name("scene.U"), "scene.U");
  EXPECT_EQ(csv_name("a,b"), "\"a,b\"");
  EXPECT_EQ(csv_name("a\"b"), "\"a\"\"b\"");
  EXPECT_EQ(csv_name("a\rb"), "\"a\rb\"");
  EXPECT_EQ(csv_name("a\nb"), "\"a\nb\"");
  EXPECT_EQ(csv_text("finished"), "\"finished\"");
  EXPECT_EQ(csv_number(0.1), "0.1");
  EXPECT_EQ(csv_number(std::nan("")), "");
  EXPECT_EQ(csv_header({"a", "b,c"}), "a,\"b,c\"\n");
}

TEST(CsvTables, StudyTableReadsBackWithHostileNamesAndCells) {
  TempDir tmp;
  StudyTable t;
  t.columns = {"case",
               "index",
               "scene.number_fraction." + kHostile,
               "ma_inf_measured",
               "delta_over_D_reason",
               "flag"};
  nlohmann::ordered_json row;
  row["case"] = "a";
  row["index"] = 0;
  row["scene.number_fraction." + kHostile] = 0.5;
  row["ma_inf_measured"] = 5.9;
  row["delta_over_D_reason"] = kHostile;
  row["flag"] = true;
  t.rows.push_back(row);
  row["case"] = kHostile;
  row["index"] = 1;
  row["ma_inf_measured"] = nullptr;
  row["delta_over_D_reason"] = "";
  t.rows.push_back(row);
  write_study_table(tmp.path(), t);
  expect_read_back(tmp.path() / "study.csv", {t.columns,
                                              {"a", "0", "0.5", "5.9", kHostile, "true"},
                                              {kHostile, "1", "0.5", "", "", "true"}});
}

TEST(CsvTables, DetachmentTableReadsBackWithAHostileRunName) {
  TempDir tmp;
  DetachmentRow r;
  r.run = "runs/" + kHostile;
  r.delta_over_D = std::nan("");
  r.delta_over_D_reason = kHostile;
  r.verdict = "consistent, \"within\" noise";
  write_detachment_table(tmp.path(), {r, r});
  const Table rows = read_csv(read(tmp.path() / "detachment.csv"));
  ASSERT_EQ(rows.size(), 3u);
  for (const auto& row : rows) EXPECT_EQ(row.size(), rows[0].size());
  EXPECT_EQ(rows[0][0], "run");
  EXPECT_EQ(rows[1][0], r.run);
  EXPECT_EQ(rows[1][5], "") << "delta_over_D: NaN is an empty cell";
  EXPECT_EQ(rows[1][10], kHostile);
  // The verdict's column by its name: the thickness columns come after it
  // (docs/output_format.md, detachment.csv).
  const auto verdict = std::find(rows[0].begin(), rows[0].end(), "delta_over_D_verdict");
  ASSERT_NE(verdict, rows[0].end());
  EXPECT_EQ(rows[1][std::size_t(verdict - rows[0].begin())], r.verdict);
  expect_read_back(tmp.path() / "detachment.csv", rows);
}

TEST(CsvTables, ConvergenceTableReadsBackWithAHostileLabel) {
  TempDir tmp;
  FieldAnalysis a;
  ConvergenceChoice c;
  c.kind = "rows";
  c.label = kHostile;
  c.size_d = 1.5;
  a.convergence.choices = {c, c};
  std::ofstream(tmp.path() / "convergence.csv", std::ios::binary) << convergence_csv(a);
  const Table rows = read_csv(read(tmp.path() / "convergence.csv"));
  ASSERT_EQ(rows.size(), 3u);
  for (const auto& row : rows) EXPECT_EQ(row.size(), rows[0].size());
  EXPECT_EQ(rows[1][0], kHostile);
  EXPECT_EQ(rows[1][1], "rows");
  EXPECT_EQ(rows[1][2], "1.5");
  expect_read_back(tmp.path() / "convergence.csv", rows);
}
