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

/// A transparent huge page: AllocateLarge aligns its blocks to this and rounds them up to it.
constexpr std::size_t HugePageBytes = std::size_t(2) << 20;

/// The block RaiseMallocThresholdOnce allocates and frees, which moves glibc's mmap threshold to
/// this (just below its ceiling, 32 MiB on 64-bit systems).
constexpr std::size_t RaisedMallocThreshold = std::size_t(31) << 20;

/// Up to this many bytes, and no further, AllocateLarge asks for huge pages: the largest block
/// that, with the 2 MiB aligned_alloc asks for on top to align it, stays below glibc's mmap
/// threshold at its ceiling (RaisedMallocThreshold): 28 MiB. A block up to here comes back from
/// the heap once freed, its huge pages already there; a larger one is a fresh mapping each time
/// (blocks of 30 and 32 MiB were, the limit having been 32 MiB), and on a guest that reports free
/// memory to its host (Linux page reporting: this project's VMs) a fresh huge page costs several
/// times what its 512 small pages do, and at times 30 times: 1.6-2.3 s per GiB on one day, 5-13 s
/// on another, against 0.4-0.7 s (0.13 against 0.36 s for memory the guest had just freed). At
/// 10^7 points the tiles filter took 0.54-0.58 us per point with a limit of 32 MiB, 0.60-0.68
/// without (with ReuseLargeBlocks); at 10^6 points, right after the Delaunay filter, 0.44-0.49 us
/// per point with 28 MiB in eight runs, 0.43-1.67 with 32 MiB (its 30.5 MiB array of tile
/// corners was mapped and faulted afresh on huge pages in every run).
constexpr std::size_t HugePageAdviceLimit =
  (RaisedMallocThreshold - HugePageBytes - 1) / HugePageBytes * HugePageBytes;

/// bytes of memory, 2 MiB aligned and advised to be backed by huge pages when LargePageBytes <=
/// bytes <= HugePageAdviceLimit (plain malloc below). Release it with ReleaseLarge(memory, bytes)
/// or std::free (which never keeps it: VTK frees the filters' output arrays so). Throws
/// std::bad_alloc. A large block first raises glibc's mmap threshold (RaiseMallocThresholdOnce).
void* AllocateLarge(std::size_t bytes);

/// Gives back memory from AllocateLarge (bytes: what was asked for). Inside a
/// ReuseLargeBlocks scope a block above HugePageAdviceLimit is kept for the next AllocateLarge of
/// about its size (the size asked for, rounded to huge pages: a kept block handed out for a
/// little less is kept again at that size); any other is freed.
void ReleaseLarge(void* memory, std::size_t bytes) noexcept;

/// While one of these lives (on any thread), blocks above HugePageAdviceLimit given back by
/// ReleaseLarge are kept and handed out again by AllocateLarge for requests of about their size
/// (at most 1/8 smaller, so that a block reused for less does not hold much memory that was
/// touched and is not needed); when the last one ends, the blocks kept are freed. Smaller blocks
/// go back to glibc's heap at once, which hands them out again for any size: kept here, blocks of
/// a few MiB were held from requests they could have served, the heap grew, and its freed top
/// was trimmed at the scope's end, to be faulted afresh (the tiles filter with its graph at 10^6
/// points took 0.82-0.90 us per point, against 0.45-0.47 keeping only the larger ones). At most an
/// eighth of the machine's memory is kept, the oldest blocks freed first: scopes on several threads
/// that overlap may keep the store open for long. For a run whose steps free large arrays before
/// the next step makes its own (a build's temporaries, then a tessellation freed before its tiles
/// are written out): the memory is mapped and faulted once instead of twice. A kept block that no
/// later request fits stays resident until the scope ends: the peak can grow by the blocks of a
/// step that frees before the next allocates (at 10^7 points, 2.51 to 2.58 GB for the tiles
/// filter, 1.49 to 1.56 GB for the Delaunay filter).
class ReuseLargeBlocks
{
public:
  ReuseLargeBlocks();
  ~ReuseLargeBlocks();
  ReuseLargeBlocks(const ReuseLargeBlocks&) = delete;
  ReuseLargeBlocks& operator=(const ReuseLargeBlocks&) = delete;
};

/// The bytes of the blocks kept for reuse now (0 outside every ReuseLargeBlocks scope).
std::size_t KeptLargeBlockBytes();

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
