#include "io/particle_dump.hpp"

#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <sstream>

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
    throw UserError("cannot read " + to_string(format) + " dump '" + path.string() +
                    "': " + std::strerror(errno));
  }
}

DumpReader::~DumpReader() {
  if (file_ != nullptr) std::fclose(file_);
}

void DumpReader::fail(const std::string& why) const {
  throw UserError(to_string(format_) + " dump '" + path_.string() + "' line " +
                  std::to_string(line_) + ": " + why);
}

bool DumpReader::read_line(std::string& line) {
  char* buffer = nullptr;
  std::size_t capacity = 0;
  errno = 0;
  const ssize_t n = ::getline(&buffer, &capacity, file_);
  if (n < 0) {
    const int error = errno;
    std::free(buffer);
    if (std::ferror(file_))
      throw UserError("cannot read " + to_string(format_) + " dump '" + path_.string() +
                      "': " + std::strerror(error));
    return false;
  }
  line.assign(buffer, static_cast<std::size_t>(n));
  std::free(buffer);
  if (!line.empty() && line.back() == '\n') line.pop_back();
  ++line_;
  return true;
}

std::string DumpReader::expect_line(const std::string& what) {
  std::string line;
  if (!read_line(line)) {
    ++line_;
    fail("the file ends where " + what +
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
  if (trimmed(line) != "ITEM: TIMESTEP")
    fail("expected 'ITEM: TIMESTEP' at the start of a frame, found '" + trimmed(line) + "'");
  f = DumpFrame{};
  f.where = path_.string() + ":" + std::to_string(line_);
  bool ok = false;
  f.timestep = parse_integer(trimmed(expect_line("the timestep")), ok);
  if (!ok) fail("the timestep is not an integer");

  long atoms = -1;
  bool have_box = false;
  std::vector<int> at(kColumnCount, -1);
  std::size_t columns = 0;
  for (;;) {
    const std::string item = trimmed(expect_line("the frame's ITEM: ATOMS"));
    if (item == "ITEM: TIME") {
      const double t = parse_number(trimmed(expect_line("the time")), ok);
      if (!ok) fail("the time is not a finite number");
      f.time = t;
    } else if (item == "ITEM: UNITS") {
      expect_line("the units");
    } else if (item == "ITEM: NUMBER OF ATOMS") {
      atoms = parse_integer(trimmed(expect_line("the number of atoms")), ok);
      if (!ok || atoms < 0) fail("the number of atoms is not a whole number >= 0");
    } else if (starts_with(item, "ITEM: BOX BOUNDS")) {
      const std::vector<std::string> flags = split(item.substr(16));
      for (const std::string& flag : flags)
        if (flag == "xy" || flag == "xz" || flag == "yz")
          fail("the box is triclinic (BOX BOUNDS " + trimmed(item.substr(16)) +
               "); only orthogonal boxes are read");
      for (int k = 0; k < 3; ++k) {
        const std::vector<std::string> t = split(expect_line("the box bounds"));
        bool ok_lo = false, ok_hi = false;
        if (t.size() == 2) {
          f.box_lo[k] = parse_number(t[0], ok_lo);
          f.box_hi[k] = parse_number(t[1], ok_hi);
        }
        if (!ok_lo || !ok_hi) fail("a box bounds line is not two numbers 'lo hi'");
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
      std::string missing;
      for (int k = 0; k < kColumnCount; ++k)
        if (at[static_cast<std::size_t>(k)] < 0)
          missing += (missing.empty() ? "" : ", ") + std::string(kColumns[k].name);
      if (!missing.empty())
        fail("ITEM: ATOMS lacks the column(s) " + missing +
             " (granshock reads id type x y vx vy; write them with dump custom)");
      break;
    } else {
      fail("unexpected line '" + item + "' in a frame's header");
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
    if (t.size() != columns)
      fail("an atom line has " + std::to_string(t.size()) + " values, ITEM: ATOMS names " +
           std::to_string(columns) + " columns (a truncated or corrupted line?)");
    auto token = [&](int k) {
      return t[static_cast<std::size_t>(at[static_cast<std::size_t>(k)])];
    };
    f.id.push_back(parse_integer(token(0), ok));
    if (!ok) fail("the atom id '" + token(0) + "' is not an integer");
    f.type.push_back(parse_integer(token(1), ok));
    if (!ok) fail("the atom type '" + token(1) + "' is not an integer");
    std::vector<double>* values[] = {&f.x, &f.y, &f.vx, &f.vy};
    for (int k = 2; k < kColumnCount; ++k) {
      values[k - 2]->push_back(parse_number(token(k), ok));
      if (!ok)
        fail("the " + std::string(kColumns[k].name) + " value '" + token(k) +
             "' is not a finite number");
    }
  }
  return true;
}

}  // namespace granshock
