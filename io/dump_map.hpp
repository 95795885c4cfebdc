// The map that lets `granshock fields --from-dump` analyse another code's particles
// (docs/fields.md, "Fields from LAMMPS or LIGGGHTS dumps"): a granshock scene file
// (docs/scene_format.md: species, domain, obstacle, inflow, contact restitution, time step,
// production window, bins and blocks), whose keys give the analysis what run.h5's scene
// gives it for a granshock run, plus a [dump] table that maps the dump's atom types to
// the scene's species:
//   [dump]
//   dt = 1e-6                       # optional: s per dump timestep (default time.dt)
//   flow_start = 0.0                # optional: when the flow past the obstacle began, s
//   [dump.types]
//   1 = "steel"                     # atom type = species name
//   2 = "aluminium"
#pragma once

#include <filesystem>
#include <map>
#include <optional>
#include <string>

#include "io/scene_file.hpp"

namespace granshock {

struct DumpMap {
  LoadedScene scene;
  std::map<long, int> species_of_type;  // atom type -> index into the scene's species
  std::optional<double> dt;             // [dump] dt, s per timestep
  // [dump] flow_start: the time on the dump's clock at which the flow met the obstacle
  // (default 0); the steadiness check counts the wash-out time from it (docs/fields.md,
  // section 12).
  double flow_start = 0;
  // Seconds per dump timestep: [dump] dt, else the scene's time.dt.
  double seconds_per_timestep() const { return dt ? *dt : scene.scene.setup.dt; }
};

// Reads and checks the map. Every problem is one UserError naming the file and the key
// (the scene's keys are checked as `granshock run` checks them).
DumpMap load_dump_map(const std::filesystem::path& path);
DumpMap parse_dump_map(const std::string& text, const std::string& origin);

}  // namespace granshock
