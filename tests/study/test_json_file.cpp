// Reading JSON files back (analysis/json_file.hpp): the nesting is bounded before the parser
// runs, only regular files of bounded size are read, and every reader of summary.json and
// trade.json goes through it (a 200 000-level summary.json crashed the parser's callers).
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <fstream>
#include <functional>
#include <sstream>

#include "analysis/json_file.hpp"
#include "analysis/summary_json.hpp"
#include "cases/accuracy/accuracy_table.hpp"
#include "cases/study/case_directory.hpp"
#include "core/user_error.hpp"
#include "io/run_directory.hpp"
#include "scene_fixtures.hpp"

using namespace granshock;
using granshock::testing::TempDir;
namespace fs = std::filesystem;

namespace {

// {"a": {"a": ... 1 ...}} with `depth` objects.
std::string nested_objects(int depth) {
  std::string text;
  for (int k = 0; k < depth; ++k) text += "{\"a\": ";
  text += "1";
  return text + std::string(std::size_t(depth), '}');
}

std::string message_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const UserError& e) {
    return e.what();
  }
  return "";
}

std::string read(const fs::path& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace

TEST(JsonFile, NestingIsCountedOutsideStrings) {
  EXPECT_EQ(json_nesting_depth("1"), 0);
  EXPECT_EQ(json_nesting_depth("{}"), 1);
  EXPECT_EQ(json_nesting_depth(R"({"a": [1, {"b": []}], "c": [2]})"), 4);
  EXPECT_EQ(json_nesting_depth(R"(["[[[{{{", "\"[[[", "\\", [1]])"), 2);
  EXPECT_EQ(json_nesting_depth(nested_objects(200000)), 200000);
  EXPECT_EQ(json_nesting_depth("]]]][[["), 3) << "not JSON: counted all the same";
}

TEST(JsonFile, DeepFilesAreRefusedInOneLine) {
  TempDir tmp;
  const fs::path ok = tmp.write("ok.json", nested_objects(kMaxJsonDepth));
  EXPECT_EQ(json_nesting_depth(read(ok)), 64);
  EXPECT_TRUE(read_json_file(ok).value.is_object());
  const fs::path deep = tmp.write("deep.json", nested_objects(kMaxJsonDepth + 1));
  EXPECT_EQ(message_of([&] { read_json_file(deep); }),
            deep.string() + ": JSON nested deeper than 64 levels");
  const fs::path deeper = tmp.write("deeper.json", "[" + nested_objects(200000) + "]");
  EXPECT_EQ(message_of([&] { read_json_file(deeper); }),
            deeper.string() + ": JSON nested deeper than 64 levels");
}

TEST(JsonFile, OnlyRegularFilesOfBoundedSizeAreRead) {
  TempDir tmp;
  const fs::path fifo = tmp.path() / "fifo.json";
  ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
  EXPECT_EQ(message_of([&] { read_json_file(fifo, "summary"); }),
            "summary '" + fifo.string() + "' is a FIFO (named pipe), not a regular file")
      << "a FIFO must be refused, not waited on";
  EXPECT_EQ(message_of([&] { read_json_file(tmp.path()); }),
            "JSON file '" + tmp.path().string() + "' is a directory, not a regular file");
  EXPECT_NE(message_of([&] { read_json_file(tmp.path() / "absent.json"); }).find("cannot read"),
            std::string::npos);
  const fs::path huge = tmp.write("huge.json", "{}");
  fs::resize_file(huge, kMaxJsonFileBytes + 1);  // sparse: no disk is used
  EXPECT_NE(message_of([&] { read_json_file(huge); }).find("is longer than 67108864 bytes"),
            std::string::npos);
}

TEST(JsonFile, TextThatIsNotJsonIsLeftToTheCaller) {
  TempDir tmp;
  for (const char* text : {"{\"a\": tru", "", "[1e999]"}) {
    const JsonFile f = read_json_file(tmp.write("bad.json", text));
    EXPECT_TRUE(f.value.is_discarded()) << text;
    EXPECT_FALSE(f.error.empty()) << text;
  }
}

TEST(JsonFile, EveryReaderRefusesADeepFile) {
  TempDir tmp;
  const std::string deep = nested_objects(200000);
  const std::string refusal = ": JSON nested deeper than 64 levels";

  // A case directory of a study (study --collect, --emit slurm, the runs).
  const fs::path dir = tmp.path() / "case";
  fs::create_directories(dir);
  tmp.write("case/" + std::string(kRunMarker), "format = 1\n");
  tmp.write("case/summary.json", deep);
  EXPECT_EQ(message_of([&] { inspect_case_directory(dir); }),
            (dir / "summary.json").string() + refusal);

  // `granshock fields` adding its keys to summary.json: refused, the file left as it was.
  EXPECT_EQ(message_of([&] {
              merge_summary_json(dir / "summary.json", {{"k", 1}});
            }),
            (dir / "summary.json").string() + refusal);
  EXPECT_EQ(read(dir / "summary.json"), deep);

  // `granshock run --accuracy-table`.
  const fs::path table = tmp.write("trade.json", deep);
  EXPECT_EQ(message_of([&] { read_accuracy_table(table); }), table.string() + refusal);
}
