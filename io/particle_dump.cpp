#include "io/particle_dump.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <sstream>

#include "core/available_memory.hpp"
#include "core/quoted_input.hpp"
#include "core/user_error.hpp"
#include "io/regular_file.hpp"

namespace granshock {

namespace {

std::vector<std::string> split(const std::string& line) {
  std::istringstream s(line);
  std::vector<std::string> out;
  std::string token;
  while (s >> token) out.push_back(token);
  return out;
}

bool starts_with(const std::string& s, const std::string& prefix) {
  return s.compare(0, prefix.size(), prefix) == 0;
}

std::string trimmed(const std::string& s) {
  const auto b = s.find_first_not_of(" \t\r");
  if (b == std::string::npos) return "";
  return s.substr(b, s.find_last_not_of(" \t\r") - b + 1);
}

// The columns granshock reads, with the names a dump may give each (unwrapped
// coordinates are wrapped into the periodic domain when binned).
struct Column {
  const char* name;
  const char* alternative;
};
constexpr Column kColumns[] = {{"id", nullptr}, {"type", nullptr}, {"x", "xu"},
                               {"y", "yu"},     {"vx", nullptr},   {"vy", nullptr}};
constexpr int kColumnCount = 6;

// A frame's header items (TIMESTEP, TIME, UNITS, NUMBER OF ATOMS, BOX BOUNDS, ATOMS) and
// then some: a header that never reaches ITEM: ATOMS is refused before it is read to the end.
constexpr int kMaxHeaderItems = 64;

// What a frame holds per atom while it is read (DumpFrame: id, type, x, y, vx, vy), twice:
// a caller keeps a frame beside the one being read (sum_dump_frames keeps the first).
constexpr double kFrameBytesPerAtom = 2 * 6 * 8;

std::string quoted_path(const std::filesystem::path& path) {
  return quoted_input(path.string(), 1024);
}

}  // namespace

DumpFormat parse_dump_format(const std::string& name) {
  if (name == "lammps") return DumpFormat::lammps;
  if (name == "liggghts") return DumpFormat::liggghts;
  throw UserError("dump format '" + name + "' is not one of lammps, liggghts");
}

std::string to_string(DumpFormat format) {
  return format == DumpFormat::lammps ? "LAMMPS" : "LIGGGHTS";
}

DumpReader::DumpReader(const std::filesystem::path& path, DumpFormat format)
    : path_(path), format_(format) {
  const RegularFile file(path, to_string(format) + " dump");
  const int fd = ::dup(file.fd());
  if (fd >= 0) file_ = ::fdopen(fd, "r");
  if (file_ == nullptr) {
    if (fd >= 0) ::close(fd);
    throw UserError("cannot read " + to_string(format) + " dump " + quoted_path(path) + ": " +
                    std::strerror(errno));
  }
}

DumpReader::~DumpReader() {
  if (file_ != nullptr) std::fclose(file_);
}

void DumpReader::fail(const std::string& why) const {
  const std::string where =
      to_string(format_) + " dump " + quoted_path(path_) + " line " + std::to_string(line_) + ": ";
  // Whatever is wrong with the file's last line inside a frame, cut off before its
  // newline, is its cut.
  if (unterminated_ && in_frame_)
    throw TruncatedDump(where + why + " (the file's last line, cut off before its newline)");
  throw UserError(where + why);
}

bool DumpReader::read_line(std::string& line) {
  // Byte by byte up to the cap: getline() would take a whole file without a newline (a
  // sparse or NUL-padded one) into memory before the line could be judged.
  line.clear();
  int c = 0;
  errno = 0;
  while ((c = getc_unlocked(file_)) != EOF && c != '\n') {
    if (c == '\0') {
      ++line_;
      fail(
          "the line holds a NUL byte (binary data, not the text of a dump: a damaged or "
          "padded file?)");
    }
    if (line.size() == kMaxDumpLineBytes) {
      ++line_;
      fail(fmt::format("the line is longer than {} bytes (not a dump line: a damaged file?)",
                       kMaxDumpLineBytes));
    }
    line.push_back(char(c));
  }
  if (c == EOF) {
    if (std::ferror(file_))
      throw UserError("cannot read " + to_string(format_) + " dump " + quoted_path(path_) + ": " +
                      std::strerror(errno));
    if (line.empty()) return false;  // a last line without a newline still counts
  }
  unterminated_ = c == EOF;
  ++line_;
  return true;
}

void DumpReader::check_frame_memory(long atoms) const {
  // A frame is read whole before it is binned: its size is checked against the memory
  // this process may take before any of it is allocated.
  const double needed = double(atoms) * kFrameBytesPerAtom;
  const std::optional<double> available = available_memory_bytes();
  if (atoms > kMaxDumpAtoms || (available && needed > *available))
    fail(fmt::format(
        "ITEM: NUMBER OF ATOMS {}: a frame of that many atoms needs about {:.3g} GB while it is "
        "read, more than {} (a damaged count, or a dump to split into smaller frames)",
        atoms, needed / 1e9,
        available && needed > *available
            ? fmt::format("the {:.3g} GB available (MemAvailable, ulimit -v)", *available / 1e9)
            : fmt::format("granshock reads ({} atoms a frame)", kMaxDumpAtoms)));
}

void DumpReader::refuse_duplicate_ids(const DumpFrame& f) const {
  std::vector<long> ids = f.id;
  std::sort(ids.begin(), ids.end());
  const auto twice = std::adjacent_find(ids.begin(), ids.end());
  if (twice != ids.end())
    fail(
        fmt::format("the frame at {} holds atom id {} twice (each atom once a frame: "
                    "two frames written into one, or a damaged file?)",
                    f.where, *twice));
}

std::string DumpReader::expect_line(const std::string& what) {
  std::string line;
  if (!read_line(line)) {
    ++line_;
    throw TruncatedDump(to_string(format_) + " dump " + quoted_path(path_) + " line " +
                        std::to_string(line_) + ": the file ends where " + what +
                        " should follow (a truncated dump: was it still being written?)");
  }
  return line;
}

namespace {

double parse_number(const std::string& token, bool& ok) {
  const char* begin = token.c_str();
  char* end = nullptr;
  errno = 0;
  const double v = std::strtod(begin, &end);
  ok = end != begin && *end == '\0' && errno != ERANGE && std::isfinite(v);
  return v;
}

long parse_integer(const std::string& token, bool& ok) {
  const char* begin = token.c_str();
  char* end = nullptr;
  errno = 0;
  const long v = std::strtol(begin, &end, 10);
  ok = end != begin && *end == '\0' && errno != ERANGE;
  return v;
}

}  // namespace

bool DumpReader::next(DumpFrame& f) {
  std::string line;
  do {
    if (!read_line(line)) return false;
  } while (trimmed(line).empty());
  // The first line of a frame cut off: the start of "ITEM: TIMESTEP" and the end of the file.
  in_frame_ = unterminated_ && std::string("ITEM: TIMESTEP").rfind(trimmed(line), 0) == 0;
  if (trimmed(line) != "ITEM: TIMESTEP")
    fail("expected 'ITEM: TIMESTEP' at the start of a frame, found " + quoted_input(trimmed(line)));
  in_frame_ = true;
  f = DumpFrame{};
  f.where = printable_line(path_.string(), 1024) + ":" + std::to_string(line_);
  bool ok = false;
  f.timestep = parse_integer(trimmed(expect_line("the timestep")), ok);
  if (!ok) fail("the timestep is not an integer");

  long atoms = -1;
  bool have_box = false;
  std::vector<int> at(kColumnCount, -1);
  int z_at = -1, vz_at = -1;  // optional: the projection's warning (DumpFrame::has_z)
  std::size_t columns = 0;
  for (int items = 0;; ++items) {
    // A frame's header has a handful of items; thousands are not a dump.
    if (items == kMaxHeaderItems)
      fail(fmt::format("the frame at {} has more than {} header items before ITEM: ATOMS", f.where,
                       kMaxHeaderItems));
    const std::string item = trimmed(expect_line("the frame's ITEM: ATOMS"));
    if (item == "ITEM: TIME") {
      const double t = parse_number(trimmed(expect_line("the time")), ok);
      if (!ok) fail("the time is not a finite number");
      f.time = t;
    } else if (item == "ITEM: UNITS") {
      expect_line("the units");
    } else if (item == "ITEM: NUMBER OF ATOMS") {
      const std::string count = trimmed(expect_line("the number of atoms"));
      atoms = parse_integer(count, ok);
      if (!ok || atoms < 0)
        fail("ITEM: NUMBER OF ATOMS " + quoted_input(count) + " is not a whole number >= 0");
      check_frame_memory(atoms);
    } else if (starts_with(item, "ITEM: BOX BOUNDS")) {
      const std::vector<std::string> flags = split(item.substr(16));
      for (const std::string& flag : flags)
        if (flag == "xy" || flag == "xz" || flag == "yz")
          fail("the box is triclinic (BOX BOUNDS " + quoted_input(trimmed(item.substr(16))) +
               "); only orthogonal boxes are read");
      for (int k = 0; k < 3; ++k) {
        const std::vector<std::string> t = split(expect_line("the box bounds"));
        bool ok_lo = false, ok_hi = false;
        if (t.size() == 2) {
          f.box_lo[k] = parse_number(t[0], ok_lo);
          f.box_hi[k] = parse_number(t[1], ok_hi);
        }
        if (!ok_lo || !ok_hi) fail("a box bounds line is not two numbers 'lo hi'");
        if (!(f.box_lo[k] < f.box_hi[k]))
          fail(
              fmt::format("ITEM: BOX BOUNDS of the frame at {}: the {} bounds {:.17g} {:.17g} are "
                          "not 'lo hi' with lo < hi",
                          f.where, "xyz"[k], f.box_lo[k], f.box_hi[k]));
      }
      have_box = true;
    } else if (starts_with(item, "ITEM: ATOMS")) {
      const std::vector<std::string> names = split(item.substr(11));
      columns = names.size();
      for (std::size_t c = 0; c < names.size(); ++c)
        for (int k = 0; k < kColumnCount; ++k)
          if (names[c] == kColumns[k].name ||
              (kColumns[k].alternative && names[c] == kColumns[k].alternative)) {
            if (at[static_cast<std::size_t>(k)] >= 0)
              fail("ITEM: ATOMS names column " + std::string(kColumns[k].name) + " twice");
            at[static_cast<std::size_t>(k)] = static_cast<int>(c);
          }
      for (std::size_t c = 0; c < names.size(); ++c) {
        if (names[c] == "z" || names[c] == "zu") z_at = int(c);
        if (names[c] == "vz") vz_at = int(c);
      }
      std::string missing;
      for (int k = 0; k < kColumnCount; ++k)
        if (at[static_cast<std::size_t>(k)] < 0)
          missing += (missing.empty() ? "" : ", ") + std::string(kColumns[k].name);
      if (!missing.empty())
        fail("ITEM: ATOMS lacks the column(s) " + missing +
             " (granshock reads id type x y vx vy; write them with dump custom)");
      break;
    } else {
      fail("unexpected line " + quoted_input(item) + " in a frame's header");
    }
  }
  if (atoms < 0) fail("the frame has no ITEM: NUMBER OF ATOMS before ITEM: ATOMS");
  if (!have_box) fail("the frame has no ITEM: BOX BOUNDS before ITEM: ATOMS");

  const std::size_t n = static_cast<std::size_t>(atoms);
  for (auto* v : {&f.x, &f.y, &f.vx, &f.vy}) v->reserve(n);
  f.id.reserve(n);
  f.type.reserve(n);
  for (std::size_t i = 0; i < n; ++i) {
    const std::string row = expect_line("atom " + std::to_string(i + 1) + " of " +
                                        std::to_string(n) + " of the frame at " + f.where);
    const std::vector<std::string> t = split(row);
    if (t.size() != columns) {
      // A truncated frame where the line is the file's last, cut off (fail).
      fail("an atom line has " + std::to_string(t.size()) + " values, ITEM: ATOMS names " +
           std::to_string(columns) + " columns (a truncated or corrupted line?)");
    }
    auto token = [&](int k) {
      return t[static_cast<std::size_t>(at[static_cast<std::size_t>(k)])];
    };
    f.id.push_back(parse_integer(token(0), ok));
    if (!ok) fail("the atom id " + quoted_input(token(0)) + " is not an integer");
    f.type.push_back(parse_integer(token(1), ok));
    if (!ok) fail("the atom type " + quoted_input(token(1)) + " is not an integer");
    std::vector<double>* values[] = {&f.x, &f.y, &f.vx, &f.vy};
    for (int k = 2; k < kColumnCount; ++k) {
      values[k - 2]->push_back(parse_number(token(k), ok));
      if (!ok)
        fail("the " + std::string(kColumns[k].name) + " value " + quoted_input(token(k)) +
             " is not a finite number");
    }
    // z and vz are not binned: a value that does not parse only leaves the spread unknown.
    if (z_at >= 0) {
      bool z_ok = false;
      const double z = parse_number(t[std::size_t(z_at)], z_ok);
      if (z_ok) {
        f.z_min = f.has_z ? std::min(f.z_min, z) : z;
        f.z_max = f.has_z ? std::max(f.z_max, z) : z;
        f.has_z = true;
      }
    }
    if (vz_at >= 0) {
      bool vz_ok = false;
      const double vz = parse_number(t[std::size_t(vz_at)], vz_ok);
      if (vz_ok) f.vz_max_abs = std::max(f.vz_max_abs, std::abs(vz));
    }
  }
  refuse_duplicate_ids(f);
  in_frame_ = false;
  return true;
}

}  // namespace granshock
