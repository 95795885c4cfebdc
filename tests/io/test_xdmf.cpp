// The XDMF description of the snapshots. The full check (XML parses, every dataset named
// is in the .h5 with the declared shape and type) is io.xdmf_matches_h5 (check_xdmf.py),
// what ParaView makes of it io.paraview_opens_outputs; these check the content that
// matters to a viewer.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "core/user_error.hpp"
#include "io/io_test_support.hpp"
#include "io/run_file.hpp"
#include "io/xdmf_writer.hpp"

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

const std::vector<FrameViewArray> kArrays{
    {"species", 1, true}, {"id", 1, true}, {"velocity", 3, false}, {"radius", 1, false}};

TEST(Xdmf, FramesReadTheirViewsAsPlainDatasets) {
  TempDir dir;
  const std::vector<SnapshotFrame> frames{{100, 0.5, 5}, {200, 1.0, 0}, {300, 1.5, 12}};
  write_particles_xdmf(dir / "particles.xmf", "run.h5", frames, 2, kArrays);
  const std::string xml = read_text(dir / "particles.xmf");
  EXPECT_EQ(occurrences(xml, "GridType=\"Uniform\""), 2u);  // the empty frame is left out
  EXPECT_EQ(xml.find("frame_000001"), std::string::npos);
  EXPECT_EQ(occurrences(xml, "<Time Value="), 2u);
  EXPECT_NE(xml.find("CollectionType=\"Temporal\""), std::string::npos);
  EXPECT_NE(xml.find("<Time Value=\"1.5\"/>"), std::string::npos);
  // ParaView's Xdmf3 readers cannot type a HyperSlab's array: they skipped it, or
  // crashed on the geometry (docs/output_format.md, "run.xmf").
  EXPECT_EQ(xml.find("HyperSlab"), std::string::npos);
  // Frame index 2 (step 300): its views, of exactly its 12 particles.
  EXPECT_NE(xml.find("TopologyType=\"Polyvertex\" NumberOfElements=\"12\" NodesPerElement=\"1\">\n"
                     "          <DataItem Dimensions=\"12\" NumberType=\"Int\" Precision=\"4\" "
                     "Format=\"HDF\">run.h5:/xdmf/frame_000002/vertex</DataItem>"),
            std::string::npos)
      << xml;
  EXPECT_NE(xml.find("<Geometry GeometryType=\"XY\">\n          <DataItem Dimensions=\"12 2\" "
                     "NumberType=\"Float\" Precision=\"8\" "
                     "Format=\"HDF\">run.h5:/xdmf/frame_000002/position<"),
            std::string::npos);
  EXPECT_NE(xml.find("Name=\"species\" AttributeType=\"Scalar\" Center=\"Node\">\n"
                     "          <DataItem Dimensions=\"12\" NumberType=\"Int\" Precision=\"4\" "
                     "Format=\"HDF\">run.h5:/xdmf/frame_000002/species<"),
            std::string::npos);
  // The velocity is one 3-component vector (z = 0 in 2-D), as glyphs need.
  EXPECT_NE(xml.find("Name=\"velocity\" AttributeType=\"Vector\" Center=\"Node\">\n"
                     "          <DataItem Dimensions=\"12 3\" NumberType=\"Float\" Precision=\"8\" "
                     "Format=\"HDF\">run.h5:/xdmf/frame_000002/velocity<"),
            std::string::npos);
  EXPECT_NE(xml.find("Name=\"radius\" AttributeType=\"Scalar\""), std::string::npos);
  EXPECT_EQ(xml.find("Name=\"vx\""), std::string::npos);
}

TEST(Xdmf, ThreeDimensionalFramesUseXYZ) {
  TempDir dir;
  write_particles_xdmf(dir / "particles.xmf", "run.h5", {{1, 0.25, 4}}, 3, kArrays);
  const std::string xml = read_text(dir / "particles.xmf");
  EXPECT_NE(xml.find("<Geometry GeometryType=\"XYZ\">\n          <DataItem Dimensions=\"4 3\""),
            std::string::npos);
  EXPECT_NE(xml.find("Name=\"velocity\" AttributeType=\"Vector\""), std::string::npos);
}

TEST(Xdmf, FileNameIsEscapedAndTimesAreExact) {
  TempDir dir;
  write_particles_xdmf(dir / "p.xmf", "a&b.h5", {{1, 0.1, 1}}, 2, kArrays);
  const std::string xml = read_text(dir / "p.xmf");
  EXPECT_NE(xml.find(">a&amp;b.h5:/xdmf/frame_000000/id<"), std::string::npos);
  EXPECT_NE(xml.find("<Time Value=\"0.10000000000000001\"/>"), std::string::npos);
}

TEST(Xdmf, RejectsNegativeCountsBadDimensionAndBadWidths) {
  TempDir dir;
  EXPECT_THROW(write_particles_xdmf(dir / "p.xmf", "run.h5", {{1, 0.0, -1}}, 2, kArrays),
               std::invalid_argument);
  EXPECT_THROW(write_particles_xdmf(dir / "p.xmf", "run.h5", {}, 4, kArrays),
               std::invalid_argument);
  EXPECT_THROW(write_particles_xdmf(dir / "p.xmf", "run.h5", {}, 2, {{"v", 2, false}}),
               std::invalid_argument);
  EXPECT_THROW(write_particles_xdmf(dir / "missing" / "p.xmf", "run.h5", {}, 2, kArrays),
               UserError);
}

TEST(Xdmf, DescribesWhatARunFileHolds) {
  TempDir dir;
  {
    RunFile run = RunFile::create(dir / "run.h5", "", "", 2, {{1e-3, 2e-3, 3e-3}, true});
    run.append_snapshot(1, 0.1, test::make_particles(3, 0));
    run.append_snapshot(2, 0.2, test::make_particles(7, 1));
    const std::vector<FrameViewArray> expected{{"species", 1, true},
                                               {"id", 1, true},
                                               {"velocity", 3, false},
                                               {"radius", 1, false},
                                               {"angular_velocity", 1, false}};
    EXPECT_EQ(run.frame_view_arrays(), expected);
    write_particles_xdmf(dir / "run.xmf", "run.h5", run.frames(), run.dim(),
                         run.frame_view_arrays());
  }
  const std::string xml = read_text(dir / "run.xmf");
  EXPECT_NE(xml.find("Dimensions=\"7 2\" NumberType=\"Float\" Precision=\"8\" "
                     "Format=\"HDF\">run.h5:/xdmf/frame_000001/position<"),
            std::string::npos);
  EXPECT_NE(xml.find(">run.h5:/xdmf/frame_000001/angular_velocity<"), std::string::npos);
  EXPECT_FALSE(std::filesystem::exists(dir / "run.xmf.tmp"));
}

}  // namespace
}  // namespace granshock
