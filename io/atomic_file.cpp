#include "atomic_file.hpp"

#include <cstdio>
#include <fstream>
#include <system_error>

#include "user_error.hpp"

namespace granshock {

void write_file_atomically(const std::filesystem::path& path, const std::string& contents) {
  const std::filesystem::path tmp = path.string() + ".tmp";
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    if (!out) throw UserError("cannot write '" + path.string() + "': directory not writable");
    out << contents;
    out.flush();
    if (!out) {
      std::error_code ignored;
      std::filesystem::remove(tmp, ignored);
      throw UserError("writing '" + path.string() + "' failed (disk full?)");
    }
  }
  std::error_code ec;
  std::filesystem::rename(tmp, path, ec);
  if (ec) {
    std::filesystem::remove(tmp, ec);
    throw UserError("cannot replace '" + path.string() + "': " + ec.message());
  }
}

}  // namespace granshock
