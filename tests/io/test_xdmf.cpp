// The XDMF description of the snapshots. The full check (XML parses, every hyperslab
// fits a dataset in the .h5) is io.xdmf_matches_h5 (check_xdmf.py); these check the
// content that matters to a viewer.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "io/io_test_support.hpp"
#include "run_file.hpp"
#include "user_error.hpp"
#include "xdmf_writer.hpp"

namespace granshock {
namespace {

using test::TempDir;

std::string read_text(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

std::size_t occurrences(const std::string& text, const std::string& what) {
  std::size_t count = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) {
    ++count;
  }
  return count;
}

TEST(Xdmf, TwoDimensionalFramesUseXYAndVelocityComponents) {
  TempDir dir;
  const std::vector<SnapshotFrame> frames{{100, 0.5, 5}, {200, 1.0, 0}, {300, 1.5, 12}};
  write_particles_xdmf(dir / "particles.xmf", "run.h5", frames, 2, 12);
  const std::string xml = read_text(dir / "particles.xmf");
  EXPECT_EQ(occurrences(xml, "GridType=\"Uniform\""), 2u);  // the empty frame is left out
  EXPECT_EQ(occurrences(xml, "<Time Value="), 2u);
  EXPECT_NE(xml.find("CollectionType=\"Temporal\""), std::string::npos);
  EXPECT_NE(xml.find("<Time Value=\"1.5\"/>"), std::string::npos);
  EXPECT_NE(xml.find("TopologyType=\"Polyvertex\" NumberOfElements=\"12\""), std::string::npos);
  EXPECT_NE(xml.find("GeometryType=\"XY\""), std::string::npos);
  // Frame index 2 (step 300): [2, 0:12, 0:2] of the [3, 12, 2] dataset.
  EXPECT_NE(xml.find(">2 0 0  1 1 1  1 12 2</DataItem>"), std::string::npos) << xml;
  EXPECT_NE(xml.find("Dimensions=\"3 12 2\" NumberType=\"Float\" Precision=\"8\" "
                     "Format=\"HDF\">run.h5:/particles/all/position/value<"),
            std::string::npos);
  EXPECT_NE(xml.find("Dimensions=\"3 12\" NumberType=\"Int\" Precision=\"4\" "
                     "Format=\"HDF\">run.h5:/particles/all/species/value<"),
            std::string::npos);
  EXPECT_NE(xml.find(">2 0 1  1 1 1  1 12 1</DataItem>"), std::string::npos);  // vy
  EXPECT_NE(xml.find("Name=\"vx\""), std::string::npos);
  EXPECT_NE(xml.find("Name=\"vy\""), std::string::npos);
  EXPECT_EQ(xml.find("AttributeType=\"Vector\""), std::string::npos);
}

TEST(Xdmf, ThreeDimensionalFramesUseXYZAndAVelocityVector) {
  TempDir dir;
  write_particles_xdmf(dir / "particles.xmf", "run.h5", {{1, 0.25, 4}}, 3, 8);
  const std::string xml = read_text(dir / "particles.xmf");
  EXPECT_NE(xml.find("GeometryType=\"XYZ\""), std::string::npos);
  EXPECT_NE(xml.find("Name=\"velocity\" AttributeType=\"Vector\""), std::string::npos);
  EXPECT_NE(xml.find("Dimensions=\"4 3\""), std::string::npos);
  EXPECT_NE(xml.find("Dimensions=\"1 8 3\""), std::string::npos);
}

TEST(Xdmf, FileNameIsEscapedAndTimesAreExact) {
  TempDir dir;
  write_particles_xdmf(dir / "p.xmf", "a&b.h5", {{1, 0.1, 1}}, 2, 1);
  const std::string xml = read_text(dir / "p.xmf");
  EXPECT_NE(xml.find(">a&amp;b.h5:/particles/all/id/value<"), std::string::npos);
  EXPECT_NE(xml.find("<Time Value=\"0.10000000000000001\"/>"), std::string::npos);
}

TEST(Xdmf, RejectsCountsAboveCapacityAndBadDimension) {
  TempDir dir;
  EXPECT_THROW(write_particles_xdmf(dir / "p.xmf", "run.h5", {{1, 0.0, 9}}, 2, 8),
               std::invalid_argument);
  EXPECT_THROW(write_particles_xdmf(dir / "p.xmf", "run.h5", {}, 4, 8), std::invalid_argument);
  EXPECT_THROW(write_particles_xdmf(dir / "missing" / "p.xmf", "run.h5", {}, 2, 8), UserError);
}

TEST(Xdmf, DescribesWhatARunFileHolds) {
  TempDir dir;
  {
    RunFile run = RunFile::create(dir / "run.h5", "", "", 2);
    run.append_snapshot(1, 0.1, test::make_particles(3, 0));
    run.append_snapshot(2, 0.2, test::make_particles(7, 1));
    write_particles_xdmf(dir / "run.xmf", "run.h5", run.frames(), run.dim(),
                         run.particle_capacity());
  }
  const std::string xml = read_text(dir / "run.xmf");
  EXPECT_NE(xml.find("Dimensions=\"2 7 2\""), std::string::npos);
  EXPECT_NE(xml.find(">1 0 0  1 1 1  1 7 2</DataItem>"), std::string::npos);
  EXPECT_FALSE(std::filesystem::exists(dir / "run.xmf.tmp"));
}

}  // namespace
}  // namespace granshock
