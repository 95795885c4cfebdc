#include "core/large_blocks.hpp"

#include <cstdlib>  // defines __GLIBC__ where the C library is glibc

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace granshock {

bool keep_large_blocks() {
#if defined(__GLIBC__)
  // Setting either disables glibc's own adjustment of the threshold (mallopt(3)).
  return mallopt(M_MMAP_THRESHOLD, int(kHeapBlockBytes)) == 1 &&
         mallopt(M_TRIM_THRESHOLD, int(kKeptFreeBytes)) == 1;
#else
  return false;
#endif
}

}  // namespace granshock
