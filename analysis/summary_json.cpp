#include "summary_json.hpp"

#include <sys/stat.h>

#include <fstream>
#include <sstream>

#include "atomic_file.hpp"
#include "user_error.hpp"

namespace granshock {

nlohmann::json read_summary_json(const std::filesystem::path& path) {
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0) return nlohmann::json::object();
  // A FIFO or a device would block the read or never end.
  if (!S_ISREG(st.st_mode)) throw UserError("'" + path.string() + "' is not a regular file");
  std::ifstream in(path);
  if (!in) throw UserError("cannot read '" + path.string() + "'");
  std::stringstream text;
  text << in.rdbuf();
  nlohmann::json j;
  try {
    j = nlohmann::json::parse(text.str());
  } catch (const nlohmann::json::parse_error& e) {
    throw UserError("'" + path.string() + "' is not valid JSON (" + e.what() +
                    "); move it away to start a new one");
  }
  if (!j.is_object()) throw UserError("'" + path.string() + "' does not hold a JSON object");
  return j;
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
