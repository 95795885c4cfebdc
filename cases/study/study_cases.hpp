// The cases of a study (docs/study.md, "Cases"): the axes combined by the study's mode,
// then the [[case]] entries, each with a unique name and its overrides in order.
#pragma once

#include <string>
#include <vector>

#include "cases/study/study_file.hpp"

namespace granshock {

struct StudyCase {
  int index = 0;                       // 0-based: `--case K`, the Slurm array index
  std::string name;                    // its directory under the study's out, and scene.name
  std::vector<std::string> overrides;  // "key=value", applied in order to the base scene
  std::vector<int> axis_value;         // per axis, the index of its value, or -1
};

// The most cases a study may have (a product of many axes grows fast).
inline constexpr std::size_t kMaxStudyCases = 10000;

// Throws UserError for duplicate names, lists of unequal length, two axes of a product
// setting the same key, or more than kMaxStudyCases cases.
std::vector<StudyCase> expand_cases(const StudySpec& study);

// The case name a sweep gives the base scene when one of its values equals it.
inline constexpr const char* kSweepBaseName = "base";

// Sweep: the cases whose overrides leave the base scene as it is become one case named
// kSweepBaseName carrying each such axis value (`same_as_base[k]` for case k, from the
// resolved scenes). Throws UserError when a [[case]] already has that name.
std::vector<StudyCase> merge_base_cases(const StudySpec& study, std::vector<StudyCase> cases,
                                        const std::vector<bool>& same_as_base);

// "key=value key=value", for progress lines and --dry-run.
std::string overrides_text(const std::vector<std::string>& overrides);

}  // namespace granshock
