// Failing together on several processes (docs/parallel.md, "Errors"). A step that can
// fail on some ranks and not on others (rank 0's files, a lock) is run through
// agree_on_failure before the next collective operation, so that no rank is left waiting
// in one: if any rank failed, the lowest failing rank rethrows its own error (the one
// message the user sees) and every other rank throws PeerFailed, which exits quietly.
// Failures after the last agreement end the job through MPI_Abort (apps/granshock).
#pragma once

#include <exception>
#include <stdexcept>
#include <string>

#include "core/communicator.hpp"
#include "core/interrupted.hpp"

namespace granshock {

class PeerFailed : public std::runtime_error {
 public:
  explicit PeerFailed(int rank, int exit_code = 2)
      : std::runtime_error("rank " + std::to_string(rank) + " failed and said why"),
        exit_code_(exit_code) {}
  // The failing rank's exit code: 2, or 128 + signal for an interruption.
  int exit_code() const { return exit_code_; }

 private:
  int exit_code_;
};

// The exit code a failure ends the process with, where it is not 2 (interrupted.hpp).
inline int exit_code_of(const std::exception_ptr& failure) {
  try {
    std::rethrow_exception(failure);
  } catch (const Interrupted& e) {
    return e.exit_code();
  } catch (...) {
    return 2;
  }
}

// True once agree_on_failure has rethrown this rank's error: every rank knows of the
// failure and leaves without waiting for another.
inline bool& failure_agreed() {
  static bool agreed = false;
  return agreed;
}

template <class Step>
void agree_on_failure(const Communicator& comm, Step&& step) {
  if (comm.size() == 1) return step();
  std::exception_ptr failure;
  try {
    step();
  } catch (...) {
    failure = std::current_exception();
  }
  // max(size - rank) over the failing ranks names the lowest of them; 0: none failed.
  const int n = comm.size();
  const int highest = int(comm.max(failure ? double(n - comm.rank()) : 0.0));
  if (highest == 0) return;
  failure_agreed() = true;
  const bool reports = comm.rank() == n - highest;
  // The others end with the exit code of the rank that reports (an interruption's too).
  const int code = int(comm.max(reports ? double(exit_code_of(failure)) : 0.0));
  if (reports) std::rethrow_exception(failure);
  throw PeerFailed(n - highest, code);
}

}  // namespace granshock
