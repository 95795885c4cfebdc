// The field sums in run.h5, writer and reader together (docs/output_format.md, "/fields"):
// /fields/grid holds the sums over the bin grid of the whole domain, [blocks, ny, nx, q],
// /fields/profile those of the stagnation-line profile, [blocks, ny, nx, q], each with the samples
// per block and the geometry as attributes (q per bin: core/bin_layout.hpp). `granshock run`
// writes them at the end of a run and `granshock fields` reads them back; one file owns the
// layout so that the two cannot disagree (tests/io/test_field_sums_file.cpp).
#pragma once

#include <limits>
#include <vector>

#include "core/bin_layout.hpp"
#include "core/bin_sums.hpp"

namespace granshock {

class RunFile;

// What a run accumulated: the sampling layout, the sums, the samples per block and the
// production window they cover.
struct FieldSumsRecord {
  FieldSampling sampling;
  std::vector<double> grid_sums;                           // [blocks][ny][nx][q]
  std::vector<double> profile_sums;                        // [blocks][ny][nx][q], empty without one
  std::vector<long> samples;                               // [blocks]
  double production_start = 0, production_end = 0;         // s
  long sample_every = 0;                                   // steps between samples
  double y_end = std::numeric_limits<double>::infinity();  // the domain's end along y, m
};

void write_field_sums(RunFile& run, const FieldSumsRecord& record);

// Read from run.h5. Throw UserError naming the file and the object when the sums are
// missing (a run without a production window) or have an inconsistent shape.
BinSums read_grid_sums(const RunFile& run);
BinSums read_profile_sums(const RunFile& run);
// Whether run.h5 holds a stagnation-line profile.
bool has_profile_sums(const RunFile& run);

}  // namespace granshock
