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
#include <unistd.h>
#endif

namespace tessera
{
namespace
{

std::size_t RoundedToHugePages(std::size_t bytes)
{
  if (bytes > std::size_t(-1) - HugePageBytes)
  {
    throw std::bad_alloc();
  }
  return (bytes + HugePageBytes - 1) / HugePageBytes * HugePageBytes;
}

struct KeptBlock
{
  void* Memory;
  std::size_t Bytes; // rounded
};

// Kept blocks, oldest first.
struct BlockStore
{
  std::mutex Lock;
  int Scopes = 0;
  std::vector<KeptBlock> Kept;
  std::size_t KeptBytes = 0;
};

// Never destroyed: a vector with static storage may give its block back while the program exits.
BlockStore& Store()
{
  static BlockStore& store = *new BlockStore;
  return store;
}

// At most this many bytes are kept (the oldest blocks go first): scopes that overlap on several
// threads may keep the store open for good, and blocks of sizes no one asks for again must not
// pile up meanwhile. An eighth of the machine's memory (2 GiB where it is unknown).
std::size_t KeptBytesLimit()
{
  static const std::size_t limit = []()
  {
    std::size_t bytes = std::size_t(16) << 30;
#if defined(__linux__)
    const long pages = sysconf(_SC_PHYS_PAGES), pageSize = sysconf(_SC_PAGESIZE);
    if (pages > 0 && pageSize > 0)
    {
      bytes = std::size_t(pages) * std::size_t(pageSize);
    }
#endif
    return bytes / 8;
  }();
  return limit;
}

// Whether a block of bytes (or of bytes rounded to huge pages: the limit is a multiple of them) is
// one the store keeps: one above HugePageAdviceLimit. Below, glibc's heap keeps freed blocks
// anyway (RaiseMallocThresholdOnce), and so a kept block always has the advice its size calls for.
bool Keepable(std::size_t bytes)
{
  return bytes > HugePageAdviceLimit;
}

// The smallest kept block of rounded bytes or more, and at most an eighth more; null if none.
void* TakeKeptBlock(std::size_t rounded)
{
  if (!Keepable(rounded))
  {
    return nullptr;
  }
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
  store.KeptBytes -= store.Kept[best].Bytes;
  store.Kept.erase(store.Kept.begin() + std::ptrdiff_t(best));
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
      store.KeptBytes = 0;
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
  return store.KeptBytes;
}

void ReleaseLarge(void* memory, std::size_t bytes) noexcept
{
  if (memory && Keepable(bytes))
  {
    BlockStore& store = Store();
    std::lock_guard<std::mutex> hold(store.Lock);
    if (store.Scopes > 0)
    {
      try
      {
        store.Kept.push_back({ memory, RoundedToHugePages(bytes) });
      }
      catch (...)
      {
        std::free(memory); // no room to keep it
        return;
      }
      store.KeptBytes += store.Kept.back().Bytes;
      std::size_t oldest = 0;
      while (store.KeptBytes > KeptBytesLimit())
      {
        store.KeptBytes -= store.Kept[oldest].Bytes;
        std::free(store.Kept[oldest++].Memory);
      }
      store.Kept.erase(store.Kept.begin(), store.Kept.begin() + std::ptrdiff_t(oldest));
      return;
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
    void* volatile block = std::malloc(RaisedMallocThreshold);
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
  if (!begin || bytes < HugePageBytes || bytes > std::uintptr_t(-1) - at)
  {
    return; // nothing whole inside, or a range that would wrap (then at + HugePageBytes cannot)
  }
  const std::uintptr_t first = (at + HugePageBytes - 1) & ~std::uintptr_t(HugePageBytes - 1);
  const std::uintptr_t end = (at + bytes) & ~std::uintptr_t(HugePageBytes - 1);
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
  void* memory = std::aligned_alloc(HugePageBytes, rounded);
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
