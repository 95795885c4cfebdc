#include "cases/bow_shock/run_log.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstring>
#include <ctime>
#include <iostream>

#include <fmt/format.h>

#include "core/user_error.hpp"
#include "io/marked_directory.hpp"

namespace granshock {

RunLog::~RunLog() {
  if (fd_ >= 0) ::close(fd_);
}

std::string RunLog::now() {
  const auto t = std::chrono::system_clock::now();
  const std::time_t seconds = std::chrono::system_clock::to_time_t(t);
  const long ms = long(
      std::chrono::duration_cast<std::chrono::milliseconds>(t.time_since_epoch()).count() % 1000);
  std::tm utc{};
  ::gmtime_r(&seconds, &utc);
  char text[32];
  std::strftime(text, sizeof text, "%Y-%m-%dT%H:%M:%S", &utc);
  return fmt::format("{}.{:03d}Z", text, ms);
}

void RunLog::say(const std::string& line) {
  if (!speaks_) return;
  std::cerr << line << "\n";
  std::cerr.flush();
  record(line);
}

void RunLog::warn(const std::string& message) {
  if (!speaks_) return;
  say("granshock: warning: " + message);
  if (std::find(warnings_.begin(), warnings_.end(), message) == warnings_.end())
    warnings_.push_back(message);
}

void RunLog::record(const std::string& line) {
  if (!speaks_) return;
  const std::string stamped = now() + "  " + line + "\n";
  if (fd_ < 0)
    pending_.push_back(stamped);
  else
    write(stamped);
}

void RunLog::open(const std::filesystem::path& dir) {
  if (!speaks_ || fd_ >= 0) return;
  path_ = dir / "log.txt";
  // O_NOFOLLOW: never through a link planted under the name (the run directory's check
  // refused one already; this closes the gap since).
  fd_ = ::open(path_.c_str(), O_WRONLY | O_APPEND | O_CREAT | O_NOFOLLOW | O_CLOEXEC, 0644);
  if (fd_ < 0)
    throw UserError(fmt::format("cannot write '{}': {}", path_.string(), std::strerror(errno)));
  // Nor into a file with a second name (a hard link made since the check): appending would
  // change that file too.
  struct stat st {};
  if (::fstat(fd_, &st) == 0 && st.st_nlink > 1) {
    ::close(fd_);
    fd_ = -1;
    refuse_hard_link(path_, st.st_nlink);
  }
  for (const std::string& line : pending_) write(line);
  pending_.clear();
}

void RunLog::write(const std::string& stamped) {
  if (failed_) return;
  // One write per line: with O_APPEND a line is never split by another writer, and a run
  // killed between writes leaves whole lines.
  const ssize_t n = ::write(fd_, stamped.data(), stamped.size());
  if (n == ssize_t(stamped.size())) return;
  failed_ = true;
  std::cerr << fmt::format(
      "granshock: warning: writing '{}' failed ({}); the run goes on without its log\n",
      path_.string(), n < 0 ? std::strerror(errno) : "a short write");
}

}  // namespace granshock
