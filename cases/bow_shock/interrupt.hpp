// SIGINT and SIGTERM as requests to stop at the next safe point (docs/output_format.md:
// a run writes its checkpoint and ends with 130 or 143). One flag for the process, shared
// by a run and by `granshock study`, which runs several cases in one process and must not
// start the next case after an interruption.
#pragma once

namespace granshock {

// From now on SIGINT and SIGTERM set the flag instead of ending the process.
void catch_interrupts();

// The signal caught since catch_interrupts() (the first one), or 0.
int interrupt_signal();

}  // namespace granshock
