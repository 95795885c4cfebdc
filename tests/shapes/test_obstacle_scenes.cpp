// Scenes with a wedge, a plate or a square (docs/scene_format.md, [obstacle]): the keys read,
// written back and read again; the user errors of the shape keys, each one line naming the key; and
// a short run of each shape's scene: mass balance at every output, and run.h5 and checkpoint.h5
// recording the shape.
#include <gtest/gtest.h>

#include "cases/bow_shock/run_command.hpp"
#include "core/user_error.hpp"
#include "io/checkpoint_file.hpp"
#include "io/run_file.hpp"
#include "io/scene_file.hpp"
#include "models/obstacle_shapes.hpp"
#include "scene/run_helpers.hpp"
#include "scene/scene_fixtures.hpp"

using namespace granshock;
using granshock::testing::run_options;
using granshock::testing::small_scene;
using granshock::testing::TempDir;

namespace {

const std::string kWedge =
    "[obstacle]\nshape = \"wedge\"\nhalf_angle = 25\nlength = \"12 d\"\n"
    "centre = [\"20 d\", \"35 d\"]\n";
const std::string kPlate =
    "[obstacle]\nshape = \"plate\"\nwidth = \"10 d\"\nthickness = \"2 d\"\n"
    "centre = [\"20 d\", \"35 d\"]\n";
const std::string kSquare =
    "[obstacle]\nshape = \"square\"\nside = \"7 d\"\nrotation = 45\n"
    "centre = [\"20 d\", \"35 d\"]\n";

std::string scene_with(const std::string& obstacle) {
  return small_scene(false) + obstacle;
}

// The refusal of a scene, or "" when it is accepted.
std::string refusal(const std::string& text, const std::vector<std::string>& sets = {}) {
  try {
    parse_scene(text, sets);
  } catch (const UserError& e) {
    return e.what();
  }
  return "";
}

void expect_same_obstacle(const Obstacle& a, const Obstacle& b) {
  EXPECT_EQ(a.shape, b.shape);
  EXPECT_EQ(a.centre, b.centre);
  EXPECT_EQ(a.size, b.size);
}

}  // namespace

TEST(ObstacleScene, EveryShapeSurvivesTheResolvedScene) {
  for (const std::string& obstacle : {kWedge, kPlate, kSquare}) {
    const LoadedScene a = parse_scene(scene_with(obstacle));
    ASSERT_TRUE(a.scene.setup.obstacle);
    const LoadedScene b = parse_scene(a.resolved);
    ASSERT_TRUE(b.scene.setup.obstacle);
    expect_same_obstacle(*a.scene.setup.obstacle, *b.scene.setup.obstacle);
    EXPECT_EQ(a.resolved, b.resolved);
  }
  const Obstacle w = *parse_scene(scene_with(kWedge)).scene.setup.obstacle;
  EXPECT_EQ(w.shape, ObstacleShape::wedge);
  EXPECT_EQ(WedgeShape::half_angle_deg(w), 25);
  EXPECT_DOUBLE_EQ(WedgeShape::length(w), 0.012);
  const Obstacle p = *parse_scene(scene_with(kPlate)).scene.setup.obstacle;
  EXPECT_EQ(p.shape, ObstacleShape::plate);
  EXPECT_DOUBLE_EQ(PlateShape::width(p), 0.010);
  EXPECT_DOUBLE_EQ(PlateShape::thickness(p), 0.002);
  const Obstacle q = *parse_scene(scene_with(kSquare)).scene.setup.obstacle;
  EXPECT_EQ(q.shape, ObstacleShape::square);
  EXPECT_DOUBLE_EQ(SquareShape::side(q), 0.007);
  EXPECT_EQ(SquareShape::rotation_deg(q), 45);
  // rotation has a default, written into the resolved scene.
  const LoadedScene face_on =
      parse_scene(scene_with("[obstacle]\nshape = \"square\"\nside = \"7 d\"\n"));
  EXPECT_EQ(SquareShape::rotation_deg(*face_on.scene.setup.obstacle), 0);
  EXPECT_NE(face_on.resolved.find("rotation = 0"), std::string::npos);
  // The cylinder stays the default, and its resolved scene names it.
  const LoadedScene c = parse_scene(small_scene(true));
  EXPECT_EQ(c.scene.setup.obstacle->shape, ObstacleShape::cylinder);
  EXPECT_NE(c.resolved.find("shape = 'cylinder'"), std::string::npos);
}

