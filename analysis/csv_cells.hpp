// The one CSV writer of every table granshock writes (study.csv, detachment.csv,
// detachment_convergence.csv; docs/output_format.md, "CSV tables"), by RFC 4180: a field
// holding a comma, a quote, CR or LF is quoted, its quotes doubled. A text cell is always
// quoted (so "nan" the text is not nan the number); a number has 10 significant digits and
// is empty when it is not finite (undetermined); a header name is quoted only when needed.
#pragma once

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

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

// A header name or other bare field: as it is, or quoted when it holds , " CR or LF.
inline std::string csv_name(const std::string& s) {
  return s.find_first_of(",\"\r\n") == std::string::npos ? s : csv_text(s);
}

// A line of fields already written by the functions above.
inline std::string csv_line(const std::vector<std::string>& fields) {
  std::string line;
  for (std::size_t k = 0; k < fields.size(); ++k) line += (k ? "," : "") + fields[k];
  return line + "\n";
}

// The header line of `names`.
inline std::string csv_header(const std::vector<std::string>& names) {
  std::vector<std::string> fields;
  for (const std::string& n : names) fields.push_back(csv_name(n));
  return csv_line(fields);
}

}  // namespace granshock
