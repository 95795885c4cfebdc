// The name a user most likely meant (a scene key, a command): the nearest of the accepted
// names by edit distance, where it is close enough to be a typo ("restitucion" for
// "restitution", "runn" for "run").
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace granshock {

// Insertions, deletions and substitutions that turn a into b (Levenshtein).
std::size_t edit_distance(const std::string& a, const std::string& b);

// Whether `typed` is a typo of `name`: different, and at most max(1, |name| / 4) edits away.
bool looks_like_typo_of(const std::string& typed, const std::string& name);

// The accepted name `typed` is a typo of, the nearest where several are; "" for none.
std::string nearest_name(const std::string& typed, const std::vector<std::string>& accepted);

}  // namespace granshock
