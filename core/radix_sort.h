#pragma once
// LSD radix sorts of 64-bit words by a run of their bits (a key packed above an id: half the memory
// traffic of keys and ids side by side). Stable: words of equal keys keep their order, so the
// result depends on the words alone, never on the number of threads.

#include "uninitialized_allocator.h"

#include <cstddef>
#include <cstdint>

namespace tessera
{

/// items sorted by bits [lowBit, lowBit + bits) of each word (lowBit + bits <= 64; the bits above
/// are 0, as a packed key's are, for the last pass may read some of them), stably, in passes of at
/// most 11 bits. On the cores from 500,000 items (RadixSortPackedInChunks), serially
/// below, where one read of the items counts every pass's digits.
///
/// Why on the cores: at 10^7 points BrioHilbertOrder took 0.42 s with a serial sort (the other
/// core idle) and 0.18-0.24 s in chunks, and the batch build 6% less time (median of 8
/// alternating runs; 1% at 10^6).
void RadixSortPacked(UninitializedVector<std::uint64_t>& items, int lowBit, int bits);

/// The same in `chunks` contiguous chunks (at most one per item), each pass counted and moved by
/// chunk on the cores (parallel_chunks.h): the same order as the serial sort for any number of
/// chunks.
void RadixSortPackedInChunks(UninitializedVector<std::uint64_t>& items,
  int lowBit,
  int bits,
  std::size_t chunks);

} // namespace tessera
