// `granshock fields --from-dump` (docs/fields.md, "Fields from LAMMPS or LIGGGHTS dumps"):
// - a hand-computed case: a few particles at known positions and velocities give known
//   sums, densities and velocities in known bins (columns in any order, x wrapped into
//   the periodic domain, frames outside the window checked but not summed);
// - the dump path against the device: the same particles written as a dump and handed
//   to the solver's own field sampling give the same grid and profile sums;
// - the committed LAMMPS dump (tests/fields/dump) is read whole, every particle counted.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <string>

#include "analysis/bin_fields.hpp"
#include "analysis/field_physics.hpp"
#include "cases/bow_shock/sampling_plan.hpp"
#include "cases/dump/dump_sums.hpp"
#include "core/solver.hpp"
#include "core/user_error.hpp"
#include "io/dump_map.hpp"
#include "models/obstacle_shapes.hpp"
#include "scene/scene_fixtures.hpp"

using namespace granshock;
namespace fs = std::filesystem;

namespace {

const fs::path kSource = GRANSHOCK_SOURCE_DIR;

// A 12 d x 24 d channel with a cylinder of 6 d at (6 d, 15 d) and bins of 2 d: the grid's
// column 0 spans x in [1 d, 3 d) (a column is centred on the axis), column 5 wraps across
// the periodic boundary ([11 d, 12 d) and [0, 1 d)), rows are 2 d from y = 0; the profile
// has columns of 0.5 d from x = 3 d and rows of 0.5 d. The window [0, 2000 steps) is cut
// into 2 blocks of 1000 steps.
const std::string kHandMap = R"(
[dump]
dt = 1e-7
[dump.types]
1 = "steel"
2 = "aluminium"
[scene]
name = "hand"
)" + granshock::testing::kPaperMixture +
                             R"(
[contact]
restitution = 0.5
[domain]
width = "12 d"
length = "24 d"
[obstacle]
diameter = "6 d"
centre = ["6 d", "15 d"]
material = "aluminium"
[inflow]
area_fraction = 0.1
velocity = 1.0
mach = 5.9
strip = "2 d"
[time]
dt = 1e-7
production_start = 0.0
duration = 2e-4
[output]
blocks = 2
[numerics]
bin_size = "2 d"
)";

// Columns in an unusual order, with z and an extra column that are ignored.
const char* const kHandDump = R"(ITEM: TIMESTEP
0
ITEM: NUMBER OF ATOMS
6
ITEM: BOX BOUNDS pp ff pp
0 0.012
0 0.024
-0.0005 0.0005
ITEM: ATOMS vy id x type c_extra vx y z
1.0 1 0.002 1 7 0.5 0.001 0
2.0 2 0.0022 2 7 -0.5 0.0015 0
0.2 3 0.0005 1 7 0.1 0.005 0
0.4 4 0.0145 1 7 0.3 0.005 0
9.0 5 0.004 2 7 9.0 -0.0005 0
0.5 6 0.00625 2 7 0.25 0.00325 0
ITEM: TIMESTEP
1000
ITEM: NUMBER OF ATOMS
1
ITEM: BOX BOUNDS pp ff pp
0 0.012
0 0.024
-0.0005 0.0005
ITEM: ATOMS vy id x type c_extra vx y z
1.0 1 0.002 1 7 1.5 0.001 0
ITEM: TIMESTEP
5000
ITEM: NUMBER OF ATOMS
1
ITEM: BOX BOUNDS pp ff pp
0 0.012
0 0.024
-0.0005 0.0005
ITEM: ATOMS vy id x type c_extra vx y z
1.0 1 0.002 1 7 100 0.001 0
)";

fs::path write_temp(const std::string& name, const std::string& text) {
  const fs::path p = fs::temp_directory_path() /
                     ("granshock_test_from_dump_" + std::to_string(::getpid()) + "_" + name);
  std::ofstream(p) << text;
  return p;
}

