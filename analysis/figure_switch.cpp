#include "analysis/figure_switch.hpp"

#include <algorithm>
#include <cctype>
#include <cstdlib>

namespace granshock {

namespace {

std::string environment_value() {
  const char* value = std::getenv("GRANSHOCK_FIGURES");
  return value == nullptr ? std::string() : std::string(value);
}

bool means_off(std::string value) {
  std::transform(value.begin(), value.end(), value.begin(),
                 [](unsigned char c) { return char(std::tolower(c)); });
  return value == "0" || value == "off" || value == "no" || value == "false";
}

// One shell word: as it is when it holds only characters the shell takes literally, else
// in single quotes ($'...' with \xHH escapes when it holds a control character, so that
// the note stays on one line).
std::string shell_word(const std::string& word) {
  const auto plain = [](unsigned char c) {
    return std::isalnum(c) || std::string("_./:=+,@%-").find(char(c)) != std::string::npos;
  };
  if (!word.empty() && std::all_of(word.begin(), word.end(), plain)) return word;
  const bool control =
      std::any_of(word.begin(), word.end(), [](unsigned char c) { return c < 0x20 || c == 0x7f; });
  std::string out = control ? "$'" : "'";
  for (const unsigned char c : word) {
    if (control && (c < 0x20 || c == 0x7f || c == '\\' || c == '\'')) {
      static const char hex[] = "0123456789abcdef";
      out += std::string("\\x") + hex[c >> 4] + hex[c & 15];
    } else if (c == '\'') {
      out += "'\\''";
    } else {
      out += char(c);
    }
  }
  return out + "'";
}

}  // namespace

bool figures_by_default() {
  return !means_off(environment_value());
}

std::string figures_skipped_note(const std::vector<std::string>& redraw) {
  const bool by_environment = !figures_by_default();
  std::string command = by_environment ? "GRANSHOCK_FIGURES=1" : "";
  for (const std::string& word : redraw) command += (command.empty() ? "" : " ") + shell_word(word);
  return "granshock: figures not drawn (" +
         (by_environment ? "GRANSHOCK_FIGURES=" + environment_value()
                         : std::string("--no-figures")) +
         "); draw them later with: " + command;
}

}  // namespace granshock
