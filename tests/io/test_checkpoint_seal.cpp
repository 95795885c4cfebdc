// The checksum of checkpoint.h5 (io/checkpoint_seal.hpp): the hash itself, and that a
// damaged, truncated, old-format or foreign file is refused with one clear line before
// HDF5 reads any of it.
#include <gtest/gtest.h>
#include <hdf5.h>

#include <random>
#include <string>

#include "core/user_error.hpp"
#include "io/checkpoint_bytes.hpp"
#include "io/checkpoint_file.hpp"
#include "io/checkpoint_seal.hpp"
#include "io/file_hash.hpp"
#include "io/io_test_support.hpp"

namespace granshock {
namespace {

using test::TempDir;

// A small valid state: n particles in a row, each listing its right-hand neighbour.
SolverState small_state(int n) {
  SolverState s;
  s.step = 40;
  s.next_id = n;
  s.neighbour_offsets.push_back(0);
  for (int i = 0; i < n; ++i) {
    for (double v : {0.001 * i, 0.002}) s.position.push_back(v);
    for (double v : {0.0, 1.0}) s.velocity.push_back(v);
    for (double v : {0.0, 0.0}) s.force.push_back(v);
    s.species.push_back(i % 2);
    s.id.push_back(i);
    if (i + 1 < n) s.neighbours.push_back(i + 1);
    s.neighbour_offsets.push_back(static_cast<int>(s.neighbours.size()));
  }
  s.reference_position = s.position;
  s.list_builds = 3;
  return s;
}

std::string refusal(const std::filesystem::path& file) {
  CheckpointExtras extras;
  try {
    read_checkpoint(file, extras);
  } catch (const UserError& e) {
    return e.what();
  }
  return "";
}

TEST(FileHash, AnySplitOfTheInputGivesTheSameDigest) {
  std::mt19937_64 rng(5);
  std::string data(1000, '\0');
  for (char& c : data) c = static_cast<char>(rng());
  const std::uint64_t whole = hash_bytes(data.data(), data.size());
  for (std::size_t a = 0; a <= 70; ++a) {
    for (std::size_t b = a; b <= data.size(); b += 37) {
      FileHash64 h;
      h.update(data.data(), a);
      h.update(data.data() + a, b - a);
      h.update(data.data() + b, data.size() - b);
      ASSERT_EQ(h.digest(), whole) << a << " " << b;
    }
  }
}

TEST(FileHash, EveryBitAndTheLengthMatter) {
  std::string data(333, 'x');
  const std::uint64_t base = hash_bytes(data.data(), data.size());
  for (std::size_t bit = 0; bit < 8 * data.size(); ++bit) {
    std::string flipped = data;
    flipped[bit / 8] = static_cast<char>(flipped[bit / 8] ^ (1 << (bit % 8)));
    ASSERT_NE(hash_bytes(flipped.data(), flipped.size()), base) << "bit " << bit;
  }
  // Zero padding of the last word is told apart from real zero bytes by the length.
  const std::string a("abc", 3), b("abc\0", 4);
  EXPECT_NE(hash_bytes(a.data(), a.size()), hash_bytes(b.data(), b.size()));
  EXPECT_NE(hash_bytes(nullptr, 0), hash_bytes(b.data() + 3, 1));
}

// The hash is part of the file format: a change would make every checkpoint "damaged".
TEST(FileHash, KnownValuesStayFixed) {
  const std::string text = "granshock checkpoint";
  EXPECT_EQ(hash_bytes(nullptr, 0), 0x2684ee2f46d8b5ecULL);
  EXPECT_EQ(hash_bytes(text.data(), text.size()), 0x3c4ffd988b8fa41dULL);
}

TEST(CheckpointSeal, HeaderIsTextInTheUserBlockAndHdf5StillReadsTheFile) {
  TempDir dir;
  const auto path = dir / "checkpoint.h5";
  write_checkpoint(path, small_state(4), CheckpointExtras{});
  const std::string bytes = test::read_bytes(path);
  ASSERT_GT(bytes.size(), seal::kUserBlockBytes);
  const std::string expected = "granshock checkpoint\nformat_version " +
                               std::to_string(kCheckpointFormat) + "\nhashed_bytes " +
                               std::to_string(bytes.size() - seal::kUserBlockBytes) + "\nhash ";
  EXPECT_EQ(bytes.compare(0, expected.size(), expected), 0) << bytes.substr(0, 120);
  EXPECT_EQ(bytes.compare(seal::kUserBlockBytes, 4, "\x89HDF"), 0);
  // Any HDF5 reader (here the plain C API) opens it: HDF5 skips the user block itself.
  EXPECT_EQ(test::read_array<int>(path, "/state/id").values, (std::vector<int>{0, 1, 2, 3}));
}

// Exhaustive: one flipped bit at every offset of a real checkpoint file.
TEST(CheckpointSeal, EveryFlippedByteIsRefusedAsDamage) {
  TempDir dir;
  const auto path = dir / "checkpoint.h5";
  write_checkpoint(path, small_state(5), CheckpointExtras{});
  const std::string bytes = test::read_bytes(path);
  for (std::size_t at = 0; at < bytes.size(); ++at) {
    test::put_byte(path, at, static_cast<char>(bytes[at] ^ (1 << (at % 8))));
    const std::string message = refusal(path);
    ASSERT_NE(message.find("is damaged"), std::string::npos) << "byte " << at << ": " << message;
    test::put_byte(path, at, bytes[at]);
  }
  EXPECT_EQ(refusal(path), "");  // restored: accepted again
}

TEST(CheckpointSeal, TruncatedOrExtendedFilesAreRefused) {
  TempDir dir;
  const auto path = dir / "checkpoint.h5";
  write_checkpoint(path, small_state(5), CheckpointExtras{});
  const std::string bytes = test::read_bytes(path);
  for (const std::string& changed :
       {bytes.substr(0, bytes.size() - 1), bytes + std::string(1, '\0'), bytes.substr(0, 600),
        bytes.substr(0, 300)}) {
    test::write_bytes(path, changed);
    const std::string message = refusal(path);
    EXPECT_NE(message.find("is damaged"), std::string::npos)
        << changed.size() << " bytes: " << message;
    EXPECT_NE(message.find(path.string()), std::string::npos) << message;
  }
  test::write_bytes(path, "");
  EXPECT_NE(refusal(path).find("is empty"), std::string::npos) << refusal(path);
  test::write_bytes(path, bytes.substr(0, bytes.size() - 8));
  EXPECT_NE(refusal(path).find("truncated or extended"), std::string::npos) << refusal(path);
  test::write_bytes(path, bytes);
  EXPECT_EQ(refusal(path), "");
}

// A checkpoint of format version 1 (HDF5 from byte 0, no user block) gets a message
// naming the format, without HDF5 being asked to read it.
TEST(CheckpointSeal, OldLayoutWithoutHeaderNamesTheFormatVersion) {
  TempDir dir;
  const auto path = dir / "checkpoint.h5";
  {
    const hid_t f = H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
    ASSERT_GE(f, 0);
    const hid_t space = H5Screate(H5S_SCALAR);
    const hid_t attr =
        H5Acreate2(f, "granshock_format_version", H5T_STD_I32LE, space, H5P_DEFAULT, H5P_DEFAULT);
    const int one = 1;
    H5Awrite(attr, H5T_NATIVE_INT, &one);
    H5Aclose(attr);
    H5Sclose(space);
    H5Fclose(f);
  }
  const std::string message = refusal(path);
  EXPECT_NE(message.find("format version 1"), std::string::npos) << message;
  EXPECT_NE(message.find("rerun with --overwrite"), std::string::npos) << message;
  EXPECT_EQ(message.find('\n'), std::string::npos) << message;
}

TEST(CheckpointSeal, NewerFormatVersionIsNamedNotCalledDamage) {
  TempDir dir;
  const auto path = dir / "checkpoint.h5";
  write_checkpoint(path, small_state(3), CheckpointExtras{});
  std::string bytes = test::read_bytes(path);
  // A future format with a valid header of its own (the header hashes itself).
  const int future = kCheckpointFormat + 1;
  std::string text =
      "granshock checkpoint\nformat_version " + std::to_string(future) + "\nsomething new\n";
  text += "header_hash " + [&] {
    char hex[17];
    std::snprintf(hex, sizeof hex, "%016llx",
                  static_cast<unsigned long long>(hash_bytes(text.data(), text.size())));
    return std::string(hex);
  }() + "\n";
  text.resize(seal::kUserBlockBytes, '\0');
  bytes.replace(0, seal::kUserBlockBytes, text);
  test::write_bytes(path, bytes);
  const std::string message = refusal(path);
  EXPECT_NE(message.find("has format version " + std::to_string(future)), std::string::npos)
      << message;
  EXPECT_NE(message.find("reads format versions 3 to 4"), std::string::npos) << message;
  EXPECT_EQ(message.find("damaged"), std::string::npos) << message;
}

TEST(CheckpointSeal, ForeignFilesAreNotCheckpoints) {
  TempDir dir;
  test::write_bytes(dir / "a.h5", std::string(2000, 'a'));
  EXPECT_NE(refusal(dir / "a.h5").find("not a granshock checkpoint"), std::string::npos);
  test::write_bytes(dir / "short.h5", "granshock");
  EXPECT_NE(refusal(dir / "short.h5").find("not a granshock checkpoint"), std::string::npos);
}

}  // namespace
}  // namespace granshock
