#include "analysis/summary_json.hpp"

#include "analysis/json_file.hpp"
#include "core/user_error.hpp"
#include "io/atomic_file.hpp"

namespace granshock {

nlohmann::json read_summary_json(const std::filesystem::path& path) {
  std::error_code ec;
  if (!std::filesystem::exists(std::filesystem::symlink_status(path, ec)))
    return nlohmann::json::object();
  // A regular file of bounded size and nesting (json_file.hpp): a FIFO or a device would
  // block the read or never end, a file nested on purpose would overflow the parser.
  JsonFile existing = read_json_file(path, "summary");
  if (existing.value.is_discarded())
    throw UserError("'" + path.string() + "' is not valid JSON (" + existing.error +
                    "); move it away to start a new one");
  if (!existing.value.is_object())
    throw UserError("'" + path.string() + "' does not hold a JSON object");
  return std::move(existing.value);
}

void merge_summary_json(const std::filesystem::path& path, const nlohmann::json& keys) {
  write_summary_json(path, read_summary_json(path), keys);
}

void write_summary_json(const std::filesystem::path& path, nlohmann::json base,
                        const nlohmann::json& keys) {
  for (const auto& [key, value] : keys.items()) base[key] = value;
  write_file_atomically(path, base.dump(2) + "\n");
}

}  // namespace granshock