double q(const BinSums& s, int block, int iy, int ix, int species,
         BinLayout::SpeciesQuantity what) {
  const BinLayout l = s.layout();
  return s.sums[static_cast<std::size_t>(l.offset(block, iy, ix, l.species_index(species, what)))];
}

double total_count(const BinSums& s) {
  const BinLayout l = s.layout();
  double n = 0;
  for (int b = 0; b < s.blocks; ++b)
    for (int iy = 0; iy < s.ny; ++iy)
      for (int ix = 0; ix < s.nx; ++ix)
        for (int a = 0; a < s.n_species; ++a)
          n += s.sums[static_cast<std::size_t>(
              l.offset(b, iy, ix, l.species_index(a, BinLayout::count)))];
  return n;
}

}  // namespace

TEST(FromDump, HandComputedParticlesGiveKnownSumsDensitiesAndVelocities) {
  const DumpMap map = parse_dump_map(kHandMap, "hand map");
  const fs::path dump = write_temp("hand.dump", kHandDump);
  const DumpSums s = sum_dump_frames(map, DumpFormat::lammps, {dump});
  fs::remove(dump);
  const BinSums& g = s.grid;
  ASSERT_EQ(g.nx, 6);
  ASSERT_EQ(g.ny, 12);
  EXPECT_NEAR(g.x0, 1e-3, 1e-15);
  EXPECT_NEAR(g.dx, 2e-3, 1e-15);
  EXPECT_NEAR(g.dy, 2e-3, 1e-15);
  EXPECT_EQ(s.frames_read, 3);
  EXPECT_EQ(s.frames_used, 2);  // timestep 5000 lies past the window
  EXPECT_EQ(g.samples, (std::vector<double>{1, 1}));
  // Block 0, bin (row 0, column 0): steel 1 (v = (0.5, 1)) and aluminium 2 (v = (-0.5, 2)).
  EXPECT_EQ(q(g, 0, 0, 0, 0, BinLayout::count), 1);
  EXPECT_EQ(q(g, 0, 0, 0, 0, BinLayout::sum_vx), 0.5);
  EXPECT_EQ(q(g, 0, 0, 0, 0, BinLayout::sum_vxvy), 0.5);
  EXPECT_EQ(q(g, 0, 0, 0, 1, BinLayout::count), 1);
  EXPECT_EQ(q(g, 0, 0, 0, 1, BinLayout::sum_vy), 2.0);
  EXPECT_EQ(q(g, 0, 0, 0, 1, BinLayout::sum_vyvy), 4.0);
  EXPECT_EQ(q(g, 0, 0, 0, 1, BinLayout::sum_vxvy), -1.0);
  // Atom 3 (x = 0.5 d, left of x0) lies in the wrapping column 5, row 2; atom 4
  // (x = 14.5 d, past the box as an unwrapped xu may be) is wrapped to 2.5 d: column 0.
  EXPECT_EQ(q(g, 0, 2, 5, 0, BinLayout::count), 1);
  EXPECT_EQ(q(g, 0, 2, 5, 0, BinLayout::sum_vx), 0.1);
  EXPECT_EQ(q(g, 0, 2, 0, 0, BinLayout::count), 1);
  EXPECT_EQ(q(g, 0, 2, 0, 0, BinLayout::sum_vx), 0.3);
  EXPECT_EQ(q(g, 0, 2, 0, 0, BinLayout::sum_vyvy), 0.4 * 0.4);
  // Atom 6 at (6.25 d, 3.25 d): grid column 2, row 1; profile column 6, row 6.
  EXPECT_EQ(q(g, 0, 1, 2, 1, BinLayout::count), 1);
  ASSERT_TRUE(s.profile);
  EXPECT_EQ(q(*s.profile, 0, 6, 6, 1, BinLayout::count), 1);
  EXPECT_EQ(q(*s.profile, 0, 6, 6, 1, BinLayout::sum_vx), 0.25);
  EXPECT_EQ(total_count(*s.profile), 1);
  // Block 1: atom 1 again, v = (1.5, 1). Atom 5 (y < 0) is nowhere.
  EXPECT_EQ(q(g, 1, 0, 0, 0, BinLayout::count), 1);
  EXPECT_EQ(q(g, 1, 0, 0, 0, BinLayout::sum_vx), 1.5);
  EXPECT_EQ(total_count(g), 6);

  // The fields of bin (0, 0) over both samples: n_a = N_a / (K A), u mass-weighted.
  const FieldPhysics phys = field_physics_from_scene(map.scene.scene);
  MaskRule every_bin;
  every_bin.min_particle_samples = 1;
  const BinFields f = compute_bin_fields(g, phys, every_bin);
  const std::size_t k = f.index(0, 0);
  const double area = 2e-3 * 2e-3, m1 = phys.mass[0], m2 = phys.mass[1];
  EXPECT_NEAR(f.species_n[0][k], 2 / (2 * area), 1e-9);
  EXPECT_NEAR(f.species_n[1][k], 1 / (2 * area), 1e-9);
  EXPECT_NEAR(f.n[k], 3 / (2 * area), 1e-9);
  EXPECT_NEAR(f.phi[k], 3 / (2 * area) * M_PI * 1e-6 / 4, 1e-12);
  EXPECT_NEAR(f.ux[k], (m1 * (0.5 + 1.5) + m2 * -0.5) / (2 * m1 + m2), 1e-12);
  EXPECT_NEAR(f.uy[k], (m1 * 2.0 + m2 * 2.0) / (2 * m1 + m2), 1e-12);
  EXPECT_NEAR(f.species_ux[0][k], 1.0, 1e-12);
  EXPECT_NEAR(f.rho[k], (2 * m1 + m2) / (2 * area), 1e-9 * m1 / area);
}

