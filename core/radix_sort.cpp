// RadixSortPacked and RadixSortPackedInChunks: LSD radix sorts of 64-bit words by a run of their
// bits, on one thread or in contiguous chunks on the cores.
#include "radix_sort.h"

#include "parallel_chunks.h"

#include <algorithm>

namespace tessera
{
namespace
{
constexpr int MaxDigitBits = 11;

// The digits of a sort: as wide as the fewest passes of at most MaxDigitBits bits allow.
struct PackedDigits
{
  PackedDigits(int lowBit, int bits)
    : LowBit(lowBit)
    , Passes((bits + MaxDigitBits - 1) / MaxDigitBits)
    , Bits(this->Passes > 0 ? (bits + this->Passes - 1) / this->Passes : 0)
    , Buckets(std::size_t(1) << this->Bits)
  {
  }

  std::size_t Of(std::uint64_t item, int pass) const
  {
    return std::size_t((item >> (this->LowBit + pass * this->Bits)) & (this->Buckets - 1));
  }

  int LowBit, Passes, Bits;
  std::size_t Buckets;
};

/// Turns counts into the first output slot of each digit, in place.
void ExclusiveSums(std::size_t* counts, std::size_t size)
{
  std::size_t sum = 0;
  for (std::size_t k = 0; k < size; ++k)
  {
    const std::size_t here = counts[k];
    counts[k] = sum;
    sum += here;
  }
}

// On one thread: every pass's digits counted in one read of the items.
void SortSerially(UninitializedVector<std::uint64_t>& items, const PackedDigits& digits)
{
  std::vector<std::size_t> count(digits.Buckets * std::size_t(digits.Passes), 0);
  for (const std::uint64_t item : items)
  {
    for (int pass = 0; pass < digits.Passes; ++pass)
    {
      ++count[std::size_t(pass) * digits.Buckets + digits.Of(item, pass)];
    }
  }
  UninitializedVector<std::uint64_t> buffer(items.size());
  for (int pass = 0; pass < digits.Passes; ++pass)
  {
    std::size_t* const c = count.data() + std::size_t(pass) * digits.Buckets;
    ExclusiveSums(c, digits.Buckets);
    std::uint64_t* const out = buffer.data();
    for (const std::uint64_t item : items)
    {
      out[c[digits.Of(item, pass)]++] = item;
    }
    items.swap(buffer);
  }
}

// Each pass, each chunk counts its digits, and then moves its items to the slots after those of
// the same digit in earlier chunks. That is where the serial pass puts them, so the order is the
// same for any number of chunks.
//
//   chunk 0: a1 b1 a2 | chunk 1: b2 a3     digit a: a1 a2 (chunk 0) a3 (chunk 1)
//                                          digit b: b1 (chunk 0) b2 (chunk 1)
void SortInChunks(UninitializedVector<std::uint64_t>& items,
  const PackedDigits& digits,
  const std::vector<std::int32_t>& bounds)
{
  const std::size_t chunks = bounds.size() - 1;
  std::vector<std::size_t> slots(chunks * digits.Buckets);
  UninitializedVector<std::uint64_t> buffer(items.size());
  for (int pass = 0; pass < digits.Passes; ++pass)
  {
    parallel::RunChunks(chunks,
      [&](std::size_t c)
      {
        std::size_t* const count = slots.data() + c * digits.Buckets;
        std::fill(count, count + digits.Buckets, std::size_t(0));
        for (std::int32_t k = bounds[c]; k < bounds[c + 1]; ++k)
        {
          ++count[digits.Of(items[k], pass)];
        }
      });
    std::size_t sum = 0;
    for (std::size_t digit = 0; digit < digits.Buckets; ++digit)
    {
      for (std::size_t c = 0; c < chunks; ++c)
      {
        std::size_t& slot = slots[c * digits.Buckets + digit];
        const std::size_t here = slot;
        slot = sum;
        sum += here;
      }
    }
    parallel::RunChunks(chunks,
      [&](std::size_t c)
      {
        std::size_t* const slot = slots.data() + c * digits.Buckets;
        std::uint64_t* const out = buffer.data();
        for (std::int32_t k = bounds[c]; k < bounds[c + 1]; ++k)
        {
          const std::uint64_t item = items[k];
          out[slot[digits.Of(item, pass)]++] = item;
        }
      });
    items.swap(buffer);
  }
}

} // namespace

void RadixSortPacked(UninitializedVector<std::uint64_t>& items, int lowBit, int bits)
{
  const std::size_t threads = parallel::ThreadCount(std::int64_t(items.size()), 250000);
  const PackedDigits digits(lowBit, bits);
  if (threads > 1)
  {
    RadixSortPackedInChunks(items, lowBit, bits, threads);
  }
  else if (digits.Passes > 0)
  {
    SortSerially(items, digits);
  }
}

void RadixSortPackedInChunks(UninitializedVector<std::uint64_t>& items,
  int lowBit,
  int bits,
  std::size_t chunks)
{
  const PackedDigits digits(lowBit, bits);
  if (digits.Passes > 0 && !items.empty())
  {
    const std::size_t parts = std::max<std::size_t>(1, std::min(chunks, items.size()));
    SortInChunks(items, digits, parallel::ChunkBounds(std::int32_t(items.size()), parts));
  }
}

} // namespace tessera
