// Ownership of HDF5 identifiers (hid_t). Every file, group, dataset, dataspace, type and
// property list is closed exactly once, also when an exception unwinds: a leaked file
// identifier keeps the file open (and locked) until the process ends.
#pragma once

#include <hdf5.h>

#include <stdexcept>
#include <string>
#include <utility>

namespace granshock::h5 {

// An HDF5 call failed. The message names the operation and HDF5's own reason; the
// public io functions add the file's path and rethrow it as a UserError.
class Hdf5Error : public std::runtime_error {
 public:
  explicit Hdf5Error(const std::string& what) : std::runtime_error(what) {}
};

// The innermost message on HDF5's error stack ("unable to open file: ... No such file"),
// or "" when the stack is empty. Clears the stack.
std::string take_error_message();

// Turns off HDF5's printing of whole error stacks to stderr: a failure reaches the user
// as one line (an exception), not as a page of library internals. Idempotent.
void silence_error_printing();

class Handle {
 public:
  using Closer = herr_t (*)(hid_t);

  Handle() = default;
  Handle(hid_t id, Closer closer) : id_(id), closer_(closer) {}
  ~Handle() { static_cast<void>(close()); }

  Handle(Handle&& other) noexcept
      : id_(std::exchange(other.id_, H5I_INVALID_HID)), closer_(other.closer_) {}
  Handle& operator=(Handle&& other) noexcept {
    if (this != &other) {
      static_cast<void>(close());
      id_ = std::exchange(other.id_, H5I_INVALID_HID);
      closer_ = other.closer_;
    }
    return *this;
  }
  Handle(const Handle&) = delete;
  Handle& operator=(const Handle&) = delete;

  hid_t get() const { return id_; }
  bool valid() const { return id_ >= 0; }
  // Lets go without closing: for a file opened by several processes at once, whose close
  // waits for all of them, after a failure on this one alone (the job is about to end).
  void abandon() { id_ = H5I_INVALID_HID; }

  // Closes now and reports HDF5's status: closing a file is where buffered data reaches
  // the disk, so callers that must know it arrived check the result.
  herr_t close() {
    herr_t status = 0;
    if (id_ >= 0 && closer_ != nullptr) status = closer_(id_);
    id_ = H5I_INVALID_HID;
    return status;
  }

 private:
  hid_t id_ = H5I_INVALID_HID;
  Closer closer_ = nullptr;
};

// Takes ownership of `id` or throws Hdf5Error("<what> failed: <reason>") when it is
// negative, HDF5's sign of failure.
inline Handle checked(hid_t id, Handle::Closer closer, const std::string& what) {
  if (id < 0) {
    const std::string reason = take_error_message();
    throw Hdf5Error(what + " failed" + (reason.empty() ? "" : ": " + reason));
  }
  return Handle(id, closer);
}

inline void check(herr_t status, const std::string& what) {
  if (status < 0) {
    const std::string reason = take_error_message();
    throw Hdf5Error(what + " failed" + (reason.empty() ? "" : ": " + reason));
  }
}

// One factory per kind of identifier, so a handle always has the matching close call.
inline Handle file(hid_t id, const std::string& what) {
  return checked(id, H5Fclose, what);
}
inline Handle group(hid_t id, const std::string& what) {
  return checked(id, H5Gclose, what);
}
inline Handle dataset(hid_t id, const std::string& what) {
  return checked(id, H5Dclose, what);
}
inline Handle dataspace(hid_t id, const std::string& what) {
  return checked(id, H5Sclose, what);
}
inline Handle datatype(hid_t id, const std::string& what) {
  return checked(id, H5Tclose, what);
}
inline Handle attribute(hid_t id, const std::string& what) {
  return checked(id, H5Aclose, what);
}
inline Handle plist(hid_t id, const std::string& what) {
  return checked(id, H5Pclose, what);
}
inline Handle object(hid_t id, const std::string& what) {
  return checked(id, H5Oclose, what);
}

}  // namespace granshock::h5
