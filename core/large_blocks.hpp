// Large blocks of memory kept for reuse (docs/benchmarks.md, "Fresh pages"). glibc's
// malloc maps every block above 32 MB afresh and unmaps it on free, so each such
// allocation pays one page fault per 4 kB page on first touch, which on a virtual machine
// made a copy of a paper case's field sums 40 times slower than a copy into pages already
// held (measured in docs/benchmarks.md, "Fresh pages"). A checkpoint, the end of a run and
// each move between threads and one thread copy those sums. Taking large blocks from the
// heap and keeping freed memory there makes the second and later copies reuse pages the
// process already has.
#pragma once

namespace granshock {

// Blocks up to kHeapBlockBytes come from the heap; freed memory is returned to the system
// only above kKeptFreeBytes. Returns false where the C library refused (then nothing
// changed). Called once, at the start of a program, before large allocations.
constexpr long kHeapBlockBytes = 512L << 20;
constexpr long kKeptFreeBytes = 1L << 30;
bool keep_large_blocks();

}  // namespace granshock
