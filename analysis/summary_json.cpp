#include "summary_json.hpp"

#include <fstream>
#include <sstream>

#include "atomic_file.hpp"
#include "regular_file.hpp"
#include "user_error.hpp"

namespace granshock {

void merge_summary_json(const std::filesystem::path& path, const nlohmann::json& keys) {
  nlohmann::json merged = nlohmann::json::object();
  std::error_code ec;
  if (std::filesystem::exists(path, ec)) {
    require_regular_file(path, "summary");  // a FIFO would block the read
    std::ifstream in(path);
    if (!in) throw UserError("cannot read '" + path.string() + "'");
    std::stringstream text;
    text << in.rdbuf();
    try {
      merged = nlohmann::json::parse(text.str());
    } catch (const nlohmann::json::parse_error& e) {
      throw UserError("'" + path.string() + "' is not valid JSON (" + e.what() +
                      "); move it away to start a new one");
    }
    if (!merged.is_object()) throw UserError("'" + path.string() + "' does not hold a JSON object");
  }
  for (const auto& [key, value] : keys.items()) merged[key] = value;
  write_file_atomically(path, merged.dump(2) + "\n");
}

}  // namespace granshock
