// SIGINT and SIGTERM as requests to stop at the next safe point (docs/output_format.md,
// "Signals": a run writes its checkpoint and ends with 130 or 143). One flag for the
// process, shared by a run and by `granshock study`, which runs several cases in one
// process and must not start the next case after an interruption.
#pragma once

#include <string>

#include "core/interrupted.hpp"

namespace granshock {

// The first thing the program does: SIGINT and SIGTERM are held (blocked, kept pending)
// until the command is known, so that one sent while MPI and Kokkos start is neither lost
// nor fatal without a word.
void hold_interrupts();
// Commands that do not stop at safe points: the signals act as usual again (a held one
// ends the process now).
void release_interrupts();

// From now on SIGINT and SIGTERM set the flag instead of ending the process (a held one
// sets it at once).
void catch_interrupts();

// The signal caught since catch_interrupts() (the first one), or 0.
int interrupt_signal();

// Throws Interrupted when a signal was caught: the checks of long setup phases.
void throw_if_interrupted();

// For the last phase of a run, whose data is complete (the field analysis): while an
// ExitAtInterrupt lives, a signal (or one caught before it) ends the process at once,
// printing `message` (one line) with exit code 128 + signal. Only the analysis' own
// temporaries are left behind, and `granshock fields` redoes it.
class ExitAtInterrupt {
 public:
  explicit ExitAtInterrupt(const std::string& message);
  ~ExitAtInterrupt();
  ExitAtInterrupt(const ExitAtInterrupt&) = delete;
  ExitAtInterrupt& operator=(const ExitAtInterrupt&) = delete;
};

}  // namespace granshock
