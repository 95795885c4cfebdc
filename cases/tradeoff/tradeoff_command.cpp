#include "cases/tradeoff/tradeoff_command.hpp"

#include <unistd.h>

#include <fstream>
#include <iostream>

#include "analysis/figures.hpp"
#include "analysis/json_file.hpp"
#include "cases/accuracy/accuracy_range.hpp"
#include "cases/study/study_command.hpp"
#include "cases/tradeoff/tradeoff_plan.hpp"
#include "core/user_error.hpp"
#include "io/scene_file.hpp"
#include "tradeoff_paths.hpp"

namespace granshock {

namespace fs = std::filesystem;

namespace {

// The table holds where it was measured: its scene's D/d and Ma (accuracy_range.hpp),
// added to trade.json beside what trade_table.py wrote, by a write-and-rename.
void record_range(const fs::path& table, const CertifiedRange& range) {
  JsonFile file = read_json_file(table, "trade table");
  if (file.value.is_discarded() || !file.value.is_object())
    throw UserError("'" + table.string() + "' is not the table trade_table.py writes");
  file.value["certified_range"] = to_json(range);
  const fs::path part = table.string() + ".part";
  {
    std::ofstream f(part);
    f << file.value.dump(1) << "\n";
    if (!f) throw UserError("cannot write '" + part.string() + "'");
  }
  fs::rename(part, table);
}

}  // namespace

int tradeoff_command(const TradeoffOptions& o) {
  const LoadedScene loaded = load_scene_file(o.scene_file, o.overrides);
  const std::string name = "tradeoff_" + loaded.scene.name;
  const fs::path out = o.out_dir.empty() ? fs::path("runs") / name : o.out_dir;
  const std::string toml =
      tradeoff_study_toml(name, o.scene_file, o.overrides, tradeoff_cases(loaded.scene));

  // The study runner refuses a directory it did not make, so the study file is written
  // aside (removed however the study ends) and copied in, for the record, once the study
  // has made its directory.
  struct TemporaryFile {
    fs::path path;
    ~TemporaryFile() {
      std::error_code ignored;
      fs::remove(path, ignored);
    }
  } study_file{fs::temp_directory_path() / (name + "-" + std::to_string(::getpid()) + ".toml")};
  {
    std::ofstream file(study_file.path);
    file << toml;
    if (!file) throw UserError("cannot write '" + study_file.path.string() + "'");
  }
  StudyOptions study;
  study.study_file = study_file.path;
  study.out_dir = out;
  study.collect = o.collect;
  study.dry_run = o.dry_run;
  study.quiet = o.quiet;
  study.figures = o.figures;
  study.redraw = {"granshock", "tradeoff", o.scene_file.string()};
  if (!o.out_dir.empty()) study.redraw.insert(study.redraw.end(), {"--out", o.out_dir.string()});
  for (const std::string& set : o.overrides)
    study.redraw.insert(study.redraw.end(), {"--set", set});
  study.redraw.push_back("--collect");
  const int code = study_command(study);
  std::error_code ec;
  if (!o.dry_run && fs::is_directory(out))
    fs::copy_file(study_file.path, out / "tradeoff.toml", fs::copy_options::overwrite_existing, ec);
  if (o.dry_run) return code;
  if (code != 0) {
    std::cerr << "granshock tradeoff: no trade table until every case has finished\n";
    return code;
  }
  require_plotting_python();
  // From the cases' records (docs/study.md, "Campaign records"), not their run directories.
  std::vector<std::string> args{(out / "records").string(), out.string()};
  if (!o.figures) args.push_back("--no-figures");  // the tables without pareto.png
  run_figure_script(figure_script("trade_table.py", GRANSHOCK_TRADEOFF_SCRIPT_DIR), args);
  record_range(out / "trade.json", range_of(scene_corner(loaded.scene), loaded.scene.name));
  if (!o.quiet) std::cout << "granshock tradeoff: table in " << (out / "trade.md").string() << "\n";
  return 0;
}

}  // namespace granshock