TEST(FromDump, LiggghtsBoxBoundsWithoutFlagsAreRead) {
  const DumpMap map = parse_dump_map(kHandMap, "hand map");
  std::string text = kHandDump;
  for (std::size_t at; (at = text.find("ITEM: BOX BOUNDS pp ff pp")) != std::string::npos;)
    text.replace(at, 25, "ITEM: BOX BOUNDS");
  const fs::path dump = write_temp("liggghts.dump", text);
  const DumpSums s = sum_dump_frames(map, DumpFormat::liggghts, {dump});
  fs::remove(dump);
  EXPECT_EQ(s.frames_used, 2);
  EXPECT_EQ(total_count(s.grid), 6);
}

// Random particles of the test dump's scene (apps/bench/lammps/dump_map.toml) on a jittered
// lattice, none overlapping another or the obstacle (no contacts: no virial on either
// side), written as a LAMMPS dump and handed to the solver frame by frame.
TEST(FromDump, SumsEqualTheDeviceSamplingOfTheSameParticles) {
  const DumpMap map = load_dump_map(kSource / "apps/bench/lammps/dump_map.toml");
  const Scene& scene = map.scene.scene;
  const SamplingPlan plan(scene);
  auto solver = make_solver(scene.setup, 2000);
  solver->configure_sampling(plan.layout());

  const double d = scene.d_m, width = scene.setup.box.length(0), length = scene.setup.box.length(1);
  const Obstacle& c = *scene.setup.obstacle;
  const double a = 1.5 * d;
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> jitter(0.0, a - d);
  std::normal_distribution<double> gauss(0.0, 0.3);
  std::ostringstream dump;
  dump.precision(17);
  const int frames = 8;
  for (int k = 0; k < frames; ++k) {
    HostParticles p;
    std::ostringstream atoms;
    atoms.precision(17);
    int id = 0;
    for (double y0 = 0; y0 + a <= length; y0 += a)
      for (double x0 = 0; x0 + a <= width; x0 += a) {
        const double x = x0 + 0.5 * d + jitter(rng), y = y0 + 0.5 * d + jitter(rng);
        if (std::hypot(x - c.centre[0], y - c.centre[1]) < 0.5 * obstacle_frontal_width(c) + d)
          continue;
        const int species = int(rng() % 2);
        const double vx = gauss(rng), vy = 1 + gauss(rng);
        p.add({x, y, 0}, {vx, vy, 0}, species, id);
        ++id;
        atoms << vy << " " << id << " " << x << " " << species + 1 << " " << vx << " " << y
              << " 0\n";
      }
    const long step = 500L * k;
    dump << "ITEM: TIMESTEP\n"
         << step << "\nITEM: NUMBER OF ATOMS\n"
         << id << "\nITEM: BOX BOUNDS pp ff pp\n0 " << width << "\n0 " << length
         << "\n-0.0005 0.0005\nITEM: ATOMS vy id x type vx y z\n"
         << atoms.str();
    solver->set_particles(p);
    ASSERT_EQ(solver->diagnostics().contacts, 0);
    solver->sample_fields(plan.block_of(step));
  }
  const fs::path file = write_temp("device.dump", dump.str());
  const DumpSums s = sum_dump_frames(map, DumpFormat::lammps, {file});
  fs::remove(file);
  ASSERT_EQ(s.frames_used, frames);
  EXPECT_EQ(s.grid.samples, (std::vector<double>{2, 2, 2, 2}));
  ASSERT_TRUE(s.profile);
  for (const bool profile : {false, true}) {
    const std::vector<double> device = solver->field_sums(profile);
    const std::vector<double>& from_dump = profile ? s.profile->sums : s.grid.sums;
    ASSERT_EQ(device.size(), from_dump.size());
    double worst = 0, largest = 0;
    for (std::size_t i = 0; i < device.size(); ++i) {
      worst = std::max(worst, std::abs(device[i] - from_dump[i]));
      largest = std::max(largest, std::abs(device[i]));
    }
    EXPECT_GT(largest, 0) << (profile ? "profile" : "grid") << " is empty";
    // Sums of the same terms in another order differ by round-off only.
    EXPECT_LE(worst, 1e-12 * largest) << (profile ? "profile" : "grid");
  }
}

