#pragma once
// Large arrays on transparent huge pages (2 MiB) where the system offers them on request
// (Linux with /sys/kernel/mm/transparent_hugepage/enabled = madvise, Debian's default).
//
// Why. A derivation writes its results into fresh arrays, and each first touch of a 4 KiB page is
// a page fault. On a virtual machine with a paravirtualised MMU (this project's) a fault can cost
// more than the work that fills the page: the tiles filter faults some 350 bytes per point, and at
// 10^5 points it took 0.063-0.073 s with every allocation on 4 KiB pages against 0.034-0.038 s
// with every allocation on huge pages (glibc.malloc.hugetlb=1), one fault per 2 MiB. A library
// cannot set that for its process, so its own large arrays ask for huge pages themselves. There a
// fresh 4 KiB page cost 11 us and a fresh 2 MiB huge page 110 us (the cost of ten small ones), so
// from 256 KiB on an array is faster on huge pages, though rounding up to 2 MiB can take up to
// eight times its memory: for an array of 256 KiB to 2 MiB that is at most 2 MiB more, most of
// them a derivation's arrays, freed with it (a streaming tessellation's half-edge arrays and the
// filters' outputs live longer; StructureBytes counts capacities, not this rounding). Smaller
// arrays keep the ordinary allocator.

#include <cstddef>
#include <vector>

namespace tessera
{

/// From this many bytes on, AllocateLarge asks for huge pages.
constexpr std::size_t LargePageBytes = std::size_t(256) << 10;

/// bytes of memory, 2 MiB aligned and advised to be backed by huge pages when bytes >=
/// LargePageBytes (plain malloc otherwise). Release it with std::free. Throws std::bad_alloc.
/// A large block first raises glibc's mmap threshold (RaiseMallocThresholdOnce).
void* AllocateLarge(std::size_t bytes);

/// Raises glibc's mmap threshold to its ceiling for the process, once (large_pages.cpp), so that
/// freed blocks up to 31 MiB are reused from the heap rather than mapped afresh. AllocateLarge
/// calls it, and so does ReserveOnLargePages: a build of 10^4 points makes no block of
/// LargePageBytes, and its blocks of 40-240 KiB, freed together, went back to the system with the
/// heap's top after every build, to fault again 4 KiB at a time in the next (12% of a serial
/// build's samples; the build took 0.19-0.24 us per point with this, 0.25-0.31 without).
void RaiseMallocThresholdOnce();

/// Advises the whole 2 MiB pages inside [begin, begin + bytes) to be backed by huge pages when
/// first touched (nothing where there is none, or off Linux). For arrays that must stay
/// std::vectors (the engine's coordinates, which Points() hands out as one): at 10^7 points the
/// coordinates are read at random by id, and on 4 KiB pages nearly every read missed the TLB.
void AdviseLargePages(const void* begin, std::size_t bytes);

/// v.reserve(n), the storage advised onto huge pages when it has to grow (see AdviseLargePages):
/// the elements written into it later are then written on huge pages, not 4 KiB ones, wherever
/// its memory is fresh (memory the heap reuses keeps the pages it already has).
template<class T, class Allocator>
void ReserveOnLargePages(std::vector<T, Allocator>& v, std::size_t n)
{
  if (n > v.capacity())
  {
    RaiseMallocThresholdOnce(); // (first: a block below 31 MiB then comes from the heap)
    v.reserve(n);
    AdviseLargePages(v.data(), v.capacity() * sizeof(T));
  }
}

/// v.resize(n) on storage reserved by ReserveOnLargePages.
template<class T, class Allocator>
void ResizeOnLargePages(std::vector<T, Allocator>& v, std::size_t n)
{
  ReserveOnLargePages(v, n);
  v.resize(n);
}

/// v.assign(n, value) on storage reserved by ReserveOnLargePages (one pass over the elements).
template<class T, class Allocator>
void AssignOnLargePages(std::vector<T, Allocator>& v, std::size_t n, const T& value)
{
  v.clear();
  ReserveOnLargePages(v, n);
  v.resize(n, value);
}

} // namespace tessera
