// The per-frame views of run.h5 (io/frame_views.hpp) that run.xmf points viewers at, and the
// radius and angular velocity of format 2, read back with the plain HDF5 C API: what
// any HDF5 reader (ParaView's XDMF readers, h5py) sees through the virtual datasets.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "core/user_error.hpp"
#include "io/io_test_support.hpp"
#include "io/run_file.hpp"

namespace granshock {
namespace {

using test::TempDir;

const std::vector<double> kRadius{1e-3, 2e-3, 3e-3};  // make_particles' species 0, 1, 2

// Particles whose spin identifies them.
HostParticles spinning(int n, int frame) {
  HostParticles p = test::make_particles(n, frame);
  for (int i = 0; i < n; ++i) p.angular_velocity.push_back(10.0 * frame + i);
  return p;
}

std::string view(long frame, const std::string& name) {
  return frame_view_group(frame) + "/" + name;
}

// Sets the root attribute granshock_format_version and removes `remove` (if any): a file
// as an older or newer granshock would have written it.
void rewrite_as_format(const std::filesystem::path& path, int version, const char* remove) {
  const hid_t f = H5Fopen(path.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
  ASSERT_GE(f, 0);
  const hid_t a = H5Aopen(f, "granshock_format_version", H5P_DEFAULT);
  ASSERT_GE(H5Awrite(a, H5T_NATIVE_INT, &version), 0);
  H5Aclose(a);
  if (remove != nullptr) {
    ASSERT_GE(H5Ldelete(f, remove, H5P_DEFAULT), 0);
  }
  H5Fclose(f);
}

int format_version(const std::filesystem::path& path) {
  const hid_t f = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  int version = 0;
  const hid_t a = H5Aopen(f, "granshock_format_version", H5P_DEFAULT);
  H5Aread(a, H5T_NATIVE_INT, &version);
  H5Aclose(a);
  H5Fclose(f);
  return version;
}

TEST(FrameViews, HoldExactlyEachFramesParticles) {
  TempDir dir;
  const auto path = dir / "run.h5";
  {
    RunFile run = RunFile::create(path, "", "", 2, {kRadius, true});
    run.append_snapshot(10, 0.1, spinning(3, 0));
    run.append_snapshot(20, 0.2, spinning(7, 1));
    run.append_snapshot(30, 0.3, spinning(0, 2));
  }
  const HostParticles p = spinning(7, 1);
  const auto position = test::read_array<double>(path, view(1, "position"));
  const auto velocity = test::read_array<double>(path, view(1, "velocity"));
  EXPECT_EQ(position.shape, (std::vector<hsize_t>{7, 2}));
  ASSERT_EQ(velocity.shape, (std::vector<hsize_t>{7, 3}));
  for (std::size_t i = 0; i < 7; ++i) {
    EXPECT_EQ(position.values[2 * i], p.position[i][0]);
    EXPECT_EQ(position.values[2 * i + 1], p.position[i][1]);
    EXPECT_EQ(velocity.values[3 * i], p.velocity[i][0]);
    EXPECT_EQ(velocity.values[3 * i + 1], p.velocity[i][1]);
    EXPECT_EQ(velocity.values[3 * i + 2], 0.0) << "a 2-D velocity's z reads as 0";
  }
  EXPECT_EQ(test::read_array<int>(path, view(1, "species")).values, p.species);
  EXPECT_EQ(test::read_array<int>(path, view(1, "id")).values, p.id);
  EXPECT_EQ(test::read_array<int>(path, view(1, "vertex")).values,
            (std::vector<int>{0, 1, 2, 3, 4, 5, 6}));
  EXPECT_EQ(test::read_array<double>(path, view(1, "angular_velocity")).values, p.angular_velocity);
  std::vector<double> radius;
  for (int s : p.species) radius.push_back(kRadius[std::size_t(s)]);
  EXPECT_EQ(test::read_array<double>(path, view(1, "radius")).values, radius);
  // The H5MD elements behind them, padded like position.
  EXPECT_EQ(test::read_array<double>(path, "/particles/all/radius/value").shape,
            (std::vector<hsize_t>{3, 7}));
  EXPECT_EQ(test::read_array<long>(path, "/particles/all/angular_velocity/step").values,
            (std::vector<long>{10, 20, 30}));
  EXPECT_EQ(test::read_array<double>(path, "/parameters/species_radius").values, kRadius);
  // An empty frame has an empty group (viewers leave it out).
  EXPECT_TRUE(test::has_object(path, frame_view_group(2)));
  EXPECT_FALSE(test::has_object(path, view(2, "position")));
  EXPECT_EQ(format_version(path), kRunFileFormat);
}

TEST(FrameViews, ThreeDimensionalVelocitiesAreViewedAsStored) {
  TempDir dir;
  const auto path = dir / "run.h5";
  {
    RunFile run = RunFile::create(path, "", "", 3, {kRadius, false});
    run.append_snapshot(10, 0.1, test::make_particles(4, 2));
    EXPECT_EQ(run.frame_view_arrays().size(), 4u);  // no angular velocity without friction
  }
  const HostParticles p = test::make_particles(4, 2);
  const auto velocity = test::read_array<double>(path, view(0, "velocity"));
  ASSERT_EQ(velocity.shape, (std::vector<hsize_t>{4, 3}));
  for (std::size_t i = 0; i < 4; ++i)
    for (std::size_t c = 0; c < 3; ++c) EXPECT_EQ(velocity.values[3 * i + c], p.velocity[i][c]);
  EXPECT_EQ(test::read_array<double>(path, view(0, "position")).shape,
            (std::vector<hsize_t>{4, 3}));
  EXPECT_FALSE(test::has_object(path, "/particles/all/angular_velocity"));
}

// A resumed run rewrites the frames after its checkpoint: their views must show the new
// rows, and views of frames it has not reached again must go.
TEST(FrameViews, ResumeReplacesTheViewsOfFramesItCutAway) {
  TempDir dir;
  const auto path = dir / "run.h5";
  {
    RunFile run = RunFile::create(path, "", "", 2, {kRadius, true});
    run.append_snapshot(10, 0.1, spinning(3, 0));
    run.append_snapshot(20, 0.2, spinning(7, 1));
    run.append_snapshot(30, 0.3, spinning(5, 2));
  }
  {
    RunFile run = RunFile::open_for_resume(path, 10, {});
    run.append_snapshot(25, 0.25, spinning(2, 5));
  }
  EXPECT_EQ(test::read_array<int>(path, view(1, "id")).values, spinning(2, 5).id);
  EXPECT_EQ(test::read_array<double>(path, view(1, "angular_velocity")).values,
            spinning(2, 5).angular_velocity);
  EXPECT_EQ(test::read_array<int>(path, view(0, "id")).values, spinning(3, 0).id);
  EXPECT_FALSE(test::has_object(path, frame_view_group(2)));
}

// Run files of format 1 (before radius and views) are still read, and a resumed one keeps
// its layout: no radius from the middle of the run on; it gains views of every frame.
TEST(FrameViews, AFormatOneFileKeepsItsLayoutAndGainsViews) {
  TempDir dir;
  const auto path = dir / "run.h5";
  {
    RunFile run = RunFile::create(path, "", "", 2);
    run.append_snapshot(10, 0.1, test::make_particles(3, 0));
    run.append_snapshot(20, 0.2, test::make_particles(4, 1));
  }
  rewrite_as_format(path, 1, "/xdmf");
  EXPECT_EQ(RunFile::open_read_only(path).frames().size(), 2u);
  {
    RunFile run = RunFile::open_for_resume(path, 20, {});
    EXPECT_TRUE(run.contents().species_radius.empty());
    EXPECT_FALSE(run.contents().angular_velocity);
    run.append_snapshot(30, 0.3, spinning(5, 2));
    const std::vector<FrameViewArray> old{
        {"species", 1, true}, {"id", 1, true}, {"velocity", 3, false}};
    EXPECT_EQ(run.frame_view_arrays(), old);
  }
  EXPECT_EQ(format_version(path), 1);
  EXPECT_FALSE(test::has_object(path, "/particles/all/radius"));
  for (long k = 0; k < 3; ++k) EXPECT_TRUE(test::has_object(path, view(k, "velocity"))) << k;
  EXPECT_EQ(test::read_array<int>(path, view(0, "id")).values, test::make_particles(3, 0).id);
}

TEST(FrameViews, ANewerFormatIsRefusedByName) {
  TempDir dir;
  const auto path = dir / "run.h5";
  { RunFile::create(path, "", "", 2); }
  rewrite_as_format(path, kRunFileFormat + 1, nullptr);
  try {
    RunFile::open_read_only(path);
    FAIL() << "a run file of a newer format was read";
  } catch (const UserError& e) {
    EXPECT_NE(std::string(e.what()).find("run file of format 4, written by a newer granshock "
                                         "(this one reads formats 1 to 3)"),
              std::string::npos)
        << e.what();
  }
  EXPECT_THROW(RunFile::open_for_resume(path, 0, {}), UserError);
}

TEST(FrameViews, ASpeciesWithoutARadiusWritesNothing) {
  TempDir dir;
  RunFile run = RunFile::create(dir / "run.h5", "", "", 2, {{1e-3, 2e-3}, false});
  EXPECT_THROW(run.append_snapshot(10, 0.1, test::make_particles(3, 0)), std::invalid_argument);
  EXPECT_TRUE(run.frames().empty());
  HostParticles short_spin = test::make_particles(2, 0);
  short_spin.angular_velocity = {1.0};
  EXPECT_THROW(run.append_snapshot(10, 0.1, short_spin), std::invalid_argument);
  run.append_snapshot(10, 0.1, test::make_particles(2, 0));  // species 0 and 1
  EXPECT_EQ(run.frames().size(), 1u);
}

}  // namespace
}  // namespace granshock
