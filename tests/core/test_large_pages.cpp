// AllocateLarge and the UninitializedAllocator built on it: large blocks are 2 MiB aligned (so
// that huge pages can back them), every byte is usable, and vectors keep their contents while
// growing across the threshold.
#include "large_pages.h"
#include "uninitialized_allocator.h"
#include "geometry.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iterator>
#include <string>
#include <type_traits>
#include <vector>

#include <sys/mman.h>
#include <sys/resource.h>

using namespace tessera;

// A build of 10^4 points makes vectors of 40-240 KiB at once, below LargePageBytes, the larger ones
// above glibc's first mmap threshold (128 KiB). glibc raises that threshold to the largest such
// block freed, and its trim threshold to twice that: the blocks then come from the heap, but once
// freed together they are more than the trim threshold at the heap's top, which goes back to the
// system, and every 4 KiB of them faults again at the next build (some 160 faults a round here),
// unless ReserveOnLargePages has raised the thresholds to their ceilings. ctest also runs this test
// alone (core.test_large_pages.fresh_process), in a process where nothing raised them before.
TEST(LargePages, SmallVectorsReservedOnLargePagesAreReusedWithoutNewPageFaults)
{
#if !defined(__GLIBC__) || defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
  GTEST_SKIP() << "glibc's own malloc only (a sanitizer's allocator holds freed blocks back)";
#else
  const std::vector<std::size_t> kibs{ 40, 80, 160, 240, 240 }; // a build's, at 10^4 points
  const auto writeAndFree = [&]()
  {
    std::vector<std::vector<std::int32_t>> arrays(kibs.size());
    std::int64_t sum = 0;
    for (std::size_t k = 0; k < kibs.size(); ++k)
    {
      ResizeOnLargePages(arrays[k], (kibs[k] << 10) / sizeof(std::int32_t));
      std::fill(arrays[k].begin(), arrays[k].end(), 7);
      sum += arrays[k].back();
    }
    return sum;
  };
  writeAndFree(); // the first ones may map and fault
  constexpr int Rounds = 20;
  rusage before{}, after{};
  ASSERT_EQ(getrusage(RUSAGE_SELF, &before), 0);
  std::int64_t sum = 0;
  for (int round = 0; round < Rounds; ++round)
  {
    sum += writeAndFree();
  }
  ASSERT_EQ(getrusage(RUSAGE_SELF, &after), 0);
  EXPECT_EQ(sum, 7 * 5 * Rounds);
  EXPECT_LT(after.ru_minflt - before.ru_minflt, Rounds);
#endif
}

TEST(LargePages, BlocksAreUsableAndLargeOnesAligned)
{
  constexpr std::uintptr_t HugePage = std::uintptr_t(2) << 20;
  for (const std::size_t bytes : { std::size_t(0),
         std::size_t(1),
         LargePageBytes - 1,
         LargePageBytes,
         LargePageBytes + 1,
         3 * LargePageBytes + 12345 })
  {
    auto* block = static_cast<unsigned char*>(AllocateLarge(bytes));
    ASSERT_NE(block, nullptr) << bytes;
    if (bytes >= LargePageBytes)
    {
      EXPECT_EQ(reinterpret_cast<std::uintptr_t>(block) % HugePage, 0u) << bytes;
    }
    std::memset(block, 0xA5, bytes);
    std::size_t wrong = 0;
    for (std::size_t k = 0; k < bytes; ++k)
    {
      wrong += block[k] != 0xA5;
    }
    EXPECT_EQ(wrong, 0u) << bytes;
    std::free(block);
  }
}

