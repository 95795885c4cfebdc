// `granshock export DIR --lammps-dump FILE [--map MAP]` (docs/output_format.md, "Export to
// LAMMPS and OVITO"): the snapshots of DIR/run.h5 as the text of a LAMMPS `dump custom`
// with the columns id type x y z vx vy vz radius, which LAMMPS' read_dump, OVITO and
// `granshock fields --from-dump` read. Ids and types count from 1, as LAMMPS' do (granshock
// id + 1, species index + 1); each frame lists its atoms by id, with ITEM: TIME, the box of
// the scene (x periodic, y fixed, z a periodic layer one diameter thick in 2-D) and numbers
// written with 17 significant digits, so that reading them back gives the same doubles.
// MAP: the run's resolved scene with the [dump] table of its types, the map that
// `fields --from-dump` needs for FILE.
#pragma once

#include <filesystem>

namespace granshock {

struct ExportOptions {
  std::filesystem::path run_dir;
  std::filesystem::path lammps_dump;  // required
  std::filesystem::path map;          // optional
  bool quiet = false;
};

// Returns 0; throws UserError for a directory without run.h5, one a run is writing, or an
// output that cannot be written (each written atomically: a failure leaves no half file).
int export_command(const ExportOptions& options);

}  // namespace granshock
