#include "core/allocation_failure.hpp"

namespace granshock {

namespace {

// The text between `open` and the next `close` after it, or "".
std::string between(const std::string& text, const std::string& open, const std::string& close) {
  const auto from = text.find(open);
  if (from == std::string::npos) return {};
  const auto start = from + open.size();
  const auto end = text.find(close, start);
  return end == std::string::npos ? std::string() : text.substr(start, end - start);
}

}  // namespace

std::optional<std::string> allocation_failure(const std::string& what) {
  const bool failed = what.rfind("Kokkos failed to allocate", 0) == 0 ||
                      what.rfind("Kokkos encountered an allocation failure", 0) == 0;
  if (!failed) return std::nullopt;
  const std::string label = between(what, "label \"", "\"");
  const std::string size = between(what, "Allocation of size ", " failed");
  std::string line = "not enough memory: Kokkos could not allocate";
  if (!label.empty() && label.size() <= 80) line += " '" + label + "'";
  if (!size.empty() && size.size() <= 20) line += " (" + size + ")";
  line +=
      "; make the scene smaller (fewer particles, a smaller numerics.skin, larger bins: "
      "docs/stability.md, \"Limits\")";
  for (char& c : line)
    if (c == '\n' || c == '\r') c = ' ';
  return line;
}

}  // namespace granshock
