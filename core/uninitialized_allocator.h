#pragma once
// A std::allocator whose resize() leaves new elements of trivially constructible types
// uninitialised, so that the pass that writes them first (often on the cores) is also the one that
// first touches their pages: a serial zero fill of a large array costs a page fault per 4 KiB.
// Arrays of LargePageBytes or more come on transparent huge pages (large_pages.h), a page fault
// per 2 MiB.

#include "large_pages.h"

#include <cstdlib>
#include <memory>
#include <new>
#include <utility>
#include <vector>

namespace tessera
{

/// std::allocator, except that resize() leaves new elements uninitialised (default-initialised:
/// nothing is written for int32, uint64 and the like) and large arrays are on huge pages.
template<class T>
struct UninitializedAllocator : std::allocator<T>
{
  template<class U>
  struct rebind
  {
    using other = UninitializedAllocator<U>;
  };
  UninitializedAllocator() = default;
  template<class U>
  UninitializedAllocator(const UninitializedAllocator<U>&) noexcept
  {
  }
  T* allocate(std::size_t n)
  {
    if (n > std::size_t(-1) / sizeof(T))
    {
      throw std::bad_array_new_length();
    }
    return static_cast<T*>(AllocateLarge(n * sizeof(T)));
  }
  void deallocate(T* p, std::size_t n) noexcept { ReleaseLarge(p, n * sizeof(T)); }
  template<class U>
  void construct(U* p) noexcept
  {
    ::new (static_cast<void*>(p)) U;
  }
  template<class U, class... Args>
  void construct(U* p, Args&&... args)
  {
    ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
  }
};

/// A std::vector of T whose resize() writes nothing.
template<class T>
using UninitializedVector = std::vector<T, UninitializedAllocator<T>>;

} // namespace tessera
