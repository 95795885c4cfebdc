#include "cases/study/safe_name.hpp"

#include <cctype>

namespace granshock {

bool is_safe_name(const std::string& name) {
  if (name.empty() || name.size() > 64 || name[0] == '.' || name[0] == '-') return false;
  for (char c : name)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '.' && c != '_' && c != '-')
      return false;
  return true;
}

std::string safe_name(const std::string& text) {
  std::string out;
  bool gap = false;
  for (char c : text) {
    const bool ok = std::isalnum(static_cast<unsigned char>(c)) || c == '.' || c == '_' || c == '-';
    if (!ok) {
      gap = true;
      continue;
    }
    if (gap && !out.empty()) out += '-';
    gap = false;
    out += c;
  }
  const std::size_t start = out.find_first_not_of(".-");
  return start == std::string::npos ? std::string() : out.substr(start);
}

}  // namespace granshock
