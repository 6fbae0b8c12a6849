#pragma once
// OrderByDistinctKeys: the positions of distinct integer keys in ascending key order, by a
// counting sort (O(count + keyLimit)). The tessellation filters list their tiles in ascending
// point id with it, whatever order an engine derived them in (the Green-Sibson dual's spatial
// order, the Brassel-Reif sweep's).

#include <cstddef>
#include <cstdint>
#include <vector>

namespace tessera
{

/// The positions 0 .. count-1 of keys, ordered by key: keys[result[0]] < keys[result[1]] < ...
/// The keys must be distinct and in [0, keyLimit). The slot table (keyLimit entries, written at
/// random) and the result are on huge pages where large (large_pages.h).
std::vector<std::int32_t> OrderByDistinctKeys(const std::int32_t* keys,
  std::size_t count,
  std::size_t keyLimit);

} // namespace tessera
