#include "io/fields_directory.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include "core/user_error.hpp"

namespace granshock {

namespace fs = std::filesystem;

namespace {

// The atomic writers' temporaries (io/atomic_file.hpp; analysis/figure_files.py for the
// figures) are NAME.tmp.
std::vector<std::string> with_temporaries(const std::vector<std::string>& names) {
  std::vector<std::string> all;
  for (const std::string& name : names) {
    all.push_back(name);
    all.push_back(name + ".tmp");
  }
  return all;
}

}  // namespace

const std::vector<std::string>& fields_outputs() {
  // analysis/fields_output.cpp, analysis/summary_json.cpp and the figures drawn by
  // analysis/plot_fields.py.
  static const std::vector<std::string> outputs =
      with_temporaries({"fields.h5", "fields.xmf", "detachment_convergence.csv", "summary.json",
                        "figures/solid_fraction.png", "figures/temperature.png", "figures/mach.png",
                        "figures/stagnation_profiles.png"});
  return outputs;
}

const std::vector<std::string>& comparison_outputs() {
  // analysis/detachment_table.cpp and analysis/plot_detachment.py.
  static const std::vector<std::string> outputs =
      with_temporaries({"detachment.csv", "detachment.json", "figures/detachment_length.png"});
  return outputs;
}

namespace {

const std::vector<std::string>& outputs_of(FieldsOutput what) {
  return what == FieldsOutput::one_run ? fields_outputs() : comparison_outputs();
}

// Which granshock directory `out` is: its marker kind, or none.
enum class Kind { none, fields, run, study };

Kind kind_of(const fs::path& out, std::optional<DirectoryMarker>& fields_marker) {
  fields_marker = read_marker(out, kFieldsMarker);
  if (fields_marker) return Kind::fields;
  if (read_marker(out, kRunMarker)) return Kind::run;
  if (read_marker(out, kStudyMarker)) return Kind::study;
  return Kind::none;
}

}  // namespace

void FieldsDirectory::check(const fs::path& out, FieldsOutput what) {
  if (out.empty()) throw UserError("--out: the directory name is empty");
  std::error_code ec;
  const bool exists = fs::exists(out, ec);
  if (exists && !fs::is_directory(out, ec))
    throw UserError(fmt::format("--out '{}' exists and is not a directory", out.string()));
  if (!exists) {
    check_creatable(out);
    return;
  }
  if (::access(out.c_str(), W_OK | X_OK) != 0)
    throw UserError(fmt::format("--out '{}' is not writable", out.string()));
  std::optional<DirectoryMarker> marker;
  switch (kind_of(out, marker)) {
    case Kind::none:
      if (directory_is_empty(out)) return;
      throw UserError(fmt::format(
          "--out '{}' is not empty and was not written by granshock fields (it has no {} "
          "marker); granshock never replaces files it did not create: choose a new or empty "
          "directory",
          out.string(), kFieldsMarker));
    case Kind::run:
      throw UserError(fmt::format(
          "--out '{}' is a granshock run directory; `granshock fields {}` writes the analysis "
          "of its own run there, nothing else does: choose another --out",
          out.string(), out.string()));
    case Kind::study:
      if (what == FieldsOutput::one_run)
        throw UserError(fmt::format(
            "--out '{}' is a granshock study directory; it takes the comparison of several "
            "runs, not the analysis of one: choose another --out",
            out.string()));
      break;
    case Kind::fields:
      check_marker_format(out, *marker, kFieldsDirectoryFormat, "fields-directory");
      if (locked_by_another(out, kFieldsMarker)) refuse_in_use(out, *marker);
      break;
  }
  check_outputs_are_files(out, outputs_of(what));
}

FieldsDirectory FieldsDirectory::claim(const fs::path& out, FieldsOutput what) {
  check(out, what);
  std::error_code ec;
  fs::create_directories(out, ec);
  if (ec) throw UserError(fmt::format("cannot create --out '{}': {}", out.string(), ec.message()));
  std::optional<DirectoryMarker> marker;
  if (kind_of(out, marker) == Kind::study) return FieldsDirectory(out, DirectoryLock());
  FieldsDirectory claimed(
      out, DirectoryLock::take(out, kFieldsMarker,
                               "granshock fields directory: granshock fields replaces only its "
                               "own outputs here",
                               kFieldsDirectoryFormat));
  check_outputs_are_files(out, outputs_of(what));  // again, now that the lock is ours
  return claimed;
}

}  // namespace granshock
