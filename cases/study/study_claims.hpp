// The paper's qualitative claims checked across the finished cases of a study (docs/study.md,
// "Claims"), each as one line with its numbers and a verdict against a stated criterion:
//   - delta/D falls as Ma_inf rises, at fixed D/d;
//   - delta/D is nearly constant in D/d at fixed Ma_inf (relative spread <= 20 %);
//   - phi is about 0.5 between shock and obstacle (shock-layer mean in [0.35, 0.65]);
//   - the hot region behind the shock is subsonic (at least half of the hot strip bins);
//   - the local Ma upstream of the shock exceeds Ma_inf (peak / Ma_inf > 1);
//   - the wake is nearly empty (phi behind the cylinder below 0.2 phi_inf).
// The per-case numbers come from each run's summary.json (docs/fields.md, section 6).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "cases/study/study_table.hpp"

namespace granshock {

struct StudyClaim {
  std::string claim;      // the paper's words
  std::string criterion;  // how it is judged
  std::string verdict;    // "holds", "does not hold" or "undetermined"
  std::string numbers;    // the values behind the verdict
};

std::vector<StudyClaim> check_paper_claims(const StudyTable& table);

// <out>/claims.md (a table) and <out>/claims.json, each written atomically.
void write_claims(const std::filesystem::path& out, const std::vector<StudyClaim>& claims);

}  // namespace granshock
