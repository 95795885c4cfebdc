#include "cases/bow_shock/run_log.hpp"

#include <algorithm>
#include <chrono>
#include <ctime>
#include <iostream>

#include <fmt/format.h>

namespace granshock {

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
  if (!file_.is_open())
    pending_.push_back(stamped);
  else
    file_.append(stamped);
}

void RunLog::open(const std::filesystem::path& dir) {
  if (!speaks_ || file_.is_open()) return;
  file_.open(dir / "log.txt");
  for (const std::string& line : pending_) file_.append(line);
  pending_.clear();
}

}  // namespace granshock
