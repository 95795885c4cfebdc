// Study files (docs/study.md, "The study file"): the shorthand and the full form of axis
// values become the overrides `granshock run --set` takes, and every mistake a user can make
// in the file is one UserError line naming the file and the key.
#include <gtest/gtest.h>

#include "cases/study/study_cases.hpp"
#include "cases/study/study_file.hpp"
#include "core/user_error.hpp"

using namespace granshock;

namespace {

const std::string kHead = R"([study]
name = "s"
base = "scene.toml"
)";

// The message of the UserError that parsing `text` throws, or "" when it parses.
std::string error_of(const std::string& text) {
  try {
    parse_study(text, "dir/s.toml");
  } catch (const UserError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(StudyFile, ShorthandValuesBecomeOneOverrideEachWithTheirShortestText) {
  const StudySpec s = parse_study(kHead + R"(
[[axis]]
name = "phi"
key = "inflow.area_fraction"
values = [0.05, 0.475, 2, "50 d", true]
)",
                                  "dir/s.toml");
  ASSERT_EQ(s.axes.size(), 1u);
  const auto& v = s.axes[0].values;
  ASSERT_EQ(v.size(), 5u);
  EXPECT_EQ(v[0].overrides, std::vector<std::string>{"inflow.area_fraction=0.05"});
  EXPECT_EQ(v[1].overrides, std::vector<std::string>{"inflow.area_fraction=0.475"});
  EXPECT_EQ(v[2].overrides, std::vector<std::string>{"inflow.area_fraction=2"});
  EXPECT_EQ(v[3].overrides.at(0).substr(0, 21), "inflow.area_fraction=");
  EXPECT_NE(v[3].overrides.at(0).find("50 d"), std::string::npos);
  EXPECT_EQ(v[4].overrides, std::vector<std::string>{"inflow.area_fraction=true"});
  EXPECT_EQ(v[0].label, "phi-0.05");
  EXPECT_EQ(v[3].label, "phi-50-d");  // filesystem-safe
  ASSERT_TRUE(v[1].number.has_value());
  EXPECT_EQ(*v[1].number, 0.475);
  EXPECT_FALSE(v[3].number.has_value());
  EXPECT_EQ(v[3].text, "50 d");
  EXPECT_EQ(s.base, "dir/scene.toml") << "base is taken relative to the study file";
  EXPECT_EQ(s.out, "runs/s");
  EXPECT_EQ(s.mode, StudyMode::product);
}

TEST(StudyFile, FullFormLinksKeysAndFlattensNestedTables) {
  const StudySpec s = parse_study(kHead + R"(
[[axis]]
name = "U"
values = [
  { label = "u0475", value = 0.475, inflow.velocity = 0.475, inflow.mach = 2.64 },
  { label = "u1 fast!", inflow = { velocity = 1.0, mach = 5.9 } },
]
[[axis]]
name = "mix"
[[axis.values]]
label = "one"
value = "pure"
species = [{ name = "a", material = "steel", diameter = "1 d", number_fraction = 1.0 }]
)",
                                  "s.toml");
  const auto& u = s.axes[0].values;
  EXPECT_EQ(u[0].overrides,
            (std::vector<std::string>{"inflow.mach=2.64", "inflow.velocity=0.475"}));
  EXPECT_EQ(u[1].overrides, (std::vector<std::string>{"inflow.mach=5.9", "inflow.velocity=1.0"}));
  EXPECT_EQ(u[0].label, "u0475");
  EXPECT_EQ(u[1].label, "u1-fast");
  EXPECT_EQ(*u[0].number, 0.475);
  EXPECT_EQ(u[1].text, "u1 fast!") << "without value, the label is the table's value";
  const auto& mix = s.axes[1].values[0];
  EXPECT_EQ(mix.text, "pure");
  ASSERT_EQ(mix.overrides.size(), 1u);
  EXPECT_EQ(mix.overrides[0].rfind("species=[{", 0), 0u) << mix.overrides[0];
}

TEST(StudyFile, ExplicitCasesAndCommonOverridesAndSlurmSettings) {
  const StudySpec s = parse_study(R"([study]
name = "s"
base = "/abs/scene.toml"
out = "elsewhere"
mode = "zip"
set = ["time.duration=0.01"]
[[case]]
name = "a"
set = ["inflow.mach=3", "scene.seed=2"]
[slurm]
cpus_per_task = 16
options = ["--partition=short"]
)",
                                  "x/s.toml");
  EXPECT_EQ(s.base, "/abs/scene.toml");
  EXPECT_EQ(s.out, "elsewhere");
  EXPECT_EQ(s.mode, StudyMode::list);
  EXPECT_EQ(s.common, std::vector<std::string>{"time.duration=0.01"});
  ASSERT_EQ(s.cases.size(), 1u);
  EXPECT_EQ(s.cases[0].overrides, (std::vector<std::string>{"inflow.mach=3", "scene.seed=2"}));
  EXPECT_EQ(s.slurm.cpus_per_task, 16);
  EXPECT_EQ(s.slurm.options, std::vector<std::string>{"--partition=short"});
}

