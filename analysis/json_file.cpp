#include "analysis/json_file.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "core/user_error.hpp"
#include "io/regular_file.hpp"

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

JsonFile read_json_file(const std::filesystem::path& path, const std::string& what) {
  const std::string text = read_regular_file(path, what, kMaxJsonFileBytes);
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
