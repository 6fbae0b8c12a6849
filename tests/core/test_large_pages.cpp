// AllocateLarge and the UninitializedAllocator built on it: large blocks are 2 MiB aligned (so
// that huge pages can back them), every byte is usable, and vectors keep their contents while
// growing across the threshold.
#include "large_pages.h"
#include "uninitialized_allocator.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <cstdlib>
#include <cstring>

using namespace tessera;

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
