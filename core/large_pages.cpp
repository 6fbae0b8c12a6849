// AllocateLarge: aligned_alloc plus madvise(MADV_HUGEPAGE) (see large_pages.h for why).
#include "large_pages.h"

#include <cstdlib>
#include <new>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace tessera
{

void* AllocateLarge(std::size_t bytes)
{
  constexpr std::size_t HugePage = std::size_t(2) << 20;
  if (bytes < LargePageBytes)
  {
    void* memory = std::malloc(bytes == 0 ? 1 : bytes);
    if (!memory)
    {
      throw std::bad_alloc();
    }
    return memory;
  }
  // aligned_alloc wants a multiple of the alignment; the whole rounded range is advised.
  if (bytes > std::size_t(-1) - HugePage)
  {
    throw std::bad_alloc();
  }
  const std::size_t rounded = (bytes + HugePage - 1) / HugePage * HugePage;
  void* memory = std::aligned_alloc(HugePage, rounded);
  if (!memory)
  {
    throw std::bad_alloc();
  }
#if defined(__linux__) && defined(MADV_HUGEPAGE)
  // Advice only: where huge pages are off or none is free, the pages are ordinary ones.
  madvise(memory, rounded, MADV_HUGEPAGE);
#endif
  return memory;
}

} // namespace tessera
