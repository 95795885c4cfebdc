// One particle snapshot as listed in run.h5 (/particles/all/count): what an XDMF file
// needs to point a viewer at it.
#pragma once

namespace granshock {

struct SnapshotFrame {
  long step = 0;    // solver steps done when it was taken
  double time = 0;  // s
  long count = 0;   // particles in it: rows [0, count) of the frame hold data
};

}  // namespace granshock
