// The resolved scene's numbers (io/shortest_floats.hpp): toml++ wrote friction = 0.3 as
// 0.29999999999999999; the shortest form reads back as the same double.
#include <gtest/gtest.h>

#include <cstdlib>
#include <string>

#include "io/scene_file.hpp"
#include "io/shortest_floats.hpp"

using namespace granshock;

TEST(ShortestFloats, WritesTheShortestTextThatReadsBackTheSame) {
  EXPECT_EQ(shortest_float(0.3), "0.3");
  EXPECT_EQ(shortest_float(2e-7), "2e-07");
  EXPECT_EQ(shortest_float(200.0), "200.0");  // still a TOML float
  EXPECT_EQ(shortest_float(-0.15), "-0.15");
  for (double v : {0.1, 1.0 / 3.0, 7850.0 / 2.907, 6.02214076e23, 5e-324})
    EXPECT_EQ(std::strtod(shortest_float(v).c_str(), nullptr), v) << v;
}

TEST(ShortestFloats, RewritesValuesAndLeavesStringsKeysAndHeaders) {
  const std::string toml =
      "[scene]\nname = \"0.29999999999999999\"\nseed = 1\n"
      "[materials.1.5e3]\nfriction = 0.29999999999999999\n"
      "centre = [ 0.074999999999999997, 0.12 ]\n"
      "pair = { e = 0.50000000000000000, name = 'x 0.10000000000000001' }\n"
      "# 0.10000000000000001\n";
  EXPECT_EQ(with_shortest_floats(toml),
            "[scene]\nname = \"0.29999999999999999\"\nseed = 1\n"
            "[materials.1.5e3]\nfriction = 0.3\n"
            "centre = [ 0.075, 0.12 ]\n"
            "pair = { e = 0.5, name = 'x 0.10000000000000001' }\n"
            "# 0.10000000000000001\n");
}

TEST(ShortestFloats, TheResolvedSceneEchoesWhatTheUserWrote) {
  const LoadedScene loaded = load_scene_file(
      std::string(GRANSHOCK_SOURCE_DIR) + "/scenes/default.toml", {"contact.friction=0.3"});
  EXPECT_NE(loaded.resolved.find("friction = 0.3\n"), std::string::npos) << loaded.resolved;
  EXPECT_EQ(loaded.resolved.find("99999999"), std::string::npos) << loaded.resolved;
  EXPECT_EQ(loaded.resolved.find("00000001"), std::string::npos) << loaded.resolved;
  // The same scene back.
  EXPECT_EQ(parse_scene(loaded.resolved, {}, "resolved").resolved, loaded.resolved);
}
