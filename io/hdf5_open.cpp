// Opening an existing granshock HDF5 file, shared by run.h5 and checkpoint.h5.
#include "io/hdf5_open.hpp"

#include <system_error>

#include "io/hdf5_helpers.hpp"

namespace granshock::h5 {

UserError cannot_open(const std::string& doing, const std::filesystem::path& path,
                      const std::string& reason) {
  return UserError("cannot " + doing + " '" + path.string() + "': " + reason);
}

void require_existing(const std::filesystem::path& path, const std::string& doing) {
  silence_error_printing();
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) throw cannot_open(doing, path, "no such file");
}

Handle open_existing_file(const std::filesystem::path& path, unsigned flags,
                          const std::string& doing) {
  const hid_t id = H5Fopen(path.c_str(), flags, H5P_DEFAULT);
  if (id < 0) throw cannot_open(doing, path, take_error_message());
  return Handle(id, H5Fclose);
}

bool is_granshock_file(hid_t file, const std::string& kind) {
  return has_attribute(file, "granshock_file") &&
         read_string_attribute(file, "granshock_file") == kind;
}

}  // namespace granshock::h5
