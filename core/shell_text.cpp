#include "core/shell_text.hpp"

#include <fmt/format.h>

#include <cstring>

namespace granshock {

namespace {

bool is_control(char c) {
  const auto u = static_cast<unsigned char>(c);
  return u < 0x20 || u == 0x7f;
}

std::string hex_escape(char c) {
  return fmt::format("\\x{:02x}", static_cast<unsigned char>(c));
}

}  // namespace

bool has_control_character(const std::string& text) {
  for (char c : text)
    if (is_control(c)) return true;
  return false;
}

std::string shell_quote(const std::string& text) {
  if (!has_control_character(text)) {
    std::string out = "'";
    for (char c : text) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return out + "'";
  }
  // ANSI-C quoting (bash(1), "QUOTING"): \xHH is one byte of at most two hex digits, so a
  // digit after the escape stays a character of its own.
  std::string out = "$'";
  for (char c : text) {
    if (is_control(c))
      out += hex_escape(c);
    else if (c == '\\' || c == '\'')
      out += std::string("\\") + c;
    else
      out += c;
  }
  return out + "'";
}

std::string comment_text(const std::string& text) {
  std::string out;
  for (char c : text) {
    if (is_control(c))
      out += hex_escape(c);
    else if (c == '\\')
      out += "\\\\";
    else
      out += c;
  }
  return out;
}

bool sbatch_plain(const std::string& text) {
  for (char c : text) {
    const auto u = static_cast<unsigned char>(c);
    if (u <= 0x20 || u >= 0x7f || std::strchr("'\"\\$#%", c)) return false;
  }
  return true;
}

}  // namespace granshock
