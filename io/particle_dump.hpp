// Particle dumps of other DEM codes (docs/fields.md, "Fields from LAMMPS or LIGGGHTS
// dumps"): the text of LAMMPS `dump custom`, which LIGGGHTS writes the same way,
//   ITEM: TIMESTEP / N, [ITEM: TIME / t,] ITEM: NUMBER OF ATOMS / N,
//   ITEM: BOX BOUNDS [flags] / three lines lo hi, ITEM: ATOMS col col ... / N lines,
// frame after frame. The columns id, type, x (or xu), y (or yu), vx and vy are read in
// whatever order the ATOMS line names them; any other column is ignored. Every problem is
// one UserError naming the file and line: an unreadable or truncated file, a missing
// column, a malformed number, a triclinic box. Input quoted in a message is cut and
// escaped (core/quoted_input.hpp).
#pragma once

#include <cstdio>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "core/user_error.hpp"

namespace granshock {

enum class DumpFormat { lammps, liggghts };
DumpFormat parse_dump_format(const std::string& name);  // "lammps" | "liggghts"
std::string to_string(DumpFormat format);               // "LAMMPS" | "LIGGGHTS"

// The file ended inside a frame (a dump still being written, or cut off): the frames before
// are whole (sum_dump_frames uses them from the last file, with a warning).
class TruncatedDump : public UserError {
 public:
  using UserError::UserError;
};

struct DumpFrame {
  long timestep = 0;
  std::optional<double> time;  // ITEM: TIME (LAMMPS `dump_modify time yes`), s
  double box_lo[3] = {0, 0, 0}, box_hi[3] = {0, 0, 0};
  std::vector<long> id;
  std::vector<long> type;
  std::vector<double> x, y, vx, vy;
  // z and vz where the dump has them (3-D, or a quasi-2-D layer at one z): their spread, for
  // the warning that a 3-D dump is binned as its x-y projection.
  bool has_z = false;
  double z_min = 0, z_max = 0, vz_max_abs = 0;
  std::string where;  // "FILE:LINE" of its ITEM: TIMESTEP line, for messages

  std::size_t size() const { return id.size(); }
};

// The longest line a dump may have (ITEM: ATOMS with many columns fits many times over),
// and the most atoms a frame may hold whatever the machine's memory: past them the file is
// refused before it is read into memory (a file without newlines, a damaged count).
inline constexpr std::size_t kMaxDumpLineBytes = 64 * 1024;
inline constexpr long kMaxDumpAtoms = 1L << 40;

// Reads the frames of one dump file in order.
class DumpReader {
 public:
  // Throws UserError when the file cannot be opened or is not a regular file.
  DumpReader(const std::filesystem::path& path, DumpFormat format);
  ~DumpReader();
  DumpReader(const DumpReader&) = delete;
  DumpReader& operator=(const DumpReader&) = delete;

  // The next frame into `frame`; false at the end of the file. Throws TruncatedDump where
  // the file ends inside the frame (or its last line, without a newline, is cut short), and
  // UserError on a malformed frame: a line past kMaxDumpLineBytes or holding a NUL byte, a
  // count of atoms the memory cannot hold, an inverted box, an atom id twice.
  bool next(DumpFrame& frame);

 private:
  bool read_line(std::string& line);  // false at the end of the file
  std::string expect_line(const std::string& what);
  void check_frame_memory(long atoms) const;
  void refuse_duplicate_ids(const DumpFrame& frame) const;
  [[noreturn]] void fail(const std::string& why) const;

  std::filesystem::path path_;
  DumpFormat format_;
  std::FILE* file_ = nullptr;
  long line_ = 0;
  bool unterminated_ = false;  // the line read last ended at the end of the file, not "\n"
  bool in_frame_ = false;      // between a frame's ITEM: TIMESTEP and its last atom
};

}  // namespace granshock
