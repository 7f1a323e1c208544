#include "core/MemoryPolicy.hpp"

#include <climits>
#include <cstdint>
#include <cstdlib>  // defines __GLIBC__ where glibc is the C library
#include <fstream>
#include <string>

#include <Kokkos_Core.hpp>

#if defined(__GLIBC__)
#include <malloc.h>
#endif

// Under AddressSanitizer the heap is the sanitizer's, not glibc's: nothing to advise.
#if defined(__GLIBC__) && defined(__linux__) && !defined(__SANITIZE_ADDRESS__)
#include <sys/mman.h>
#include <unistd.h>
#define IMPM_HEAP_ADVICE 1
#endif

namespace impm {

void keepFreedMemory() {
#if defined(__GLIBC__)
  mallopt(M_MMAP_MAX, 0);              // large blocks from the heap, not from mmap
  mallopt(M_TRIM_THRESHOLD, INT_MAX);  // and the heap's free top is not given back
#endif
}

#if defined(IMPM_HEAP_ADVICE)
namespace {

// The heap from where it stood when the advice began to where it has been marked.  Kokkos
// allocates from one thread, so the callback needs no lock.
std::uintptr_t heapBase = 0;
std::uintptr_t markedTop = 0;

// Once per growth: the advice is a hint, and a refusal (a range the kernel will not mark)
// would be refused again.
void markHeap() {
  const auto top = reinterpret_cast<std::uintptr_t>(sbrk(0));
  if (top <= markedTop)
    return;
  madvise(reinterpret_cast<void*>(heapBase), top - heapBase, MADV_HUGEPAGE);
  markedTop = top;
}

void markHeapOnAllocation(Kokkos_Profiling_SpaceHandle, const char*, const void*, uint64_t) {
  markHeap();
}

bool hugePagesOff() {
  std::ifstream in("/sys/kernel/mm/transparent_hugepage/enabled");
  std::string modes;
  std::getline(in, modes);
  return !in || modes.find("[never]") != std::string::npos;
}

}  // namespace
#endif

bool adviseHugePages() {
#if defined(IMPM_HEAP_ADVICE)
  if (heapBase != 0)
    return true;
  if (hugePagesOff() || Kokkos::Tools::profileLibraryLoaded())
    return false;
  const long page = sysconf(_SC_PAGESIZE);
  heapBase = reinterpret_cast<std::uintptr_t>(sbrk(0)) & ~static_cast<std::uintptr_t>(page - 1);
  markedTop = heapBase;
  mallopt(M_TOP_PAD, 64 << 20);
  Kokkos::Tools::Experimental::set_allocate_data_callback(markHeapOnAllocation);
  return true;
#else
  return false;
#endif
}

}  // namespace impm
