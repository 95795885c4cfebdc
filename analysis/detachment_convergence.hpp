// Does delta depend on how the profile was cut? (docs/fields.md, "Convergence table".) The
// detachment length by every definition again for other analysis choices, and a verdict per
// definition on whether it agrees with itself across them:
//   rows 0.5, 1, 1.5, 2 and 3 d   the profile's rows merged from the obstacle's face upstream
//                                 (the strip kept), i.e. the bin size along the line;
//   strip 1, 2, 4 and 6 d         the profile strip's width (rows of 0.5 d);
//   grid column                   the grid's column centred on the axis (its bin size);
//   first half, second half       the two halves of the production window.
// A choice agrees when its delta lies within two errors of the reference's (the larger of the
// two errors for cuts of the same data; the combined error of the two independent halves).
#pragma once

#include <string>
#include <vector>

#include "analysis/detachment.hpp"

namespace granshock {

struct ConvergenceChoice {
  std::string kind;   // "rows", "strip", "grid_column", "window"
  std::string label;  // e.g. "rows 1.5 d"
  double size_d = 0;  // rows: row height, strip and grid column: width, in d (window: 0)
  Detachments result;
};

struct ConvergenceVerdict {
  FrontDefinition definition = kPrimaryFront;
  bool applicable = false;  // the reference delta exists
  bool consistent = false;
  double max_deviation = 0;  // largest |delta - delta_ref| over the choices that found one, m
  std::string worst;         // the choice of the largest deviation in units of its tolerance
  std::string text;          // one line: consistent, or which choice disagrees and by how much
};

struct DetachmentConvergence {
  std::vector<ConvergenceChoice> choices;
  std::vector<ConvergenceVerdict> verdicts;  // in the order of kFrontDefinitions
  const ConvergenceVerdict& of(FrontDefinition definition) const;
};

struct ConvergenceInput {
  const BinSums* profile = nullptr;  // the whole stagnation-line profile (all its columns)
  const BinSums* grid = nullptr;
  int axis_column = 0;  // the grid column on the axis
  double x_axis = 0;
  double strip_width = 0;                  // the reference strip, m
  const Detachments* reference = nullptr;  // at the reference strip and rows
};

DetachmentConvergence detachment_convergence(const ConvergenceInput& input,
                                             const FieldPhysics& physics,
                                             const UpstreamValues& upstream,
                                             const DetachmentSearch& search);

}  // namespace granshock
