// RadixSortPacked and RadixSortPackedInChunks against std::stable_sort by the same bits: words
// whose keys repeat (so that stability shows in the order of their other bits), keys of one to
// three passes, and any number of chunks, more than there are words included.
#include "radix_sort.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <random>
#include <vector>

using namespace tessera;

namespace
{
/// n words: a key in bits [lowBit, lowBit + bits), drawn from 4000 values so that keys repeat,
/// with random bits below it and zeros above it.
UninitializedVector<std::uint64_t> Words(std::size_t n, int lowBit, int bits, std::uint64_t seed)
{
  std::mt19937_64 rng(seed);
  const std::uint64_t keyMask = bits >= 64 ? ~std::uint64_t(0) : (std::uint64_t(1) << bits) - 1;
  const std::uint64_t lowMask = lowBit == 0 ? 0 : (std::uint64_t(1) << lowBit) - 1;
  std::vector<std::uint64_t> keys(4000);
  for (std::uint64_t& key : keys)
  {
    key = rng() & keyMask;
  }
  UninitializedVector<std::uint64_t> words(n);
  for (std::uint64_t& word : words)
  {
    word = (keys[rng() % keys.size()] << lowBit) | (rng() & lowMask);
  }
  return words;
}

/// words stably sorted by their key bits, by the standard library.
UninitializedVector<std::uint64_t> StableSorted(UninitializedVector<std::uint64_t> words,
  int lowBit,
  int bits)
{
  const auto key = [&](std::uint64_t word)
  { return bits == 0 ? 0 : (word >> lowBit) & (~std::uint64_t(0) >> (64 - bits)); };
  std::stable_sort(
    words.begin(), words.end(), [&](std::uint64_t a, std::uint64_t b) { return key(a) < key(b); });
  return words;
}
} // namespace

TEST(RadixSort, SortsStablyByTheKeyBitsInAnyNumberOfChunks)
{
  struct Case
  {
    int LowBit, Bits;
  };
  // 3 passes of 11 bits (BRIO keys at 10^7 points), 3 of 8, 1 of 11, 1 of 1, and a key up to
  // bit 63.
  for (const Case c :
    { Case{ 20, 31 }, Case{ 5, 23 }, Case{ 0, 11 }, Case{ 7, 1 }, Case{ 33, 31 } })
  {
    const UninitializedVector<std::uint64_t> words = Words(100003, c.LowBit, c.Bits, 17);
    const UninitializedVector<std::uint64_t> expected = StableSorted(words, c.LowBit, c.Bits);
    ASSERT_NE(words, expected) << "the words must not be in order already";
    UninitializedVector<std::uint64_t> sorted = words;
    RadixSortPacked(sorted, c.LowBit, c.Bits);
    EXPECT_EQ(sorted, expected) << "serial, key bits " << c.LowBit << " + " << c.Bits;
    for (const std::size_t chunks : { 1, 2, 3, 7 })
    {
      UninitializedVector<std::uint64_t> inChunks = words;
      RadixSortPackedInChunks(inChunks, c.LowBit, c.Bits, chunks);
      EXPECT_EQ(inChunks, expected)
        << chunks << " chunks, key bits " << c.LowBit << " + " << c.Bits;
    }
  }
}

TEST(RadixSort, FewWordsAndNoKeyBits)
{
  for (const std::size_t n : { 0, 1, 5 })
  {
    const UninitializedVector<std::uint64_t> words = Words(n, 4, 31, 3);
    UninitializedVector<std::uint64_t> inChunks = words;
    RadixSortPackedInChunks(inChunks, 4, 31, 7); // more chunks than words
    EXPECT_EQ(inChunks, StableSorted(words, 4, 31)) << n << " words";
  }
  // No key bits: nothing to sort by, the order stays.
  const UninitializedVector<std::uint64_t> words = Words(1000, 10, 20, 5);
  UninitializedVector<std::uint64_t> same = words;
  RadixSortPacked(same, 10, 0);
  EXPECT_EQ(same, words);
  RadixSortPackedInChunks(same, 10, 0, 3);
  EXPECT_EQ(same, words);
}