TEST(LargePages, VectorsKeepTheirContentsWhileGrowingPastTheThreshold)
{
  UninitializedVector<std::int32_t> values;
  const std::int32_t count = std::int32_t(3 * LargePageBytes / sizeof(std::int32_t));
  for (std::int32_t k = 0; k < count; ++k)
  {
    values.push_back(k);
  }
  values.resize(values.size() + 1000); // left unwritten, then written
  for (std::size_t k = std::size_t(count); k < values.size(); ++k)
  {
    values[k] = -1;
  }
  std::int64_t wrong = 0;
  for (std::int32_t k = 0; k < count; ++k)
  {
    wrong += values[k] != k;
  }
  EXPECT_EQ(wrong, 0);
  EXPECT_EQ(values.back(), -1);
  // The vector's block came from AllocateLarge (its rebind and allocate are the allocator's own).
  ASSERT_GE(values.capacity() * sizeof(std::int32_t), LargePageBytes);
  EXPECT_EQ(reinterpret_cast<std::uintptr_t>(values.data()) % (std::uintptr_t(2) << 20), 0u);
  UninitializedVector<std::int32_t> copy(values.begin(), values.end());
  EXPECT_TRUE(copy == values);
}

// Each derivation frees its large blocks and the next one asks for them again: they must come back
// from the heap, not as fresh mappings whose every page faults again (glibc served every 2 MiB
// aligned block by a mapping of its own before AllocateLarge raised its mmap threshold). Counted
// in minor page faults: a block of 3 MiB written in full is at least one fault on huge pages and
// 768 on 4 KiB ones, each time it is mapped afresh.
TEST(LargePages, FreedLargeBlocksAreReusedWithoutNewPageFaults)
{
#if !defined(__GLIBC__) || defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
  GTEST_SKIP() << "glibc's own malloc only (a sanitizer's allocator holds freed blocks back)";
#else
  // Also the largest block on huge pages: with the 2 MiB aligned_alloc adds to align it, it
  // must stay below glibc's mmap threshold, or it is mapped afresh each time (blocks of 30 and
  // 32 MiB were, and faulted 15-16 huge pages a round). Where earlier tests left the heap
  // fragmented, its 14 huge pages can shift by one now and then (26 faults in 20 rounds after
  // this file's other tests): the bound is half of its huge pages a round, a fresh mapping all.
  for (const std::size_t bytes : { std::size_t(3) << 20, HugePageAdviceLimit })
  {
    const auto writeAndFree = [bytes]()
    {
      void* block = AllocateLarge(bytes);
      std::memset(block, 0x5A, bytes);
      std::free(block);
    };
    writeAndFree(); // the first ones may map and fault
    writeAndFree();
    constexpr int Rounds = 20;
    rusage before{}, after{};
    ASSERT_EQ(getrusage(RUSAGE_SELF, &before), 0);
    for (int round = 0; round < Rounds; ++round)
    {
      writeAndFree();
    }
    ASSERT_EQ(getrusage(RUSAGE_SELF, &after), 0);
    const long hugePages = long(bytes / HugePageBytes);
    EXPECT_LT(after.ru_minflt - before.ru_minflt, Rounds * std::max(1L, hugePages / 2))
      << bytes << " bytes";
  }
#endif
}

namespace
{
/// The VmFlags of the mapping that holds address (Linux /proc/self/smaps); empty where unknown.
std::string MappingFlags(const void* address)
{
  std::ifstream smaps("/proc/self/smaps");
  const std::uintptr_t at = reinterpret_cast<std::uintptr_t>(address);
  std::string line;
  bool inside = false;
  while (std::getline(smaps, line))
  {
    unsigned long long begin = 0, end = 0;
    if (std::sscanf(line.c_str(), "%llx-%llx ", &begin, &end) == 2 && line.find('-') < 17)
    {
      inside = begin <= at && at < end;
    }
    else if (inside && line.rfind("VmFlags:", 0) == 0)
    {
      return line;
    }
  }
  return {};
}

bool HugePagesOnRequest()
{
  std::ifstream mode("/sys/kernel/mm/transparent_hugepage/enabled");
  std::string text((std::istreambuf_iterator<char>(mode)), std::istreambuf_iterator<char>());
  return text.find("[madvise]") != std::string::npos || text.find("[always]") != std::string::npos;
}
} // namespace

