#pragma once
// Internal: per-thread state kept on cache lines of its own.
//
// Two threads that write one cache line take it from each other at every write, even when they
// write different variables on it (false sharing). The two regions of the batch build sat side
// by side in an array and each wrote its own counters and flip stack at every insertion: the
// Delaunay triangulation of 10^6 points took 286-336 ms on two cores, and 186-191 ms once each
// region had lines of its own.

#include <cstddef>

namespace tessera
{

/// The cache line of x86-64 and of most ARM64 cores. (std::hardware_destructive_interference_size
/// would say so too, but GCC warns that its value may change between compiler versions.)
constexpr std::size_t CacheLineBytes = 64;

/// One chunk's value in an array of per-thread state, alone on its cache lines.
template<class T>
struct alignas(CacheLineBytes) OwnCacheLines
{
  T Value;
};

} // namespace tessera
