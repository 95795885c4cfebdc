// The CPU time this process has used, all its threads together (user + system): what a
// run costs on a shared machine, where wall time also counts the other programs' turns.
#pragma once

namespace granshock {

double process_cpu_seconds();

}  // namespace granshock
