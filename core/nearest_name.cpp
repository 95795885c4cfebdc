#include "core/nearest_name.hpp"

#include <algorithm>

namespace granshock {

std::size_t edit_distance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t above = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] != b[j - 1])});
      diagonal = above;
    }
  }
  return row[b.size()];
}

bool looks_like_typo_of(const std::string& typed, const std::string& name) {
  return typed != name && edit_distance(typed, name) <= std::max<std::size_t>(1, name.size() / 4);
}

std::string nearest_name(const std::string& typed, const std::vector<std::string>& accepted) {
  std::string nearest;
  for (const std::string& name : accepted)
    if (looks_like_typo_of(typed, name) &&
        (nearest.empty() || edit_distance(typed, name) < edit_distance(typed, nearest)))
      nearest = name;
  return nearest;
}

}  // namespace granshock