struct BadStudy {
  const char* name;
  std::string text;
  const char* expected;
};

class StudyFileRefuses : public ::testing::TestWithParam<BadStudy> {};

TEST_P(StudyFileRefuses, WithOneLineNamingTheFileAndTheKey) {
  const std::string message = error_of(GetParam().text);
  EXPECT_NE(message.find(GetParam().expected), std::string::npos) << message;
  EXPECT_EQ(message.find("study file 'dir/s.toml'"), 0u) << message;
  EXPECT_EQ(message.find('\n'), std::string::npos) << message;
}

INSTANTIATE_TEST_SUITE_P(
    Mistakes, StudyFileRefuses,
    ::testing::Values(
        BadStudy{"UnknownStudyKey", kHead + "nmae = 1\n", "unknown key 'nmae'"},
        BadStudy{"UnknownTable", kHead + "[axes]\n", "unknown key 'axes'"},
        BadStudy{"NoStudyTable", "[[case]]\nname = \"a\"\n", "needs a [study] table"},
        BadStudy{"NoBase", "[study]\nname = \"s\"\n[[case]]\nname = \"a\"\n", "'base' is required"},
        BadStudy{"UnsafeName", "[study]\nname = \"../x\"\nbase = \"b\"\n", "name '../x' must be"},
        BadStudy{"BadMode", kHead + "mode = \"cartesian\"\n", "mode must be"},
        BadStudy{"NoCases", kHead, "defines no case"},
        BadStudy{"EmptyAxis", kHead + "[[axis]]\nname = \"p\"\nkey = \"k\"\nvalues = []\n",
                 "'values' is empty"},
        BadStudy{"UnknownAxisKey", kHead + "[[axis]]\nname = \"p\"\nvalue = [1]\n",
                 "unknown key 'value'"},
        BadStudy{"PlainValueWithoutKey", kHead + "[[axis]]\nname = \"p\"\nvalues = [1]\n",
                 "every value must be a table"},
        BadStudy{"TableWithoutLabel",
                 kHead + "[[axis]]\nname = \"p\"\nvalues = [{ inflow.mach = 3 }]\n",
                 "needs a label"},
        BadStudy{"TableUnderAKey",
                 kHead + "[[axis]]\nname = \"p\"\nkey = \"k\"\nvalues = [{ a = 1 }]\n",
                 "a table, but the axis names one key"},
        BadStudy{"DateValue",
                 kHead + "[[axis]]\nname = \"p\"\nkey = \"k\"\nvalues = [1979-05-27]\n",
                 "a date or time"},
        BadStudy{"TwoAxesOneName",
                 kHead + "[[axis]]\nname = \"p\"\nkey = \"a\"\nvalues = [1]\n[[axis]]\nname = "
                         "\"p\"\nkey = \"b\"\nvalues = [2]\n",
                 "two axes are named 'p'"},
        BadStudy{"CaseSetNotStrings", kHead + "[[case]]\nname = \"a\"\nset = [1]\n",
                 "'set' must be an array"},
        BadStudy{"CaseSetWithoutEquals", kHead + "[[case]]\nname = \"a\"\nset = [\"inflow\"]\n",
                 "expected key=value"},
        BadStudy{"SlurmCpus", kHead + "[[case]]\nname = \"a\"\n[slurm]\ncpus_per_task = 0\n",
                 "cpus_per_task must be"},
        BadStudy{"SlurmOptionWithNewline",
                 kHead + "[[case]]\nname = \"a\"\n[slurm]\noptions = "
                         "[\"--partition=short\\ntouch PWNED\"]\n",
                 "option $'--partition=short\\x0atouch PWNED' must be one sbatch option"},
        BadStudy{"SlurmOptionWithTab",
                 kHead + "[[case]]\nname = \"a\"\n[slurm]\noptions = [\"--comment=a\\tb\"]\n",
                 "without control characters"},
        BadStudy{"NotToml", kHead + "[[axis]\n", "not valid TOML"}),
    [](const ::testing::TestParamInfo<BadStudy>& p) { return std::string(p.param.name); });

TEST(StudyNames, SafeNamesFollowTheSceneNameRule) {
  EXPECT_TRUE(is_safe_name("d10_u0475"));
  EXPECT_TRUE(is_safe_name("phi-0.05"));
  EXPECT_FALSE(is_safe_name(""));
  EXPECT_FALSE(is_safe_name(".hidden"));
  EXPECT_FALSE(is_safe_name("-x"));
  EXPECT_FALSE(is_safe_name("a/b"));
  EXPECT_FALSE(is_safe_name(std::string(65, 'a')));
  EXPECT_EQ(safe_name("50 d"), "50-d");
  EXPECT_EQ(safe_name("../x y/"), "x-y");
  EXPECT_EQ(safe_name("!!"), "");
}
