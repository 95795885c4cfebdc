// The field sums in run.h5 (io/field_sums_file.hpp): what `granshock run` writes,
// `granshock fields` reads back, value for value and with the geometry it was written
// with, for the bin grid and the stagnation-line profile; a file without sums is refused
// with a message that names it.
#include <gtest/gtest.h>

#include <cmath>
#include <numeric>

#include "core/user_error.hpp"
#include "io/field_sums_file.hpp"
#include "io/io_test_support.hpp"
#include "io/run_file.hpp"

namespace granshock {
namespace {

using test::TempDir;

FieldSumsRecord record(bool with_profile) {
  FieldSumsRecord r;
  BinLayout& g = r.sampling.grid;
  g.n_species = 2;
  g.nx = 5;
  g.ny = 7;
  g.x0 = 0.001;
  g.y0 = -0.002;
  g.dx = 0.003;
  g.dy = 0.0025;
  g.x_period = 0.015;
  g.blocks = 3;
  r.grid_sums.resize(std::size_t(g.blocks) * g.bins() * g.quantities());
  std::iota(r.grid_sums.begin(), r.grid_sums.end(), 0.25);
  if (with_profile) {
    BinLayout& p = r.sampling.profile;
    p = g;
    p.x0 = 0.004;
    p.nx = 4;
    p.dx = 0.001;
    p.x_period = 0;
    p.y0 = 0.0;
    p.dy = 0.0005;
    p.ny = 11;
    r.profile_sums.resize(std::size_t(g.blocks) * p.bins() * g.quantities());
    std::iota(r.profile_sums.begin(), r.profile_sums.end(), -3.5);
  }
  r.samples = {4, 5, 6};
  r.production_start = 0.1;
  r.production_end = 0.3;
  r.sample_every = 50;
  r.y_end = 0.0155;
  return r;
}

TEST(FieldSumsFile, GridAndProfileReadBackAsWritten) {
  TempDir dir;
  const FieldSumsRecord r = record(true);
  {
    RunFile run = RunFile::create(dir / "run.h5", "given", "resolved", 2);
    write_field_sums(run, r);
  }
  const RunFile run = RunFile::open_read_only(dir / "run.h5");
  const BinSums grid = read_grid_sums(run);
  const BinLayout& g = r.sampling.grid;
  EXPECT_EQ(grid.n_species, g.n_species);
  EXPECT_EQ(grid.nx, g.nx);
  EXPECT_EQ(grid.ny, g.ny);
  EXPECT_EQ(grid.blocks, g.blocks);
  EXPECT_EQ(grid.x0, g.x0);
  EXPECT_EQ(grid.y0, g.y0);
  EXPECT_EQ(grid.dx, g.dx);
  EXPECT_EQ(grid.dy, g.dy);
  EXPECT_EQ(grid.x_period, g.x_period);
  EXPECT_EQ(grid.y_end, r.y_end);
  EXPECT_EQ(grid.production_start, r.production_start);
  EXPECT_EQ(grid.production_end, r.production_end);
  EXPECT_EQ(grid.sums, r.grid_sums);
  EXPECT_EQ(grid.samples, (std::vector<double>{4, 5, 6}));
  // The layout's offsets address the same values the writer was given.
  EXPECT_EQ(grid.sums[std::size_t(grid.layout().offset(2, 6, 4, 3))],
            r.grid_sums[std::size_t(g.offset(2, 6, 4, 3))]);

  ASSERT_TRUE(has_profile_sums(run));
  const BinSums profile = read_profile_sums(run);
  const BinLayout& p = r.sampling.profile;
  EXPECT_EQ(profile.n_species, g.n_species);
  EXPECT_EQ(profile.nx, p.nx);
  EXPECT_EQ(profile.ny, p.ny);
  EXPECT_EQ(profile.blocks, g.blocks);
  EXPECT_EQ(profile.x0, p.x0);
  EXPECT_EQ(profile.dx, p.dx);
  EXPECT_EQ(profile.x_period, 0);
  EXPECT_EQ(profile.y0, p.y0);
  EXPECT_EQ(profile.dy, p.dy);
  EXPECT_EQ(profile.sums, r.profile_sums);
  EXPECT_EQ(profile.samples, grid.samples);
}

// Run files before the obstacle-aligned grid (granshock 0.8) had square bins (@bin_size) and
// a profile of one column (@n, @x_lo, @x_hi): they are still read.
TEST(FieldSumsFile, FilesWithSquareBinsAndAOneColumnProfileAreRead) {
  TempDir dir;
  const FieldSumsRecord r = record(true);
  {
    RunFile run = RunFile::create(dir / "run.h5", "given", "resolved", 2);
    const BinLayout& g = r.sampling.grid;
    run.write_array("/fields/grid/sums", r.grid_sums, {g.blocks, g.ny, g.nx, g.quantities()});
    run.write_array("/fields/grid/samples", {4, 5, 6}, {g.blocks});
    for (const auto& [name, value] : {std::pair<const char*, long>{"nx", g.nx},
                                      {"ny", g.ny},
                                      {"blocks", g.blocks},
                                      {"n_species", g.n_species}})
      run.write_attribute("/fields/grid", name, value);
    run.write_attribute("/fields/grid", "x0", g.x0);
    run.write_attribute("/fields/grid", "y0", g.y0);
    run.write_attribute("/fields/grid", "bin_size", 0.003);
    const std::vector<double> profile(std::size_t(g.blocks) * 11 * g.quantities(), 1.5);
    run.write_array("/fields/profile/sums", profile, {g.blocks, 11, g.quantities()});
    run.write_array("/fields/profile/samples", {4, 5, 6}, {g.blocks});
    run.write_attribute("/fields/profile", "n", 11L);
    run.write_attribute("/fields/profile", "x_lo", 0.004);
    run.write_attribute("/fields/profile", "x_hi", 0.008);
    run.write_attribute("/fields/profile", "y0", 0.0);
    run.write_attribute("/fields/profile", "dy", 0.0005);
  }
  const RunFile run = RunFile::open_read_only(dir / "run.h5");
  const BinSums grid = read_grid_sums(run);
  EXPECT_EQ(grid.dx, 0.003);
  EXPECT_EQ(grid.dy, 0.003);
  EXPECT_EQ(grid.x_period, 0);
  EXPECT_TRUE(std::isinf(grid.y_end));
  EXPECT_EQ(grid.sums, r.grid_sums);
  ASSERT_TRUE(has_profile_sums(run));
  const BinSums profile = read_profile_sums(run);
  EXPECT_EQ(profile.nx, 1);
  EXPECT_EQ(profile.ny, 11);
  EXPECT_EQ(profile.x0, 0.004);
  EXPECT_DOUBLE_EQ(profile.dx, 0.004);
  EXPECT_EQ(profile.dy, 0.0005);
  EXPECT_EQ(profile.n_species, 2);
}

TEST(FieldSumsFile, NoProfileIsSaidSo) {
  TempDir dir;
  {
    RunFile run = RunFile::create(dir / "run.h5", "given", "resolved", 2);
    write_field_sums(run, record(false));
  }
  const RunFile run = RunFile::open_read_only(dir / "run.h5");
  EXPECT_FALSE(has_profile_sums(run));
  EXPECT_EQ(read_grid_sums(run).nx, 5);
}

TEST(FieldSumsFile, ARunWithoutSumsIsRefusedNamingTheFile) {
  TempDir dir;
  { RunFile run = RunFile::create(dir / "run.h5", "given", "resolved", 2); }
  const RunFile run = RunFile::open_read_only(dir / "run.h5");
  try {
    static_cast<void>(read_grid_sums(run));
    FAIL() << "sums read from a file that has none";
  } catch (const UserError& e) {
    EXPECT_NE(std::string(e.what()).find("run.h5"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace granshock
