#include "io/hdf5_handle.hpp"

namespace granshock::h5 {

namespace {

// Keeps the innermost (first visited walking upward) description: it says what went
// wrong ("No such file or directory"), where the outer ones only repeat the call.
herr_t keep_innermost(unsigned n, const H5E_error2_t* error, void* client) {
  auto* message = static_cast<std::string*>(client);
  if (n == 0 && error != nullptr && error->desc != nullptr) *message = error->desc;
  return 0;
}

}  // namespace

std::string take_error_message() {
  std::string message;
  H5Ewalk2(H5E_DEFAULT, H5E_WALK_UPWARD, keep_innermost, &message);
  H5Eclear2(H5E_DEFAULT);
  // File errors carry the system's words among driver details ("unable to open file:
  // name = ..., errno = 2, error message = 'No such file or directory', flags = ...").
  if (message.find("unable to lock file") != std::string::npos) {
    return "in use by another program (HDF5 file lock)";
  }
  const std::string marker = "error message = '";
  const std::size_t at = message.find(marker);
  if (at != std::string::npos) {
    const std::size_t from = at + marker.size();
    const std::size_t to = message.find('\'', from);
    if (to != std::string::npos) message = message.substr(from, to - from);
  }
  if (message == "file signature not found") message = "not an HDF5 file";
  return message;
}

void silence_error_printing() {
  static const bool silenced = [] {
    H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
    return true;
  }();
  static_cast<void>(silenced);
}

}  // namespace granshock::h5