// The committed LAMMPS dump (tests/fields/dump/README.md) with its map: every frame lies in
// the window, 4 per block, and every particle of every frame (all inside the box) is
// counted once in the grid.
TEST(FromDump, CommittedLammpsDumpIsSummedWhole) {
  const DumpMap map = load_dump_map(kSource / "apps/bench/lammps/dump_map.toml");
  const fs::path dump = kSource / "tests/fields/dump/small_bow_shock.dump";
  const DumpSums s = sum_dump_frames(map, DumpFormat::lammps, {dump});
  EXPECT_EQ(s.frames_read, 16);
  EXPECT_EQ(s.frames_used, 16);
  EXPECT_EQ(s.grid.samples, (std::vector<double>{4, 4, 4, 4}));
  // The atoms per frame, read independently of the reader: the line after each
  // "ITEM: NUMBER OF ATOMS".
  std::ifstream in(dump);
  std::string line;
  double atoms = 0;
  while (std::getline(in, line))
    if (line == "ITEM: NUMBER OF ATOMS" && std::getline(in, line)) atoms += std::stod(line);
  EXPECT_GT(atoms, 16 * 150);
  EXPECT_EQ(total_count(s.grid), atoms);
  ASSERT_EQ(s.series.particles.size(), 16u);
  EXPECT_NEAR(s.series.time.front(), 0.06, 1e-12);  // counted from [dump] flow_start = -0.06 s
}

TEST(FromDump, MapRefusesAnUnknownSpeciesAndAnUnknownKey) {
  std::string text = kHandMap;
  text.replace(text.find("2 = \"aluminium\""), 15, "2 = \"copper\"");
  EXPECT_THROW(parse_dump_map(text, "m"), UserError);
  std::string extra = kHandMap;
  extra.replace(extra.find("dt = 1e-7\n[dump.types]"), 9, "step = 1e-7");
  EXPECT_THROW(parse_dump_map(extra, "m"), UserError);
}

