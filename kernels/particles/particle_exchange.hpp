// The device half of the communication seam (core/communicator.hpp; docs/design.md,
// "Seams"): at each neighbour-list rebuild, particles that left this process's subdomain
// migrate to the process that owns them now, and copies of the particles near the
// subdomain's faces (ghosts) are appended after the owned ones, so that the pair loop sees
// every partner. With one process owning the whole box there is nothing to send, and
// periodic images are resolved by the minimum image (device/box_geometry.hpp): this
// implementation moves nothing and appends no ghost.
#pragma once

namespace granshock {

template <class Store>
struct SingleProcessExchange {
  // Hands particles outside the subdomain to their owners; returns those kept.
  int migrate(Store& p) { return p.n; }
  // Appends ghost copies after the owned particles; returns how many.
  int append_ghosts(Store&) { return 0; }
};

}  // namespace granshock
