#pragma once
// A std::allocator whose resize() leaves new elements of trivially copyable, trivially
// destructible types uninitialised, so that the pass that writes them first (often on the cores)
// is also the one that first touches their pages: a serial zero fill of a large array costs a page
// fault per 4 KiB. Arrays from LargePageBytes to HugePageAdviceLimit come on transparent huge
// pages (large_pages.h), a page fault per 2 MiB.

#include "large_pages.h"

#include <cstdlib>
#include <memory>
#include <new>
#include <type_traits>
#include <utility>
#include <vector>

namespace tessera
{

/// std::allocator, except that resize() leaves new elements uninitialised (nothing is written for
/// int32, uint64, Point2 and the like: see construct) and large arrays come from AllocateLarge.
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
  /// Default construction: nothing at all for a trivially copyable, trivially destructible type
  /// (an implicit-lifetime type: its objects exist in the storage without a constructor call, as
  /// an int's do), even one with default member initialisers: Point2's zeros made resize() write
  /// every element, and at 10^7 points NumberFaceVertices zero-filled 305 MB of fresh pages on one
  /// thread before its chunks wrote the centres. Any other type is default-initialised.
  template<class U>
  void construct([[maybe_unused]] U* p) noexcept(std::is_nothrow_default_constructible_v<U>)
  {
    if constexpr (!(std::is_trivially_copyable_v<U> && std::is_trivially_destructible_v<U>))
    {
      ::new (static_cast<void*>(p)) U;
    }
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
