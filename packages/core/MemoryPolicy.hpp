#pragma once
// How the process takes memory from the operating system.

namespace impm {

// Keeps freed memory in the process instead of returning it to the operating system.  Every
// step builds its grid system afresh (views of the particle count, the graph, the matrix), and
// glibc serves blocks above 32 MB with mmap and unmaps them when freed, so the next step
// faulted every page in again: at 10^6 particles the kernel's share was 16% of the run.
// Peak memory does not change (the blocks are reused, not added).  No effect off glibc.
void keepFreedMemory();

// Asks the kernel to back the heap with transparent huge pages (2 MB).  Debian's kernels give
// them only to memory that asks (THP mode "madvise"), and glibc's malloc asks only when a
// tunable says so at the process's start, which a program cannot set for itself.  So the heap
// is marked here, and marked again each time it has grown when Kokkos allocates: every View
// (the particles' fields, Tpetra's vectors and matrices) passes that event before anything
// writes to it.  The heap then grows 64 MB ahead of what it holds, so that the vectors and
// arrays Kokkos does not see land in marked memory too.  Fewer page faults and TLB misses:
// the 64 x 512 column 6% faster, the colliding disks at 10^6 particles 16% (doc/performance.md).
// Call after Kokkos is initialized, and after keepFreedMemory: blocks that glibc serves with
// mmap are not in the heap and not marked.  Returns false, changing nothing, off Linux and glibc,
// under a kernel with huge pages off, and when a Kokkos tool is loaded (its allocation
// callback is kept).
bool adviseHugePages();

}  // namespace impm