TEST(LargePages, ResizeOnLargePagesKeepsVectorSemantics)
{
  std::vector<std::int32_t> values{ 7, 8, 9 };
  const std::size_t n = 5 * (std::size_t(2) << 20) / sizeof(std::int32_t); // 10 MiB
  ResizeOnLargePages(values, n);
  ASSERT_EQ(values.size(), n);
  EXPECT_EQ(values[0], 7);
  EXPECT_EQ(values[2], 9);
  std::size_t nonZero = 0;
  for (std::size_t k = 3; k < n; ++k)
  {
    nonZero += values[k] != 0;
  }
  EXPECT_EQ(nonZero, 0u);        // new elements value-initialised, as resize() makes them
  ResizeOnLargePages(values, 2); // shrinking: plain resize
  EXPECT_EQ(values.size(), 2u);
  EXPECT_EQ(values[1], 8);
  // Nothing to advise, or nothing whole inside: no effect, no failure.
  AdviseLargePages(nullptr, 1 << 24);
  AdviseLargePages(values.data(), 0);
  AdviseLargePages(reinterpret_cast<const char*>(values.data()) + 1, 12345);
}

TEST(LargePages, AssignAndReserveOnLargePagesKeepVectorSemantics)
{
  std::vector<std::int32_t> values{ 7, 8, 9 };
  const std::size_t n = 5 * (std::size_t(2) << 20) / sizeof(std::int32_t);
  AssignOnLargePages(values, n, std::int32_t(-1));
  ASSERT_EQ(values.size(), n);
  EXPECT_EQ(std::count(values.begin(), values.end(), -1), std::ptrdiff_t(n)); // old ones too
  AssignOnLargePages(values, 4, std::int32_t(5));                             // within the capacity
  EXPECT_EQ(values, std::vector<std::int32_t>(4, 5));
  std::vector<std::int32_t> reserved{ 1 };
  ReserveOnLargePages(reserved, n);
  EXPECT_GE(reserved.capacity(), n);
  EXPECT_EQ(reserved, std::vector<std::int32_t>{ 1 }); // contents kept, nothing added
}

