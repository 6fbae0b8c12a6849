#pragma once
// Rings given twice. By the even-odd rule two rings that are the same closed path cancel: an island
// feature that fills a hole of another feature exactly (an enclave, a sub-basin inside another,
// given as that basin's hole and as a polygon of its own) leaves the union of the two, as a ring
// given twice leaves nothing. Validation refuses rings that run along each other all the way round
// (polygon_validation.h); the identical ones among them can be left out in pairs first.
//
//     +-----------+          rings: the outline, the hole h (of the first feature) and
//     |   +---+   |          the island h' (the second feature), h' the same path as h:
//     |   | h |   |          h and h' cancel, and the outline alone is the region
//     |   +---+   |
//     +-----------+

#include "geometry.h"

#include <cstddef>
#include <utility>
#include <vector>

namespace tessera
{

/// Pairs (r, s), r < s, of rings that are the same closed path: the same vertices in the same
/// cyclic order, either way round and from any start, repeated consecutive vertices (a closing
/// vertex equal to the first included) aside. Of three or more identical rings the first two are
/// paired, then the next two; an odd one is in no pair. A ring with a NaN coordinate, or of fewer
/// than three distinct vertices, is in none (validation names it). Ring r is
/// vertices[offsets[r], offsets[r + 1]). Ascending by r. O(v log v) for v vertices.
std::vector<std::pair<std::size_t, std::size_t>> IdenticalRingPairs(
  const std::vector<std::size_t>& offsets,
  const std::vector<Point2>& vertices);

} // namespace tessera
