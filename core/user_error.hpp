// An error the user can cause and fix (bad flag, bad scene, unsafe time step): the
// program prints its message on one line and exits non-zero, without a stack trace.
#pragma once

#include <stdexcept>
#include <string>

namespace granshock {

class UserError : public std::runtime_error {
 public:
  explicit UserError(const std::string& what) : std::runtime_error(what) {}
};

}  // namespace granshock
