#include "json_file.hpp"

#include <fcntl.h>
#include <fmt/format.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>

#include "user_error.hpp"

namespace granshock {

int json_nesting_depth(std::string_view text) {
  int depth = 0, deepest = 0;
  bool in_string = false, escaped = false;
  for (char c : text) {
    if (in_string) {
      if (escaped)
        escaped = false;
      else if (c == '\\')
        escaped = true;
      else if (c == '"')
        in_string = false;
    } else if (c == '"') {
      in_string = true;
    } else if (c == '[' || c == '{') {
      deepest = std::max(deepest, ++depth);
    } else if ((c == ']' || c == '}') && depth > 0) {
      --depth;
    }
  }
  return deepest;
}

void check_json_depth(std::string_view text, const std::string& where) {
  if (json_nesting_depth(text) > kMaxJsonDepth)
    throw UserError(fmt::format("{}: JSON nested deeper than {} levels", where, kMaxJsonDepth));
}

namespace {

// The file's bytes; O_NONBLOCK so that opening a FIFO does not wait for a writer.
std::string read_regular_file(const std::filesystem::path& path) {
  const std::string name = path.string();
  const int fd = ::open(name.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0) throw UserError(fmt::format("cannot read '{}': {}", name, std::strerror(errno)));
  struct Closer {
    int fd;
    ~Closer() { ::close(fd); }
  } closer{fd};
  struct stat st {};
  if (::fstat(fd, &st) != 0)
    throw UserError(fmt::format("cannot read '{}': {}", name, std::strerror(errno)));
  if (!S_ISREG(st.st_mode)) throw UserError(fmt::format("'{}' is not a regular file", name));
  if (std::size_t(st.st_size) > kMaxJsonFileBytes)
    throw UserError(fmt::format("'{}' is longer than {} bytes", name, kMaxJsonFileBytes));
  std::string text(std::size_t(st.st_size), '\0');
  std::size_t done = 0;
  while (done < text.size()) {
    const ssize_t got = ::read(fd, text.data() + done, text.size() - done);
    if (got < 0 && errno == EINTR) continue;
    if (got < 0) throw UserError(fmt::format("cannot read '{}': {}", name, std::strerror(errno)));
    if (got == 0) break;  // the file shrank meanwhile
    done += std::size_t(got);
  }
  text.resize(done);
  return text;
}

}  // namespace

JsonFile read_json_file(const std::filesystem::path& path) {
  const std::string text = read_regular_file(path);
  check_json_depth(text, path.string());
  JsonFile file;
  try {
    file.value = nlohmann::json::parse(text);
  } catch (const nlohmann::json::exception& e) {  // parse_error, or out_of_range for 1e999
    file.value = nlohmann::json(nlohmann::json::value_t::discarded);
    file.error = e.what();
  }
  return file;
}

}  // namespace granshock
