#include "io/shortest_floats.hpp"

#include <charconv>
#include <cstdlib>
#include <regex>
#include <vector>

namespace granshock {

std::string shortest_float(double value) {
  char text[64];
  const std::to_chars_result r = std::to_chars(text, text + sizeof text, value);
  std::string out(text, r.ptr);
  // 200 is a TOML integer; a float needs a fraction or an exponent.
  if (out.find_first_of(".eEn") == std::string::npos) out += ".0";
  return out;
}

namespace {

bool is_float(const std::string& token) {
  static const std::regex number(R"([+-]?[0-9]+(\.[0-9]+)?([eE][+-]?[0-9]+)?)");
  return token.find_first_of(".eE") != std::string::npos && std::regex_match(token, number);
}

bool token_char(char c) {
  return (c >= '0' && c <= '9') || (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '.' ||
         c == '+' || c == '-' || c == '_' || c == ':';
}

}  // namespace

std::string with_shortest_floats(const std::string& toml) {
  std::string out;
  out.reserve(toml.size());
  std::vector<char> open;  // '[' (an array) or '{' (an inline table) around a value
  bool in_value = false;   // after '=' (or in an array): numbers here are values
  bool header = false;     // a [table] or [[array]] header line
  std::size_t k = 0;
  while (k < toml.size()) {
    const char c = toml[k];
    if (c == '"' || c == '\'') {  // a string, copied as it is
      const bool triple = toml.compare(k, 3, std::string(3, c)) == 0;
      const std::string quote = triple ? std::string(3, c) : std::string(1, c);
      std::size_t end = k + quote.size();
      while (end < toml.size() && toml.compare(end, quote.size(), quote) != 0) {
        if (c == '"' && toml[end] == '\\') ++end;  // an escape in a basic string
        ++end;
      }
      end = std::min(toml.size(), end + quote.size());
      out.append(toml, k, end - k);
      k = end;
      continue;
    }
    if (c == '#') {  // a comment, to the end of the line
      const std::size_t end = std::min(toml.size(), toml.find('\n', k));
      out.append(toml, k, end - k);
      k = end;
      continue;
    }
    if (token_char(c)) {
      std::size_t end = k;
      while (end < toml.size() && token_char(toml[end])) ++end;
      const std::string token = toml.substr(k, end - k);
      out += in_value && !header && is_float(token)
                 ? shortest_float(std::strtod(token.c_str(), nullptr))
                 : token;
      k = end;
      continue;
    }
    if (c == '=') {
      in_value = true;
    } else if (c == '[' && !in_value && open.empty()) {
      header = true;
    } else if ((c == '[' || c == '{') && in_value) {
      open.push_back(c);
      in_value = c == '[';  // an inline table starts with a key
    } else if ((c == ']' || c == '}') && !open.empty() && !header) {
      open.pop_back();
      in_value = true;
    } else if (c == ',' && !open.empty() && open.back() == '{') {
      in_value = false;  // the next key
    } else if (c == '\n') {
      if (open.empty()) in_value = header = false;
    }
    out += c;
    ++k;
  }
  return out;
}

}  // namespace granshock
