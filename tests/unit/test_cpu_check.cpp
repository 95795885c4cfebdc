// A -march=native build refuses a CPU that lacks its instructions (apps/granshock/
// cpu_check.hpp, docs/study.md "On a cluster"), and says what it was built from.
#include <gtest/gtest.h>

#include <string>

#include "apps/granshock/cpu_check.hpp"
#include "cases/build_info/build_description.hpp"
#include "version.hpp"

using namespace granshock;

TEST(CpuCheck, NamesTheFeaturesTheCpuLacks) {
  const char* const compiled[] = {"sse4.2", "avx", "avx2", "avx512f", nullptr};
  const auto old_cpu = [](const std::string& name) { return name == "sse4.2" || name == "avx"; };
  const std::vector<std::string> missing = missing_cpu_features(compiled, old_cpu);
  EXPECT_EQ(missing, (std::vector<std::string>{"avx2", "avx512f"}));
  const std::string line = cpu_refusal(missing, "native (sapphirerapids)");
  EXPECT_NE(line.find("avx2, avx512f"), std::string::npos) << line;
  EXPECT_NE(line.find("-DGRANSHOCK_NATIVE=OFF"), std::string::npos) << line;
  EXPECT_EQ(line.find('\n'), std::string::npos);
  EXPECT_TRUE(missing_cpu_features(compiled, [](const std::string&) { return true; }).empty());
}

TEST(CpuCheck, TheBuildMachineRunsItsOwnBuild) {
  EXPECT_EQ(check_this_cpu(), "");
}

TEST(BuildDescription, SaysVersionCommitAndInstructionSet) {
  const nlohmann::json b = build_description();
  EXPECT_EQ(b["version"], GRANSHOCK_VERSION_STRING);
  const std::string commit = b["commit"];
  EXPECT_TRUE(commit == "unknown" || commit.size() >= 40) << commit;
  EXPECT_FALSE(b["march"].get<std::string>().empty());
  EXPECT_EQ(
      version_line().rfind(
          std::string("granshock ") + GRANSHOCK_VERSION_STRING + " (commit " + commit + ", ", 0),
      0u)
      << version_line();
}
