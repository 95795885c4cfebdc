#include "cases/export/lammps_export.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <iostream>
#include <numeric>

#include "core/user_error.hpp"
#include "io/atomic_file.hpp"
#include "io/run_directory.hpp"
#include "io/run_file.hpp"
#include "io/scene_file.hpp"

namespace granshock {

namespace fs = std::filesystem;

namespace {

// One frame of the dump: its atoms by id.
void write_frame(const AtomicWrite& write, const SnapshotFrame& frame, const HostParticles& p,
                 const Scene& scene) {
  const Box& box = scene.setup.box;
  // A quasi-2-D layer: as thick as the largest sphere, centred on z = 0 (a 3-D scene's box).
  const double half = scene.setup.dim == 3 ? 0.5 * box.length(2) : 0.5 * scene.setup.max_diameter();
  const double z_lo = scene.setup.dim == 3 ? box.lo[2] : -half;
  const double z_hi = scene.setup.dim == 3 ? box.hi[2] : half;
  std::string text = fmt::format(
      "ITEM: TIMESTEP\n{}\nITEM: TIME\n{:.17g}\nITEM: NUMBER OF ATOMS\n{}\nITEM: BOX BOUNDS pp ff "
      "pp\n{:.17g} {:.17g}\n{:.17g} {:.17g}\n{:.17g} {:.17g}\nITEM: ATOMS id type x y z vx vy vz "
      "radius\n",
      frame.step, frame.time, p.size(), box.lo[0], box.hi[0], box.lo[1], box.hi[1], z_lo, z_hi);
  std::vector<std::size_t> order(p.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(),
            [&](std::size_t a, std::size_t b) { return p.id[a] < p.id[b]; });
  for (const std::size_t i : order) {
    const auto& x = p.position[i];
    const auto& v = p.velocity[i];
    const int s = p.species[i];
    const double radius = s >= 0 && std::size_t(s) < scene.setup.species.size()
                              ? scene.setup.species[std::size_t(s)].radius_m()
                              : 0.0;
    text += fmt::format("{} {} {:.17g} {:.17g} {:.17g} {:.17g} {:.17g} {:.17g} {:.17g}\n",
                        long(p.id[i]) + 1, s + 1, x[0], x[1], x[2], v[0], v[1], v[2], radius);
    if (text.size() > (1 << 20)) {  // in pieces: a run's dump may exceed the memory
      write(text);
      text.clear();
    }
  }
  write(text);
}

// The map of `fields --from-dump` for the dump: the run's own resolved scene and its types.
std::string dump_map(const std::string& resolved, const Scene& scene) {
  std::string map = resolved;
  map +=
      "\n# The map of `granshock fields --from-dump` for the dump `granshock export` wrote\n"
      "# (docs/fields.md, \"Fields from LAMMPS or LIGGGHTS dumps\"): atom type = species + 1.\n"
      "[dump]\n";
  map += fmt::format("dt = {:.17g}\n\n[dump.types]\n", scene.setup.dt);
  for (std::size_t s = 0; s < scene.setup.species.size(); ++s)
    map += fmt::format("{} = \"{}\"\n", s + 1, scene.setup.species[s].name);
  return map;
}

}  // namespace

int export_command(const ExportOptions& o) {
  if (o.lammps_dump.empty())
    throw UserError("granshock export needs --lammps-dump FILE (what to write)");
  const fs::path run_h5 = o.run_dir / "run.h5";
  std::error_code ec;
  if (!fs::exists(run_h5, ec))
    throw UserError("'" + run_h5.string() +
                    "' does not exist: granshock export writes the snapshots of a run directory");
  const std::optional<DirectoryLock> reading = hold_for_reading(o.run_dir);  // as fields --out
  const RunFile run = RunFile::open_read_only(run_h5);
  const std::string resolved = run.scene_resolved();
  const Scene scene = parse_scene(resolved, {}, run_h5.string() + ":/scene/resolved").scene;
  const std::vector<SnapshotFrame> frames = run.frames();
  long atoms = 0;
  write_file_atomically(o.lammps_dump, [&](const AtomicWrite& write) {
    for (std::size_t k = 0; k < frames.size(); ++k) {
      const HostParticles p = run.read_snapshot(long(k));
      atoms += long(p.size());
      write_frame(write, frames[k], p, scene);
    }
  });
  if (!o.map.empty()) write_file_atomically(o.map, dump_map(resolved, scene));
  if (!o.quiet)
    std::cout << fmt::format("granshock export: {} snapshots ({} atoms in all) of {} in {}{}\n",
                             frames.size(), atoms, run_h5.string(), o.lammps_dump.string(),
                             o.map.empty() ? "" : "; its map for --from-dump in " + o.map.string());
  return 0;
}

}  // namespace granshock
