// AllocateLarge: aligned_alloc plus madvise(MADV_HUGEPAGE) (see large_pages.h for why).
#include "large_pages.h"

#include <cstdint>
#include <cstdlib>
#include <new>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace tessera
{
namespace
{
constexpr std::size_t HugePage = std::size_t(2) << 20;
} // namespace

void AdviseLargePages(const void* begin, std::size_t bytes)
{
#if defined(__linux__) && defined(MADV_HUGEPAGE)
  const std::uintptr_t at = reinterpret_cast<std::uintptr_t>(begin);
  if (!begin || bytes < HugePage || bytes > std::uintptr_t(-1) - at)
  {
    return; // nothing whole inside, or a range that would wrap (then at + HugePage cannot)
  }
  const std::uintptr_t first = (at + HugePage - 1) & ~std::uintptr_t(HugePage - 1);
  const std::uintptr_t end = (at + bytes) & ~std::uintptr_t(HugePage - 1);
  if (end > first)
  {
    // Advice only: a range the system cannot back by huge pages keeps ordinary ones.
    madvise(reinterpret_cast<void*>(first), end - first, MADV_HUGEPAGE);
  }
#else
  (void)begin;
  (void)bytes;
#endif
}

void* AllocateLarge(std::size_t bytes)
{
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
  AdviseLargePages(memory, rounded); // the whole block: it is aligned and rounded
  return memory;
}

} // namespace tessera
