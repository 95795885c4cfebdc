#include "summary_json.hpp"

#include "atomic_file.hpp"
#include "json_file.hpp"
#include "user_error.hpp"

namespace granshock {

void merge_summary_json(const std::filesystem::path& path, const nlohmann::json& keys) {
  nlohmann::json merged = nlohmann::json::object();
  std::error_code ec;
  if (std::filesystem::exists(path, ec)) {
    JsonFile existing = read_json_file(path);
    if (existing.value.is_discarded())
      throw UserError("'" + path.string() + "' is not valid JSON (" + existing.error +
                      "); move it away to start a new one");
    merged = std::move(existing.value);
    if (!merged.is_object()) throw UserError("'" + path.string() + "' does not hold a JSON object");
  }
  for (const auto& [key, value] : keys.items()) merged[key] = value;
  write_file_atomically(path, merged.dump(2) + "\n");
}

}  // namespace granshock
