// AllocateLarge: aligned_alloc plus madvise(MADV_HUGEPAGE) (see large_pages.h for why), and the
// blocks ReuseLargeBlocks keeps.
#include "large_pages.h"

#include <cstdint>
#include <cstdlib>
#include <mutex>
#include <new>
#include <vector>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace tessera
{
namespace
{
constexpr std::size_t HugePage = std::size_t(2) << 20;

std::size_t RoundedToHugePages(std::size_t bytes)
{
  if (bytes > std::size_t(-1) - HugePage)
  {
    throw std::bad_alloc();
  }
  return (bytes + HugePage - 1) / HugePage * HugePage;
}

struct KeptBlock
{
  void* Memory;
  std::size_t Bytes; // rounded
};

struct BlockStore
{
  std::mutex Lock;
  int Scopes = 0;
  std::vector<KeptBlock> Kept;
};

BlockStore& Store()
{
  static BlockStore store;
  return store;
}

// The smallest kept block of rounded bytes or more, and at most an eighth more; null if none.
void* TakeKeptBlock(std::size_t rounded)
{
  BlockStore& store = Store();
  std::lock_guard<std::mutex> hold(store.Lock);
  std::size_t best = store.Kept.size();
  for (std::size_t k = 0; k < store.Kept.size(); ++k)
  {
    const std::size_t size = store.Kept[k].Bytes;
    if (size >= rounded && size - rounded <= rounded / 8 &&
      (best == store.Kept.size() || size < store.Kept[best].Bytes))
    {
      best = k;
    }
  }
  if (best == store.Kept.size())
  {
    return nullptr;
  }
  void* memory = store.Kept[best].Memory;
  store.Kept[best] = store.Kept.back();
  store.Kept.pop_back();
  return memory;
}
} // namespace

ReuseLargeBlocks::ReuseLargeBlocks()
{
  BlockStore& store = Store();
  std::lock_guard<std::mutex> hold(store.Lock);
  ++store.Scopes;
}

ReuseLargeBlocks::~ReuseLargeBlocks()
{
  std::vector<KeptBlock> kept;
  {
    BlockStore& store = Store();
    std::lock_guard<std::mutex> hold(store.Lock);
    if (--store.Scopes == 0)
    {
      kept.swap(store.Kept);
    }
  }
  for (const KeptBlock& block : kept)
  {
    std::free(block.Memory);
  }
}

std::size_t KeptLargeBlockBytes()
{
  BlockStore& store = Store();
  std::lock_guard<std::mutex> hold(store.Lock);
  std::size_t bytes = 0;
  for (const KeptBlock& block : store.Kept)
  {
    bytes += block.Bytes;
  }
  return bytes;
}

void ReleaseLarge(void* memory, std::size_t bytes) noexcept
{
  if (memory && bytes >= LargePageBytes)
  {
    BlockStore& store = Store();
    std::lock_guard<std::mutex> hold(store.Lock);
    if (store.Scopes > 0)
    {
      try
      {
        store.Kept.push_back({ memory, RoundedToHugePages(bytes) });
        return;
      }
      catch (...)
      {
        // no room to keep it: freed below
      }
    }
  }
  std::free(memory);
}

// Moves glibc's dynamic mmap threshold to its ceiling, once per process, so that freed large
// blocks go back to the heap and are reused by the next derivation instead of being unmapped.
//
// Why. glibc serves a block above its mmap threshold (128 KiB at start) by a fresh mmap, and
// unmaps it when freed; each derivation then touches fresh pages again, a page fault per page.
// glibc raises the threshold to the size of each mmapped block freed (up to 32 MiB on 64-bit
// systems, mallopt(3)), and the trim threshold to twice that, so a program that frees one large
// block soon reuses its heap for everything smaller. Huge-page blocks, 2 MiB aligned, never got
// there: aligned_alloc asks for twice the alignment, more than the threshold their own frees
// set, so every one was a fresh mapping. At 10^4 points the tiles filter mapped, faulted and
// unmapped three 4 MiB blocks per run: 0.59-0.68 us/pt, against 0.47-0.55 with this, in
// alternating runs.
//
// The cost: up to 62 MiB of freed memory at the top of the heap stays with the process, as it
// would after the process freed any 31 MiB block. A threshold fixed by mallopt (or
// MALLOC_MMAP_THRESHOLD_) is left alone: glibc then ignores frees, and so this one.
void RaiseMallocThresholdOnce()
{
#if defined(__GLIBC__)
  static const bool raised = []()
  {
    // The compiler may drop a malloc whose block is never used: the volatile keeps this one.
    void* volatile block = std::malloc(std::size_t(31) << 20);
    std::free(block);
    return true;
  }();
  (void)raised;
#endif
}

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
  const std::size_t rounded = RoundedToHugePages(bytes);
  if (void* kept = TakeKeptBlock(rounded))
  {
    return kept;
  }
  RaiseMallocThresholdOnce();
  void* memory = std::aligned_alloc(HugePage, rounded);
  if (!memory)
  {
    throw std::bad_alloc();
  }
  if (rounded <= HugePageAdviceLimit)
  {
    AdviseLargePages(memory, rounded); // the whole block: it is aligned and rounded
  }
  return memory;
}

} // namespace tessera
