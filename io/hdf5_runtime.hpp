// HDF5's process-wide behaviour for granshock's programs.
#pragma once

namespace granshock::h5 {

// Stops HDF5 from closing leftover files in an atexit handler. granshock closes every
// file it opens itself (RAII handles); what HDF5 would find at exit is only a file whose
// close already failed (a full disk), and HDF5 1.10 crashes flushing such a file. Call
// once, before any other HDF5 function.
void keep_exit_free_of_hdf5();

}  // namespace granshock::h5