// ITEM: TIME (LAMMPS `dump_modify time yes`) gives a frame's time; the timesteps alone would
// put every frame past the window (the third frame's time is past it too).
TEST(FromDump, ItemTimeGivesTheFramesTime) {
  const DumpMap map = parse_dump_map(kHandMap, "hand map");
  std::string text = kHandDump;
  const std::string first = "ITEM: TIMESTEP\n0\n", second = "ITEM: TIMESTEP\n1000\n";
  text.replace(text.find(first), first.size(), "ITEM: TIMESTEP\n900000\nITEM: TIME\n0\n");
  text.replace(text.find(second), second.size(), "ITEM: TIMESTEP\n901000\nITEM: TIME\n1e-4\n");
  const std::string third = "ITEM: TIMESTEP\n5000\n";
  text.replace(text.find(third), third.size(), "ITEM: TIMESTEP\n905000\nITEM: TIME\n5e-4\n");
  const fs::path dump = write_temp("time.dump", text);
  const DumpSums s = sum_dump_frames(map, DumpFormat::lammps, {dump});
  fs::remove(dump);
  EXPECT_EQ(s.frames_used, 2);
  EXPECT_EQ(s.grid.samples, (std::vector<double>{1, 1}));
  EXPECT_EQ(total_count(s.grid), 6);
}

// ---- Hostile dumps (docs/stability.md, "Dumps"): each refused in one line that names the
// frame or item, before its memory is taken.

namespace {

// The message of summing `text` as a LAMMPS dump of the hand map, or "" when accepted.
std::string refusal(const std::string& text, const std::string& map_text = kHandMap) {
  const DumpMap map = parse_dump_map(map_text, "hand map");
  const fs::path dump = write_temp("hostile.dump", text);
  std::string message;
  try {
    sum_dump_frames(map, DumpFormat::lammps, {dump});
  } catch (const UserError& e) {
    message = e.what();
  }
  fs::remove(dump);
  return message;
}

// `text` with every `what` replaced.
std::string replaced(std::string text, const std::string& what, const std::string& with) {
  for (std::size_t at = 0; (at = text.find(what, at)) != std::string::npos; at += with.size())
    text.replace(at, what.size(), with);
  return text;
}

}  // namespace

// A valid dump followed by NUL bytes (a preallocated or damaged file) was read as a last
// line of gigabytes and its garbage ignored; a file without newlines the same.
TEST(FromDumpHostile, NulBytesAndOverlongLinesAreRefusedAtTheirLine) {
  const std::string nul = refusal(std::string(kHandDump) + std::string(1 << 20, '\0'));
  EXPECT_NE(nul.find("line 36: the line holds a NUL byte"), std::string::npos) << nul;
  const std::string line =
      refusal(std::string(kHandDump) + std::string(kMaxDumpLineBytes + 1, 'x'));
  EXPECT_NE(line.find("line 36: the line is longer than 65536 bytes"), std::string::npos) << line;
  // Exactly at the cap is a line (here not a frame's start: refused for that, quoted short).
  const std::string at_cap = refusal(std::string(kHandDump) + std::string(kMaxDumpLineBytes, 'x'));
  EXPECT_NE(at_cap.find("expected 'ITEM: TIMESTEP'"), std::string::npos) << at_cap.substr(0, 300);
  EXPECT_LT(at_cap.size(), 400u) << "the garbage line is quoted whole";
}

// NUMBER OF ATOMS past what memory holds was an internal error (vector::reserve) or "make
// the scene smaller"; it names the item now.
TEST(FromDumpHostile, CountsPastTheMemoryAreRefusedNamingTheItem) {
  for (const char* count : {"9223372036854775807", "4000000000", "1099511627777"}) {
    const std::string m = refusal(replaced(kHandDump, "ITEM: NUMBER OF ATOMS\n6\n",
                                           std::string("ITEM: NUMBER OF ATOMS\n") + count + "\n"));
    EXPECT_NE(m.find(std::string("ITEM: NUMBER OF ATOMS ") + count + ": a frame of that many"),
              std::string::npos)
        << m;
  }
  const std::string overflow = refusal(replaced(kHandDump, "ITEM: NUMBER OF ATOMS\n6\n",
                                                "ITEM: NUMBER OF ATOMS\n99999999999999999999\n"));
  EXPECT_NE(overflow.find("ITEM: NUMBER OF ATOMS '99999999999999999999' is not a whole number"),
            std::string::npos)
      << overflow;
}

