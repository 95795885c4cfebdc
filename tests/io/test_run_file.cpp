// run.h5: snapshots with a varying particle number, time series, resume truncation,
// header, errors and write speed.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>

#include "core/user_error.hpp"
#include "io/io_test_support.hpp"
#include "io/run_file.hpp"

namespace granshock {
namespace {

using test::make_particles;
using test::read_array;
using test::TempDir;

TimeSeriesRow make_row(long step) {
  TimeSeriesRow row;
  row.step = step;
  row.time = 1e-6 * static_cast<double>(step);
  row.particles = 10 + step;
  row.kinetic_energy = 0.5 * static_cast<double>(step);
  row.temperature = 0.25 * static_cast<double>(step);
  row.contacts = 3 * step;
  row.inserted = step / 10;
  row.deleted_outlet = step / 20;
  row.deleted_inlet = step / 100;
  return row;
}

TEST(RunFile, CreateWritesHeaderAndScene) {
  TempDir dir;
  const auto path = dir / "run.h5";
  {
    RunFile run = RunFile::create(path, "as = 'given'\n", "resolved = 1\n", 2);
    EXPECT_EQ(run.dim(), 2);
    EXPECT_EQ(run.particle_capacity(), 0);
    EXPECT_TRUE(run.frames().empty());
  }
  const hid_t f = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  ASSERT_GE(f, 0);
  const hid_t h5md = H5Gopen2(f, "/h5md", H5P_DEFAULT);
  const hid_t version = H5Aopen(h5md, "version", H5P_DEFAULT);
  int v[2] = {0, 0};
  ASSERT_GE(H5Aread(version, H5T_NATIVE_INT, v), 0);
  EXPECT_EQ(v[0], 1);
  EXPECT_EQ(v[1], 1);
  H5Aclose(version);
  H5Gclose(h5md);
  H5Fclose(f);
  for (const char* group : {"/h5md/creator", "/h5md/author", "/particles/all/box",
                            "/observables/kinetic_energy/value"}) {
    EXPECT_TRUE(test::has_object(path, group)) << group;
  }
  RunFile run = RunFile::open_read_only(path);
  EXPECT_EQ(run.scene_as_given(), "as = 'given'\n");
  EXPECT_EQ(run.scene_resolved(), "resolved = 1\n");
  EXPECT_EQ(run.read_attribute_string("/h5md/creator", "name"), "granshock");
  EXPECT_EQ(run.read_attribute_string("/h5md/author", "name"), "granshock");
  EXPECT_EQ(run.read_attribute_long("/particles/all/box", "dimension"), 2);
}

TEST(RunFile, SnapshotsWithVaryingCountsRoundTrip) {
  TempDir dir;
  const auto path = dir / "run.h5";
  const int counts[] = {5, 12, 0, 3};
  {
    RunFile run = RunFile::create(path, "", "", 2);
    for (int f = 0; f < 4; ++f) {
      run.append_snapshot(100 * (f + 1), 0.5 * (f + 1), make_particles(counts[f], f));
    }
    EXPECT_EQ(run.particle_capacity(), 12);
    const std::vector<SnapshotFrame> frames = run.frames();
    ASSERT_EQ(frames.size(), 4u);
    for (int f = 0; f < 4; ++f) {
      EXPECT_EQ(frames[static_cast<std::size_t>(f)].step, 100 * (f + 1));
      EXPECT_EQ(frames[static_cast<std::size_t>(f)].time, 0.5 * (f + 1));
      EXPECT_EQ(frames[static_cast<std::size_t>(f)].count, counts[f]);
    }
  }
  const auto position = read_array<double>(path, "/particles/all/position/value");
  const auto velocity = read_array<double>(path, "/particles/all/velocity/value");
  const auto species = read_array<int>(path, "/particles/all/species/value");
  const auto id = read_array<int>(path, "/particles/all/id/value");
  ASSERT_EQ(position.shape, (std::vector<hsize_t>{4, 12, 2}));
  ASSERT_EQ(velocity.shape, (std::vector<hsize_t>{4, 12, 2}));
  ASSERT_EQ(species.shape, (std::vector<hsize_t>{4, 12}));
  ASSERT_EQ(id.shape, (std::vector<hsize_t>{4, 12}));
  for (int f = 0; f < 4; ++f) {
    const HostParticles p = make_particles(counts[f], f);
    for (int i = 0; i < 12; ++i) {
      const std::size_t row = static_cast<std::size_t>(f * 12 + i);
      if (i < counts[f]) {
        const std::size_t k = static_cast<std::size_t>(i);
        EXPECT_EQ(position.values[2 * row], p.position[k][0]);
        EXPECT_EQ(position.values[2 * row + 1], p.position[k][1]);
        EXPECT_EQ(velocity.values[2 * row], p.velocity[k][0]);
        EXPECT_EQ(velocity.values[2 * row + 1], p.velocity[k][1]);
        EXPECT_EQ(species.values[row], p.species[k]);
        EXPECT_EQ(id.values[row], p.id[k]);
      } else {  // past the frame's count: the fill values
        EXPECT_TRUE(std::isnan(position.values[2 * row])) << "frame " << f << " row " << i;
        EXPECT_TRUE(std::isnan(position.values[2 * row + 1]));
        EXPECT_TRUE(std::isnan(velocity.values[2 * row]));
        EXPECT_EQ(species.values[row], -1);
        EXPECT_EQ(id.values[row], -1);
      }
    }
  }
  for (const char* element : {"position", "velocity", "species", "id", "count"}) {
    const std::string group = std::string("/particles/all/") + element;
    const auto step = read_array<long>(path, group + "/step");
    const auto time = read_array<double>(path, group + "/time");
    EXPECT_EQ(step.values, (std::vector<long>{100, 200, 300, 400})) << group;
    EXPECT_EQ(time.values, (std::vector<double>{0.5, 1.0, 1.5, 2.0})) << group;
  }
  EXPECT_EQ(read_array<long>(path, "/particles/all/count/value").values,
            (std::vector<long>{5, 12, 0, 3}));
}

TEST(RunFile, ThreeDimensionalSnapshotKeepsZ) {
  TempDir dir;
  const auto path = dir / "run.h5";
  const HostParticles p = make_particles(4, 1);
  {
    RunFile run = RunFile::create(path, "", "", 3);
    run.append_snapshot(1, 0.1, p);
  }
  const auto position = read_array<double>(path, "/particles/all/position/value");
  ASSERT_EQ(position.shape, (std::vector<hsize_t>{1, 4, 3}));
  for (std::size_t i = 0; i < 4; ++i) {
    for (std::size_t c = 0; c < 3; ++c) EXPECT_EQ(position.values[3 * i + c], p.position[i][c]);
  }
}

TEST(RunFile, TimeSeriesRoundTrips) {
  TempDir dir;
  const auto path = dir / "run.h5";
  {
    RunFile run = RunFile::create(path, "", "", 2);
    for (long step : {0L, 50L, 100L}) run.append_time_series(make_row(step));
  }
  const std::vector<long> steps{0, 50, 100};
  auto expect_series = [&](const char* name, auto field) {
    const std::string group = std::string("/observables/") + name;
    EXPECT_EQ(read_array<long>(path, group + "/step").values, steps) << name;
    const auto time = read_array<double>(path, group + "/time");
    ASSERT_EQ(time.values.size(), 3u);
    for (std::size_t i = 0; i < 3; ++i) {
      const TimeSeriesRow row = make_row(steps[i]);
      EXPECT_EQ(time.values[i], row.time);
      using Value = decltype(field(row));
      const auto value = read_array<Value>(path, group + "/value");
      ASSERT_EQ(value.shape, (std::vector<hsize_t>{3})) << name;
      EXPECT_EQ(value.values[i], field(row)) << name;
    }
  };
  expect_series("particles", [](const TimeSeriesRow& r) { return r.particles; });
  expect_series("kinetic_energy", [](const TimeSeriesRow& r) { return r.kinetic_energy; });
  expect_series("temperature", [](const TimeSeriesRow& r) { return r.temperature; });
  expect_series("contacts", [](const TimeSeriesRow& r) { return r.contacts; });
  expect_series("inserted", [](const TimeSeriesRow& r) { return r.inserted; });
  expect_series("deleted_outlet", [](const TimeSeriesRow& r) { return r.deleted_outlet; });
  expect_series("deleted_inlet", [](const TimeSeriesRow& r) { return r.deleted_inlet; });
}

TEST(RunFile, ResumeTruncatesToTheCheckpointStep) {
  TempDir dir;
  const auto path = dir / "run.h5";
  RunFileRecord at_frame_3;  // what a checkpoint at step 300 records
  {
    RunFile run = RunFile::create(path, "", "", 2);
    for (int f = 1; f <= 5; ++f) {
      run.append_snapshot(100 * f, 0.1 * f, make_particles(2 + f, f));
      run.append_time_series(make_row(100 * f));
      if (f == 3) at_frame_3 = run.record();
    }
  }
  {
    // The checkpoint was taken at the step of frame 3; frames 4 and 5 are redone.
    RunFile run = RunFile::open_for_resume(path, 300, at_frame_3);
    EXPECT_EQ(run.frames().size(), 3u);
    run.append_snapshot(400, 0.4, make_particles(1, 40));
    run.append_snapshot(500, 0.5, make_particles(2, 50));
    run.append_time_series(make_row(400));
    run.append_time_series(make_row(500));
    const std::vector<SnapshotFrame> frames = run.frames();
    ASSERT_EQ(frames.size(), 5u);
    EXPECT_EQ(frames[3].count, 1);
    EXPECT_EQ(frames[4].count, 2);
  }
  const std::vector<long> steps{100, 200, 300, 400, 500};
  for (const char* group :
       {"/particles/all/position", "/particles/all/velocity", "/particles/all/species",
        "/particles/all/id", "/particles/all/count", "/observables/particles",
        "/observables/kinetic_energy", "/observables/deleted_inlet"}) {
    EXPECT_EQ(read_array<long>(path, std::string(group) + "/step").values, steps) << group;
    EXPECT_EQ(read_array<double>(path, std::string(group) + "/time").values.size(), 5u) << group;
  }
  const auto id = read_array<int>(path, "/particles/all/id/value");
  ASSERT_EQ(id.shape[0], 5u);
  const std::size_t width = id.shape[1];
  EXPECT_EQ(id.values[3 * width + 0], 40000);  // frame 4 is the new one
  EXPECT_EQ(id.values[3 * width + 1], -1);     // ... with one particle, not the old 6
  EXPECT_EQ(id.values[4 * width + 1], 50001);
  EXPECT_EQ(read_array<long>(path, "/observables/contacts/value").values,
            (std::vector<long>{300, 600, 900, 1200, 1500}));
}

TEST(RunFile, ResumeBeforeTheFirstFrameEmptiesTheSeries) {
  TempDir dir;
  const auto path = dir / "run.h5";
  RunFileRecord at_step_0;
  {
    RunFile run = RunFile::create(path, "", "", 2);
    at_step_0 = run.record();
    run.append_snapshot(10, 0.1, make_particles(3, 0));
    run.append_time_series(make_row(10));
  }
  RunFile run = RunFile::open_for_resume(path, 0, at_step_0);
  EXPECT_TRUE(run.frames().empty());
  run.append_snapshot(10, 0.1, make_particles(2, 0));
  EXPECT_EQ(run.frames().size(), 1u);
}

TEST(RunFile, StepsMustIncrease) {
  TempDir dir;
  RunFile run = RunFile::create(dir / "run.h5", "", "", 2);
  run.append_snapshot(10, 0.1, make_particles(1, 0));
  EXPECT_THROW(run.append_snapshot(10, 0.1, make_particles(1, 0)), std::invalid_argument);
  run.append_time_series(make_row(10));
  EXPECT_THROW(run.append_time_series(make_row(5)), std::invalid_argument);
  HostParticles bad = make_particles(2, 0);
  bad.id.pop_back();
  EXPECT_THROW(run.append_snapshot(20, 0.2, bad), std::invalid_argument);
}

TEST(RunFile, CreateInAMissingDirectoryIsAUserError) {
  TempDir dir;
  const auto path = dir / "no_such_dir" / "run.h5";
  try {
    RunFile::create(path, "", "", 2);
    FAIL() << "no exception";
  } catch (const UserError& e) {
    EXPECT_NE(std::string(e.what()).find(path.string()), std::string::npos) << e.what();
  }
  // A regular file used as a directory: fails even for root.
  std::ofstream(dir / "file") << "x";
  EXPECT_THROW(RunFile::create(dir / "file" / "run.h5", "", "", 2), UserError);
}

TEST(RunFile, OpeningWhatIsNotARunFileIsAUserError) {
  TempDir dir;
  EXPECT_THROW(RunFile::open_for_resume(dir / "missing.h5", 0, {}), UserError);
  std::ofstream(dir / "text.h5") << "not hdf5";
  EXPECT_THROW(RunFile::open_for_resume(dir / "text.h5", 0, {}), UserError);
  // An HDF5 file that is not ours.
  const hid_t f = H5Fcreate((dir / "other.h5").c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
  ASSERT_GE(f, 0);
  H5Fclose(f);
  try {
    RunFile::open_read_only(dir / "other.h5");
    FAIL() << "no exception";
  } catch (const UserError& e) {
    EXPECT_NE(std::string(e.what()).find("not a granshock run file"), std::string::npos);
  }
}

TEST(RunFile, SummaryAttributesAndArraysRoundTrip) {
  TempDir dir;
  const auto path = dir / "run.h5";
  {
    RunFile run = RunFile::create(path, "", "", 2);
    run.write_attribute("/summary", "mach", 5.25);
    run.write_attribute("/summary", "steps", 123456789012L);
    run.write_attribute("/summary", "backend", std::string("OpenMP"));
    run.write_attribute("/summary", "mach", 6.5);  // replaces
    run.write_attribute("/", "note", std::string("root attribute"));
    run.write_array("/fields/bin_sums", {1, 2, 3, 4, 5, 6}, {2, 3});
    run.write_array("/fields/bin_sums", {1, 2, 3, 4, 5, 6, 7, 8}, {2, 2, 2});  // replaces
    EXPECT_THROW(run.write_array("/fields/bad", {1, 2, 3}, {2, 2}), std::invalid_argument);
    run.flush();
  }
  RunFile run = RunFile::open_read_only(path);
  EXPECT_EQ(run.read_attribute_double("/summary", "mach"), 6.5);
  EXPECT_EQ(run.read_attribute_long("/summary", "steps"), 123456789012L);
  EXPECT_EQ(run.read_attribute_string("/summary", "backend"), "OpenMP");
  EXPECT_EQ(run.read_attribute_string("/", "note"), "root attribute");
  std::vector<long> shape;
  EXPECT_EQ(run.read_array("/fields/bin_sums", &shape),
            (std::vector<double>{1, 2, 3, 4, 5, 6, 7, 8}));
  EXPECT_EQ(shape, (std::vector<long>{2, 2, 2}));
  EXPECT_THROW(run.read_attribute_double("/summary", "missing"), UserError);
}

TEST(RunFile, MovesKeepTheFileOpen) {
  TempDir dir;
  RunFile first = RunFile::create(dir / "run.h5", "", "", 2);
  RunFile second = std::move(first);
  second.append_snapshot(1, 0.0, make_particles(2, 0));
  RunFile third = RunFile::create(dir / "other.h5", "", "", 3);
  third = std::move(second);
  EXPECT_EQ(third.frames().size(), 1u);
  EXPECT_EQ(third.dim(), 2);
}

// Large frames (100k particles, several chunks of the particle dimension) are stored
// whole. Their write speed is measured, not asserted, by `write_sample_run --bench`
// (timings in tests fail on a busy machine).
TEST(RunFile, SnapshotOf100kParticlesIsStoredWhole) {
  TempDir dir;
  RunFile run = RunFile::create(dir / "run.h5", "", "", 2);
  const HostParticles p = test::random_particles(100000);
  for (int f = 0; f < 3; ++f) run.append_snapshot(f + 1, 0.1 * f, p);
  run.flush();
  const auto frames = run.frames();
  ASSERT_EQ(frames.size(), 3u);
  for (const auto& frame : frames) EXPECT_EQ(frame.count, 100000);
  EXPECT_GE(run.particle_capacity(), 100000);
  const auto positions = run.read_array("/particles/all/position/value");
  const long cap = run.particle_capacity();
  // The last particle of the last frame reads back exactly.
  EXPECT_EQ(positions[(2 * cap + 99999) * 2 + 0], p.position[99999][0]);
  EXPECT_EQ(positions[(2 * cap + 99999) * 2 + 1], p.position[99999][1]);
}

struct Datasets {
  std::vector<std::string> chunked_without_checksum, checksummed;
};

herr_t visit_dataset(hid_t object, const char* name, const H5O_info_t* info, void* data) {
  if (info->type != H5O_TYPE_DATASET) return 0;
  auto& found = *static_cast<Datasets*>(data);
  const hid_t set = H5Dopen2(object, name, H5P_DEFAULT);
  const hid_t creation = H5Dget_create_plist(set);
  if (H5Pget_layout(creation) == H5D_CHUNKED) {
    bool checksum = false;
    for (int k = 0; k < H5Pget_nfilters(creation); ++k) {
      unsigned flags = 0;
      std::size_t values = 0;
      checksum |= H5Pget_filter2(creation, unsigned(k), &flags, &values, nullptr, 0, nullptr,
                                 nullptr) == H5Z_FILTER_FLETCHER32;
    }
    (checksum ? found.checksummed : found.chunked_without_checksum).push_back(name);
  }
  H5Pclose(creation);
  H5Dclose(set);
  return 0;
}

// The file offset of the middle of dataset `name`'s first stored chunk.
haddr_t middle_of_first_chunk(const std::filesystem::path& path, const char* name) {
  const hid_t f = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  const hid_t set = H5Dopen2(f, name, H5P_DEFAULT);
  const hid_t space = H5Dget_space(set);
  hsize_t chunks = 0, offset[3] = {0, 0, 0}, size = 0;
  unsigned mask = 0;
  haddr_t address = HADDR_UNDEF;
  if (H5Dget_num_chunks(set, space, &chunks) >= 0 && chunks > 0)
    H5Dget_chunk_info(set, space, 0, offset, &mask, &address, &size);
  H5Sclose(space);
  H5Dclose(set);
  H5Fclose(f);
  return address == HADDR_UNDEF ? address : address + size / 2;
}

void flip_byte(const std::filesystem::path& path, haddr_t at) {
  std::fstream f(path, std::ios::in | std::ios::out | std::ios::binary);
  f.seekg(std::streamoff(at));
  char c = 0;
  f.get(c);
  f.seekp(std::streamoff(at));
  f.put(char(c ^ 0x10));
}

// run.h5 had no checksum: `granshock fields` read 27 of 30 random byte flips as numbers.
// Every chunked dataset carries HDF5's Fletcher32 checksum now, and a flipped byte in a
// chunk is refused in one line naming the file as damaged.
TEST(RunFile, EveryChunkedDatasetIsChecksummedAndADamagedChunkIsRefused) {
  TempDir dir;
  const auto path = dir / "run.h5";
  {
    RunFile run = RunFile::create(path, "", "", 2, SnapshotContents{{5e-4, 5e-4, 4e-4}, true});
    for (int f = 0; f < 3; ++f)
      run.append_snapshot(100 * (f + 1), 0.5 * (f + 1), make_particles(7, f));
    for (long step = 0; step < 3; ++step) run.append_time_series(make_row(step));
    run.write_array("/fields/grid/sums", std::vector<double>(4096, 1.5), {16, 256});
  }
  Datasets found;
  {
    const hid_t f = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
    ASSERT_GE(H5Ovisit(f, H5_INDEX_NAME, H5_ITER_INC, visit_dataset, &found), 0);
    H5Fclose(f);
  }
  EXPECT_TRUE(found.chunked_without_checksum.empty())
      << "without a checksum: " << ::testing::PrintToString(found.chunked_without_checksum);
  for (const char* expected : {"particles/all/position/value", "particles/all/radius/value",
                               "observables/kinetic_energy/time", "fields/grid/sums",
                               "parameters/species_radius", "xdmf/vertex_index"})
    EXPECT_NE(std::find(found.checksummed.begin(), found.checksummed.end(), expected),
              found.checksummed.end())
        << expected << " is not checksummed";

  for (const char* name : {"/fields/grid/sums", "/particles/all/position/value"}) {
    const auto damaged = dir / "damaged.h5";
    std::filesystem::copy_file(path, damaged, std::filesystem::copy_options::overwrite_existing);
    const haddr_t at = middle_of_first_chunk(damaged, name);
    ASSERT_NE(at, HADDR_UNDEF) << name;
    flip_byte(damaged, at);
    try {
      RunFile run = RunFile::open_read_only(damaged);
      static_cast<void>(run.read_array(name));
      static_cast<void>(run.frames());
      FAIL() << name << ": a damaged chunk was read";
    } catch (const UserError& e) {
      EXPECT_NE(std::string(e.what()).find("damaged.h5' is damaged: reading it, a stored "
                                           "Fletcher32 checksum does not match its data"),
                std::string::npos)
          << e.what();
    }
  }
}

}  // namespace
}  // namespace granshock
