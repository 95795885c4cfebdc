// Fuzzing the scene checks of `granshock run --dry-run` (docs/scene_format.md): mutated copies
// of the shipped scenes (deleted, duplicated and swapped lines, truncations, random bytes,
// extreme values) must each be accepted or refused with one UserError, never end in
// another exception, a crash or a hang, and never write a file. The seed is fixed, so a
// failure names a mutation that can be replayed; a time bound keeps the test short.
#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>
#include <fstream>
#include <random>
#include <sstream>

#include "cases/bow_shock/run_checks.hpp"
#include "cases/bow_shock/run_command.hpp"
#include "core/user_error.hpp"
#include "io/scene_file.hpp"
#include "scene_fixtures.hpp"

using namespace granshock;
using granshock::testing::small_scene;
using granshock::testing::TempDir;
namespace fs = std::filesystem;

namespace {

std::vector<std::string> shipped_scenes() {
  std::vector<std::string> texts;
  const fs::path root = fs::path(GRANSHOCK_SOURCE_DIR) / "scenes";
  for (const auto& entry : fs::recursive_directory_iterator(root)) {
    if (entry.path().extension() != ".toml") continue;
    std::ifstream in(entry.path());
    texts.emplace_back(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  }
  texts.push_back(small_scene(true));
  return texts;
}

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

std::string join(const std::vector<std::string>& lines) {
  std::string out;
  for (const auto& l : lines) out += l + "\n";
  return out;
}

// Values that have broken parsers: extremes, wrong types, lengths of every kind.
const std::vector<std::string> kNasty = {"0",
                                         "-1",
                                         "1e308",
                                         "-1e308",
                                         "1e-308",
                                         "nan",
                                         "inf",
                                         "-inf",
                                         "9223372036854775807",
                                         "-9223372036854775808",
                                         "99999999999999999999",
                                         "\"\"",
                                         "\"../../x\"",
                                         "\"/tmp/x\"",
                                         "true",
                                         "[]",
                                         "[1, 2, 3]",
                                         "[\"1 d\", \"1e300 d\"]",
                                         "{ a = 1 }",
                                         "\"1e9 d\"",
                                         "\"-5 d\"",
                                         "\"nan d\"",
                                         "\"0 d\"",
                                         "\"1 m\"",
                                         "\"1e-9 d\"",
                                         "1000000000",
                                         "2",
                                         "0.999999",
                                         "1e-30",
                                         "\"single\"",
                                         "\"paper_sum\"",
                                         "\"\\u0000\""};

class Mutator {
 public:
  explicit Mutator(std::uint64_t seed) : rng_(seed) {}

  std::string mutate(const std::string& text) {
    std::string out = text;
    const int rounds = 1 + int(pick(3));
    for (int r = 0; r < rounds; ++r) out = once(out);
    return out;
  }

 private:
  std::size_t pick(std::size_t n) { return n == 0 ? 0 : std::size_t(rng_() % n); }

  std::string once(const std::string& text) {
    std::vector<std::string> lines = lines_of(text);
    if (lines.empty() || text.empty()) return text + kNasty[pick(kNasty.size())];
    const std::size_t a = pick(lines.size()), b = pick(lines.size());
    switch (pick(9)) {
      case 0:  // delete a line
        lines.erase(lines.begin() + long(a));
        return join(lines);
      case 1:  // duplicate a line
        lines.insert(lines.begin() + long(a), lines[a]);
        return join(lines);
      case 2:  // swap two lines
        std::swap(lines[a], lines[b]);
        return join(lines);
      case 3:  // truncate
        return text.substr(0, pick(text.size()));
      case 4: {  // an extreme value for a key
        const auto eq = lines[a].find('=');
        if (eq == std::string::npos) return join(lines);
        lines[a] = lines[a].substr(0, eq + 1) + " " + kNasty[pick(kNasty.size())];
        return join(lines);
      }
      case 5: {  // random bytes
        std::string out = text;
        const std::size_t at = pick(out.size());
        for (std::size_t k = 0, n = 1 + pick(8); k < n; ++k)
          out.insert(out.begin() + long(at), char(pick(256)));
        return out;
      }
      case 6: {  // swap the values of two keys
        const auto ea = lines[a].find('='), eb = lines[b].find('=');
        if (ea == std::string::npos || eb == std::string::npos) return join(lines);
        const std::string va = lines[a].substr(ea + 1), vb = lines[b].substr(eb + 1);
        lines[a] = lines[a].substr(0, ea + 1) + vb;
        lines[b] = lines[b].substr(0, eb + 1) + va;
        return join(lines);
      }
      case 7: {  // give a line another line's key
        const auto ea = lines[a].find('='), eb = lines[b].find('=');
        if (ea == std::string::npos || eb == std::string::npos) return join(lines);
        lines[a] = lines[b].substr(0, eb) + lines[a].substr(ea);
        return join(lines);
      }
      default: {  // flip one byte
        std::string out = text;
        out[pick(out.size())] ^= char(1 << pick(8));
        return out;
      }
    }
  }

  std::mt19937_64 rng_;
};

struct Outcomes {
  long accepted = 0, refused = 0;
};

}  // namespace

TEST(SceneFuzz, MutatedScenesAreAcceptedOrRefusedCleanlyAndWriteNothing) {
  constexpr long kMutations = 4000;
  constexpr double kSeconds = 25;
  const std::vector<std::string> scenes = shipped_scenes();
  ASSERT_GE(scenes.size(), 11u) << "the default scene, the nine paper scenes and a test scene";
  TempDir tmp;
  const fs::path scene_file = tmp.path() / "scene.toml";
  const fs::path out = tmp.path() / "out";
  Mutator mutator(20261123);
  Outcomes n;
  const auto start = std::chrono::steady_clock::now();
  long k = 0;
  for (; k < kMutations; ++k) {
    if (std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() > kSeconds)
      break;
    const std::string text = mutator.mutate(scenes[std::size_t(k) % scenes.size()]);
    std::ofstream(scene_file, std::ios::binary | std::ios::trunc) << text;
    RunOptions o;
    o.scene_file = scene_file;
    o.out_dir = out;
    try {
      check_run(o);
      ++n.accepted;
    } catch (const UserError& e) {
      ++n.refused;
      ASSERT_EQ(std::string(e.what()).find('\n'), std::string::npos)
          << "mutation " << k << ": a refusal of more than one line: " << e.what();
      ASSERT_LT(std::string(e.what()).size(), 1000u) << "mutation " << k;
    } catch (const std::exception& e) {
      FAIL() << "mutation " << k << " (seed 20261123) ended in " << typeid(e).name() << ": "
             << e.what() << "\n--- scene ---\n"
             << text.substr(0, 2000);
    }
    ASSERT_FALSE(fs::exists(out)) << "mutation " << k << " created the output directory";
  }
  std::printf("[ measured ] %ld mutated scenes: %ld accepted, %ld refused with one line\n", k,
              n.accepted, n.refused);
  EXPECT_GE(k, 500) << "too few mutations in the time bound to mean anything";
  EXPECT_GT(n.refused, 0);
  EXPECT_GT(n.accepted, 0) << "mutations that change nothing of substance must pass";
  long files = 0;
  for ([[maybe_unused]] const auto& e : fs::directory_iterator(tmp.path())) ++files;
  EXPECT_EQ(files, 1) << "only the fuzzer's own scene file may exist";
}

// The same through the program: `granshock run --dry-run` on mutated files exits 0 with
// the resolved scene on stdout, or 2 with one line on stderr, and writes nothing.
TEST(SceneFuzz, DryRunOfTheProgramWritesNothingAndAnswersInOneLine) {
  const std::vector<std::string> scenes = shipped_scenes();
  TempDir work, logs;
  Mutator mutator(7);
  int codes[256] = {};
  for (int k = 0; k < 40; ++k) {
    const std::string text =
        k < 2 ? scenes[0] : mutator.mutate(scenes[std::size_t(k) % scenes.size()]);
    std::ofstream(logs.path() / "scene.toml", std::ios::binary | std::ios::trunc) << text;
    const std::string cmd = "cd '" + work.path().string() + "' && '" GRANSHOCK_PROGRAM "' run '" +
                            (logs.path() / "scene.toml").string() + "' --dry-run >'" +
                            (logs.path() / "out.txt").string() + "' 2>'" +
                            (logs.path() / "err.txt").string() + "'";
    const int status = std::system(cmd.c_str());
    ASSERT_TRUE(WIFEXITED(status)) << "mutation " << k << " was killed by a signal";
    const int code = WEXITSTATUS(status);
    ++codes[code];
    std::ifstream err(logs.path() / "err.txt"), outf(logs.path() / "out.txt");
    std::vector<std::string> err_lines;
    for (std::string line; std::getline(err, line);)
      if (line.rfind("granshock: warning:", 0) != 0 && line.rfind("Kokkos::", 0) != 0 &&
          line.rfind("  ", 0) != 0)
        err_lines.push_back(line);
    const std::string out_text((std::istreambuf_iterator<char>(outf)), {});
    if (code == 0) {
      EXPECT_NE(out_text.find("[inflow]"), std::string::npos) << "mutation " << k;
      EXPECT_TRUE(err_lines.empty()) << "mutation " << k << ": " << err_lines[0];
    } else {
      EXPECT_EQ(code, 2) << "mutation " << k << ": " << (err_lines.empty() ? "" : err_lines[0]);
      EXPECT_EQ(err_lines.size(), 1u) << "mutation " << k;
      EXPECT_TRUE(out_text.empty()) << "mutation " << k;
    }
    ASSERT_TRUE(fs::is_empty(work.path())) << "mutation " << k << " wrote into the directory";
  }
  std::printf("[ measured ] 40 dry runs: %d exit 0, %d exit 2\n", codes[0], codes[2]);
  EXPECT_GE(codes[0], 2);
}

namespace {

// The --set path of a documented key in small_scene(), with the overrides it needs
// (materials.NAME needs all three keys), and the line of small_scene() it replaces.
struct ConcreteKey {
  std::string path;
  std::vector<std::string> with;
  std::string drop;
};

ConcreteKey concrete(const std::string& documented) {
  const std::string material = "materials.NAME.";
  if (documented.rfind(material, 0) == 0) {
    const std::string name = documented.substr(material.size());
    std::vector<std::string> with;
    for (const char* k : {"youngs_modulus=1e9", "poisson_ratio=0.2", "density=2500.0"})
      if (std::string(k).rfind(name + "=", 0) != 0)
        with.push_back("materials.glass." + std::string(k));
    return {"materials.glass." + name, with, ""};
  }
  if (documented.rfind("[[species]] ", 0) == 0)
    return {"species.0." + documented.substr(12), {}, ""};
  const std::string pairs = "contact.pairs.\"a-b\".";
  if (documented.rfind(pairs, 0) == 0)
    return {"contact.pairs.steel-aluminium." + documented.substr(pairs.size()), {}, ""};
  if (documented == "inflow.mach") return {documented, {}, "sigma = 0.1\n"};
  return {documented, {}, ""};
}

}  // namespace

// Every number of the schema, vectors included, must be finite: obstacle.centre = [nan,
// nan] passed validation and the run blew up later, blaming time.dt. A value far outside
// the physical range (1e-320, 1e308, -1) is refused naming its key, or accepted by every
// check the run makes before it starts.
TEST(SceneFuzz, EveryNumberIsFiniteAndOutOfRangeValuesNameTheirKey) {
  long cases = 0;
  for (const SceneKey& key : scene_keys()) {
    const bool vector = key.type == "[length, length]";
    if (key.type.rfind("number", 0) != 0 && key.type != "length" && !vector) continue;
    const ConcreteKey k = concrete(key.name);
    std::string text = small_scene();
    if (!k.drop.empty()) text.erase(text.find(k.drop), k.drop.size());
    const std::string named = k.path + (vector ? "[0]" : "");
    for (const std::string value : {"nan", "inf", "-inf", "1e-320", "1e308", "-1"}) {
      std::vector<std::string> sets = k.with;
      sets.push_back(k.path + "=" + (vector ? "[" + value + ", \"35 d\"]" : value));
      std::string refusal;
      try {
        Scene s = parse_scene(text, sets).scene;
        check_scene_before_run(s, false);
      } catch (const UserError& e) {
        refusal = e.what();
      }
      ++cases;
      const bool finite = value != "nan" && value != "inf" && value != "-inf";
      if (!finite) {
        EXPECT_NE(refusal.find("scene key '" + named + "' = "), std::string::npos)
            << named << " = " << value << ": " << (refusal.empty() ? "accepted" : refusal);
      } else if (!refusal.empty()) {
        EXPECT_NE(refusal.find(k.path.substr(k.path.rfind('.') + 1)), std::string::npos)
            << named << " = " << value << " is refused naming another key: " << refusal;
      }
    }
  }
  std::printf("[ measured ] %ld values of the scene's numeric keys\n", cases);
  EXPECT_GE(cases, 150);  // 6 values of each of some 30 keys
}