// Frames at one time were two samples of one state ("steady: true"); an id twice in a
// frame was two particles.
TEST(FromDumpHostile, FramesAtOneTimeAndAnIdTwiceAreRefusedNamingTheFrame) {
  std::string same_time = kHandDump;
  same_time = replaced(same_time, "ITEM: TIMESTEP\n0\n", "ITEM: TIMESTEP\n0\nITEM: TIME\n1e-5\n");
  same_time =
      replaced(same_time, "ITEM: TIMESTEP\n1000\n", "ITEM: TIMESTEP\n1000\nITEM: TIME\n1e-5\n");
  const std::string t = refusal(same_time);
  EXPECT_NE(t.find("frames out of order: the frame at "), std::string::npos) << t;
  EXPECT_NE(t.find(":18 is at time 1.0000000000000001e-05 s, not after 1.0000000000000001e-05 s"),
            std::string::npos)
      << t;
  const std::string id = refusal(replaced(kHandDump, "2.0 2 0.0022", "2.0 1 0.0022"));
  EXPECT_NE(id.find(":1 holds atom id 1 twice"), std::string::npos) << id;
}

// An inverted box was reported as "mixed box sizes" on the next frame.
TEST(FromDumpHostile, AnInvertedBoxIsRefusedInItsOwnFrame) {
  const std::string m = refusal(replaced(kHandDump, "0 0.012\n", "0.012 0\n"));
  EXPECT_NE(m.find("ITEM: BOX BOUNDS of the frame at "), std::string::npos) << m;
  EXPECT_NE(m.find("the x bounds 0.012 0 are not 'lo hi' with lo < hi"), std::string::npos) << m;
}

// A map narrower than the dump's box folded x into its own period and reported a Mach
// number; a dump in mm binned nothing where it should. Both are refused on the first frame.
TEST(FromDumpHostile, ABoxThatIsNotTheMapsDomainIsRefused) {
  const std::string narrower =
      refusal(kHandDump, replaced(kHandMap, "width = \"12 d\"", "width = \"10 d\""));
  EXPECT_NE(narrower.find("has the box x = [0, 0.012] m, the map's scene [0, 0.01] m "
                          "(domain.width)"),
            std::string::npos)
      << narrower;
  std::string mm = kHandDump;
  for (std::size_t at; (at = mm.find("0 0.024\n")) != std::string::npos;)
    mm.replace(at, 8, "0 24\n");
  const std::string in_mm = refusal(mm);
  EXPECT_NE(in_mm.find("has the box y = [0, 24] m, the map's scene [0, 0.024] m (domain.length)"),
            std::string::npos)
      << in_mm;
  // Within round-off of the map (LAMMPS writes the bounds with 17 digits) is the map.
  EXPECT_EQ(refusal(replaced(kHandDump, "0 0.012\n", "0 0.012000000000000002\n")), "");
}

// Escape bytes of a dump line reached the terminal, and a 5 MB line made a 5 MB message.
TEST(FromDumpHostile, QuotedInputIsCutAndEscaped) {
  const std::string garbage = "\x1b]0;owned\x07\x1b[2J" + std::string(60000, 'A');
  const std::string m = refusal(replaced(kHandDump, "ITEM: TIMESTEP\n1000\n", garbage + "\n"));
  EXPECT_LT(m.size(), 400u) << m.substr(0, 400);
  for (unsigned char c : m) EXPECT_TRUE(c >= 0x20 && c < 0x7f) << int(c);
  EXPECT_NE(m.find("found '\\x1b]0;owned\\x07\\x1b[2JAAAA"), std::string::npos) << m;
  EXPECT_NE(m.find("... (60014 bytes in all)"), std::string::npos) << m;
}

