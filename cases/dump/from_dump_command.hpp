// `granshock fields --from-dump FORMAT FILES... --map MAP.toml --out DIR` (docs/fields.md,
// "Fields from LAMMPS or LIGGGHTS dumps"): the analysis of `granshock fields` for the
// particles of another code's dump files.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "analysis/fields_command.hpp"

namespace granshock {

struct FieldAnalysis;

struct FromDumpOptions {
  std::string format;  // "lammps" | "liggghts"
  std::vector<std::filesystem::path> files;
  std::filesystem::path map;
  std::filesystem::path out;
};

// Reads the map and every frame, sums the frames of the production window into the bins
// of a run of the map's scene (cases/dump/dump_sums.hpp), analyses them as `granshock
// fields` analyses a run's sums, and writes fields.h5, fields.xmf,
// detachment_convergence.csv, summary.json and the figures into `out` (a new or empty
// directory, or one `granshock fields` wrote). Everything is read and checked before
// anything is written. Returns 0; throws UserError on bad input.
int from_dump_command(const FromDumpOptions& dump, const FieldsCommandOptions& options);

// The fields a dump cannot give (it has no contact forces): the collisional pressure
// tensor, the pressure and its deviation from the equation of state become NaN, and the
// equation-of-state check says why.
void drop_collisional_pressure(FieldAnalysis& analysis);

}  // namespace granshock
