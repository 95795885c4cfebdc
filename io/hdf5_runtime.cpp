#include "io/hdf5_runtime.hpp"

#include <hdf5.h>

namespace granshock::h5 {

void keep_exit_free_of_hdf5() {
  H5dont_atexit();
}

}  // namespace granshock::h5