TEST(LargePages, ResizeOnLargePagesAdvisesTheWholeHugePagesInside)
{
  if (!HugePagesOnRequest())
  {
    GTEST_SKIP() << "transparent huge pages are not offered on request here";
  }
  std::vector<double> values;
  ResizeOnLargePages(values, std::size_t(3) << 20); // 24 MiB: whole 2 MiB pages inside
  const std::string middle = MappingFlags(values.data() + values.size() / 2);
  ASSERT_FALSE(middle.empty()) << "no mapping found for the vector's storage";
  EXPECT_NE(middle.find(" hg"), std::string::npos) << middle;
  // So is storage reserved for elements pushed later.
  std::vector<double> pushed;
  ReserveOnLargePages(pushed, std::size_t(3) << 20);
  const std::string reservedFlags = MappingFlags(pushed.data() + (std::size_t(3) << 19));
  EXPECT_NE(reservedFlags.find(" hg"), std::string::npos) << reservedFlags;
  // A plain mapping of the same size is not advised (the check can tell the two apart). Not a
  // plain vector: the heap may place it where an earlier test's advised block was.
  const std::size_t plainBytes = std::size_t(24) << 20;
  void* plain =
    mmap(nullptr, plainBytes, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
  ASSERT_NE(plain, MAP_FAILED);
  const std::string plainFlags = MappingFlags(static_cast<char*>(plain) + plainBytes / 2);
  munmap(plain, plainBytes);
  EXPECT_EQ(plainFlags.find(" hg"), std::string::npos) << plainFlags;
}

TEST(LargePages, AllocateLargeAdvisesHugePagesUpToTheLimitOnly)
{
  if (!HugePagesOnRequest())
  {
    GTEST_SKIP() << "transparent huge pages are not offered on request here";
  }
  const std::size_t within = std::size_t(8) << 20;
  const std::size_t beyond = HugePageAdviceLimit + (std::size_t(4) << 20);
  auto* small = static_cast<char*>(AllocateLarge(within));
  auto* large = static_cast<char*>(AllocateLarge(beyond));
  const std::string smallFlags = MappingFlags(small + within / 2);
  const std::string largeFlags = MappingFlags(large + beyond / 2);
  std::free(small);
  std::free(large);
  ASSERT_FALSE(smallFlags.empty() || largeFlags.empty()) << "no mapping found for the blocks";
  EXPECT_NE(smallFlags.find(" hg"), std::string::npos) << smallFlags;
  EXPECT_EQ(largeFlags.find(" hg"), std::string::npos) << largeFlags;
}

// Inside a scope a released block above HugePageAdviceLimit goes to the next request of about its
// size (and not to a much smaller one); a smaller block is freed at once (the heap keeps those);
// an inner scope's end keeps the blocks while the outer lives; the outer's frees them. Outside
// every scope ReleaseLarge frees at once. (The blocks are never written: no memory is touched.)
TEST(LargePages, ReuseScopeHandsReleasedBlocksOutAgainUntilItEnds)
{
  constexpr std::size_t MiB = std::size_t(1) << 20;
  const std::size_t big = HugePageAdviceLimit + 8 * MiB;
  ASSERT_EQ(KeptLargeBlockBytes(), 0u);
  {
    const ReuseLargeBlocks outer;
    void* first = AllocateLarge(big - MiB);
    ReleaseLarge(first, big - MiB);
    EXPECT_EQ(KeptLargeBlockBytes(), big); // rounded to whole huge pages
    void* within = AllocateLarge(4 * MiB);
    ReleaseLarge(within, 4 * MiB);
    EXPECT_EQ(KeptLargeBlockBytes(), big); // not kept
    // More than an eighth smaller: a fresh block, not the kept one.
    void* smaller = AllocateLarge(HugePageAdviceLimit + 2 * MiB);
    EXPECT_NE(smaller, first);
    ReleaseLarge(smaller, HugePageAdviceLimit + 2 * MiB);
    EXPECT_EQ(KeptLargeBlockBytes(), big + HugePageAdviceLimit + 2 * MiB);
    {
      const ReuseLargeBlocks inner;
      void* again = AllocateLarge(big - 2 * MiB);
      EXPECT_EQ(again, first);
      EXPECT_EQ(KeptLargeBlockBytes(), HugePageAdviceLimit + 2 * MiB);
      ReleaseLarge(again, big - 2 * MiB); // kept as a block of the size last asked for
    }
    EXPECT_EQ(KeptLargeBlockBytes(), big + HugePageAdviceLimit);
    {
      // A vector's block goes the same way (UninitializedAllocator::deallocate releases it).
      UninitializedVector<std::int32_t> values((big - 2 * MiB) / sizeof(std::int32_t));
      EXPECT_EQ(static_cast<void*>(values.data()), first);
    }
    EXPECT_EQ(KeptLargeBlockBytes(), big + HugePageAdviceLimit);
  }
  EXPECT_EQ(KeptLargeBlockBytes(), 0u);
  void* outside = AllocateLarge(big);
  ReleaseLarge(outside, big);
  EXPECT_EQ(KeptLargeBlockBytes(), 0u);
  ReleaseLarge(nullptr, big); // like std::free(nullptr)
}

// resize() writes nothing for a trivially copyable type, even one with default member
// initialisers (Point2's zeros): a fresh block of 128 MiB, beyond HugePageAdviceLimit, is not
// touched (a zero fill would make 32768 faults on 4 KiB pages, 64 where all memory is on huge
// pages), and the elements written afterwards read back.
TEST(LargePages, ResizeWritesNothingForPoint2)
{
#if !defined(__GLIBC__) || defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
  GTEST_SKIP() << "glibc's own malloc only (a sanitizer's allocator may touch its blocks)";
#else
  static_assert(!std::is_trivially_default_constructible_v<Point2>, "Point2 zero-initialises");
  const std::size_t count = (std::size_t(128) << 20) / sizeof(Point2);
  UninitializedVector<Point2> points;
  points.reserve(count);
  rusage before{}, after{};
  ASSERT_EQ(getrusage(RUSAGE_SELF, &before), 0);
  points.resize(count);
  ASSERT_EQ(getrusage(RUSAGE_SELF, &after), 0);
  EXPECT_LT(after.ru_minflt - before.ru_minflt, 16);
  points[0] = { 1.0, 2.0 };
  points[count - 1] = { 3.0, 4.0 };
  EXPECT_EQ(points.front().y + points.back().x, 5.0);
  std::vector<Point2> plain(2); // a std::vector still zero-initialises
  EXPECT_EQ(plain[1].x + plain[1].y, 0.0);
#endif
}
