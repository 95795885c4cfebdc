// docs/scene_keys.md's table of keys, made from the scene schema (io/scene_schema.cpp) so
// that the docs cannot list a key, a range or a default the program does not have.
#include <string>

#include "io/scene_file.hpp"

namespace granshock {

namespace {
// One Markdown table row; an empty cell is written "| |", as the docs write it.
std::string row(const std::initializer_list<std::string>& cells) {
  std::string line;
  for (const std::string& cell : cells) line += cell.empty() ? "| " : "| " + cell + " ";
  return line + "|\n";
}
}  // namespace

std::string scene_keys_table() {
  std::string table = row({"key", "type", "unit", "accepted", "default", "meaning"}) +
                      "|---|---|---|---|---|---|\n";
  for (const SceneKey& k : scene_keys())
    table += row(
        {"`" + k.name + "`", k.type, k.doc.unit, k.doc.accepted, k.doc.fallback, k.doc.meaning});
  return table;
}

}  // namespace granshock
