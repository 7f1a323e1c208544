#pragma once
// How the process takes memory from the operating system.

namespace impm {

// Keeps freed memory in the process instead of returning it to the operating system.  Every
// step builds its grid system afresh (views of the particle count, the graph, the matrix), and
// glibc serves blocks above 32 MB with mmap and unmaps them when freed, so the next step
// faulted every page in again: at 10^6 particles the kernel's share was 16% of the run.
// Peak memory does not change (the blocks are reused, not added).  No effect off glibc.
void keepFreedMemory();

}  // namespace impm
