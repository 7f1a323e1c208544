#include "core/MemoryPolicy.hpp"

#include <climits>
#include <cstdlib>  // defines __GLIBC__ where glibc is the C library

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace impm {

void keepFreedMemory() {
#if defined(__GLIBC__)
  mallopt(M_MMAP_MAX, 0);              // large blocks from the heap, not from mmap
  mallopt(M_TRIM_THRESHOLD, INT_MAX);  // and the heap's free top is not given back
#endif
}

}  // namespace impm