TEST(ObstacleScene, ShapeKeyErrorsNameTheKey) {
  const std::string wedge = scene_with(kWedge), plate = scene_with(kPlate);
  EXPECT_EQ(refusal(wedge, {"obstacle.half_angle=0"}),
            "scene key 'obstacle.half_angle' = 0: must be in (0, 90)");
  EXPECT_EQ(refusal(wedge, {"obstacle.half_angle=90"}),
            "scene key 'obstacle.half_angle' = 90: must be in (0, 90)");
  EXPECT_EQ(refusal(plate, {"obstacle.width=0"}), "scene key 'obstacle.width' = 0 m: must be > 0");
  EXPECT_NE(refusal(plate, {"obstacle.width=\"41 d\""})
                .find("the plate must lie inside the domain, downstream of the insertion strip"),
            std::string::npos);
  // As wide as the periodic channel (40 d), or nearly: accepted before, the flow closed.
  EXPECT_EQ(refusal(plate, {"obstacle.width=\"40 d\""}),
            "scene key 'obstacle.width' = 0.04 m across the flow, in a channel of domain.width "
            "= 0.04 m: the plate leaves a gap of 0 particle diameters beside it; it must leave "
            "at least 3 for the flow to pass: make it narrower or the domain wider");
  EXPECT_NE(refusal(small_scene(true), {"obstacle.diameter=\"37.5 d\""})
                .find("scene key 'obstacle.diameter' = 0.0375 m across the flow, in a channel of "
                      "domain.width = 0.04 m: the cylinder leaves a gap of 2.5 particle diameters"),
            std::string::npos);
  EXPECT_EQ(refusal(plate, {"obstacle.width=\"36 d\""}), "");
  EXPECT_NE(refusal(wedge, {"obstacle.length=\"50 d\""})
                .find("the wedge must lie inside the domain, downstream of the insertion strip"),
            std::string::npos);
  EXPECT_EQ(refusal(small_scene(true), {"obstacle.half_angle=20"}),
            "scene key 'obstacle.half_angle' = 20: is a key of obstacle.shape = \"wedge\", and "
            "the shape is \"cylinder\"");
  EXPECT_EQ(refusal(wedge, {"obstacle.diameter=\"10 d\""}),
            "scene key 'obstacle.diameter' = \"10 d\": is a key of obstacle.shape = \"cylinder\" "
            "or \"sphere\", and the shape is \"wedge\"");
  EXPECT_NE(refusal(scene_with("[obstacle]\nshape = \"wedge\"\nhalf_angle = 20\n"))
                .find("obstacle.length"),
            std::string::npos);
  EXPECT_EQ(refusal(plate, {"obstacle.shape=\"ball\""}).rfind("scene key 'obstacle.shape'", 0), 0u);
  const std::string square = scene_with(kSquare);
  EXPECT_EQ(refusal(square, {"obstacle.rotation=90"}),
            "scene key 'obstacle.rotation' = 90: must be in [0, 90)");
  EXPECT_EQ(refusal(square, {"obstacle.width=\"4 d\""}),
            "scene key 'obstacle.width' = \"4 d\": is a key of obstacle.shape = \"plate\", and "
            "the shape is \"square\"");
  EXPECT_EQ(refusal(plate, {"obstacle.side=\"4 d\""}),
            "scene key 'obstacle.side' = \"4 d\": is a key of obstacle.shape = \"square\", and "
            "the shape is \"plate\"");
  // A diamond of side 27 d is 38.2 d across: the channel's gap names both of its keys.
  EXPECT_NE(refusal(square, {"obstacle.side=\"27 d\""})
                .find("scene key 'obstacle.side' and 'obstacle.rotation' = 0.03818"),
            std::string::npos);
}

// The run refuses a particle inside the obstacle (cases/bow_shock/run_observables.cpp), so
// a completed run also says insertion kept out of each shape.
TEST(ObstacleScene, EachShapeRunsWithMassBalanceAndRecordsItsShape) {
  for (const std::string& obstacle : {kWedge, kPlate, kSquare}) {
    TempDir tmp;
    const auto scene = tmp.write("shape.toml", scene_with(obstacle));
    ASSERT_EQ(run_scene(run_options(scene, tmp.path() / "run",
                                    {"time.duration=0.004", "time.production_start=0.002"})),
              0);
    const RunFile f = RunFile::open_read_only(tmp.path() / "run" / "run.h5");
    const auto series = [&](const std::string& n) {
      return f.read_array("/observables/" + n + "/value");
    };
    const auto present = series("particles"), inserted = series("inserted");
    const auto outlet = series("deleted_outlet"), inlet = series("deleted_inlet");
    ASSERT_EQ(present.size(), 9u);  // every 0.5 ms over 4 ms, and step 0
    for (std::size_t k = 0; k < present.size(); ++k)
      EXPECT_EQ(inserted[k] - outlet[k] - inlet[k], present[k]) << "row " << k;
    const Obstacle given = *parse_scene(scene_with(obstacle)).scene.setup.obstacle;
    expect_same_obstacle(*parse_scene(f.scene_resolved()).scene.setup.obstacle, given);
    CheckpointExtras extras;
    read_checkpoint(tmp.path() / "run" / "checkpoint.h5", extras);
    expect_same_obstacle(*parse_scene(extras.scene_resolved).scene.setup.obstacle, given);
  }
}