// A map of bins below a particle's width took memory until bad_alloc, naming no key.
TEST(FromDumpHostile, BinsAMapCannotHoldAreRefusedNamingTheKey) {
  const std::string tiny =
      refusal(kHandDump, replaced(kHandMap, "bin_size = \"2 d\"", "bin_size = \"1e-6 d\""));
  EXPECT_NE(tiny.find("numerics.bin_size = 1e-06 d is smaller than the particle diameter"),
            std::string::npos)
      << tiny;
  // Bins of a particle's width over a domain of 1e5 d x 1e5 d: 1e10 bins a block.
  std::string huge = replaced(kHandMap, "width = \"12 d\"", "width = \"100000 d\"");
  huge = replaced(huge, "length = \"24 d\"", "length = \"100000 d\"");
  huge = replaced(huge, "bin_size = \"2 d\"", "bin_size = \"1 d\"");
  const std::string big = refusal(kHandDump, huge);
  EXPECT_NE(big.find("output.blocks = 2 with numerics.bin_size = 1 d needs"), std::string::npos)
      << big;
}

// A dump still being written ends inside its last frame: the frames before it are used, with
// a warning (it was refused whole). Inside an earlier file, or with no whole frame, it stays
// an error.
TEST(FromDumpInterop, ATruncatedLastFrameIsLeftOutWithAWarning) {
  const DumpMap map = parse_dump_map(kHandMap, "hand map");
  const std::string whole = kHandDump;
  // Cut inside the third frame's atom line, and at its ATOMS header.
  for (const std::size_t cut : {whole.size() - 20, whole.rfind("ITEM: ATOMS") + 5}) {
    const fs::path dump = write_temp("cut.dump", whole.substr(0, cut));
    const DumpSums s = sum_dump_frames(map, DumpFormat::lammps, {dump});
    EXPECT_EQ(s.frames_read, 2);
    EXPECT_EQ(s.frames_used, 2);
    ASSERT_EQ(s.warnings.size(), 1u);
    EXPECT_NE(s.warnings[0].find("its last frame is left out, the 2 frames before it are used"),
              std::string::npos)
        << s.warnings[0];
    const fs::path after = write_temp("after.dump", whole);
    EXPECT_THROW(sum_dump_frames(map, DumpFormat::lammps, {dump, after}), TruncatedDump);
    fs::remove(after);
    fs::remove(dump);
  }
  const std::string first = whole.substr(0, whole.find("ITEM: TIMESTEP\n1000"));
  const fs::path only = write_temp("only.dump", first.substr(0, first.size() - 12));
  EXPECT_THROW(sum_dump_frames(map, DumpFormat::lammps, {only}), TruncatedDump);
  fs::remove(only);
}

// A 3-D dump is binned as its x-y projection: said once, naming the z range.
TEST(FromDumpInterop, AThreeDimensionalDumpIsProjectedWithOneWarning) {
  const DumpMap map = parse_dump_map(kHandMap, "hand map");
  std::string spread = kHandDump;
  spread.replace(spread.find("1.0 1 0.002 1 7 0.5 0.001 0"), 27,
                 "1.0 1 0.002 1 7 0.5 0.001 0.0002");
  spread.replace(spread.find("2.0 2 0.0022 2 7 -0.5 0.0015 0"), 30,
                 "2.0 2 0.0022 2 7 -0.5 0.0015 -0.0001");
  const fs::path dump = write_temp("3d.dump", spread);
  const DumpSums s = sum_dump_frames(map, DumpFormat::lammps, {dump});
  fs::remove(dump);
  ASSERT_EQ(s.warnings.size(), 1u);
  EXPECT_NE(s.warnings[0].find("is 3-D (z from -0.0001 to 0.0002 m"), std::string::npos)
      << s.warnings[0];
  EXPECT_EQ(total_count(s.grid), 6) << "projected, every particle binned";
  // The committed LAMMPS dump is a layer at z = 0: no warning.
  const DumpMap lammps = load_dump_map(kSource / "apps/bench/lammps/dump_map.toml");
  EXPECT_TRUE(sum_dump_frames(lammps, DumpFormat::lammps,
                              {kSource / "tests/fields/dump/small_bow_shock.dump"})
                  .warnings.empty());
}
