// CSV cells of the analysis tables (detachment.csv, detachment_convergence.csv): a number
// with 10 significant digits, empty when it is not finite (undetermined); a text quoted,
// its quotes doubled.
#pragma once

#include <cmath>
#include <cstdio>
#include <string>

namespace granshock {

inline std::string csv_number(double v) {
  if (!std::isfinite(v)) return "";
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.10g", v);
  return buffer;
}

inline std::string csv_text(const std::string& s) {
  std::string out = "\"";
  for (char c : s) out += c == '"' ? std::string("\"\"") : std::string(1, c);
  return out + "\"";
}

}  // namespace granshock
