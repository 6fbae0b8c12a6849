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

/// Pairs (r, s), r < s, of rings that are the same closed path (the same vertices in the same
/// cyclic order, either way round and from any start, repeated consecutive vertices and a closing
/// vertex aside) and cancel as a hole and the island that fills it: the ring lies inside an odd
/// number of the other rings (its copies aside). Copies of an outer boundary would take their
/// region away, so they are in no pair (validation refuses them as a ring given twice). Of three
/// or more copies the first two are paired, then the next two; an odd one is in no pair. A ring
/// with a coordinate that is not finite, of fewer than three distinct vertices, or that passes
/// through its smallest vertex twice, is in none (validation names it). Ring r is
/// vertices[offsets[r], offsets[r + 1]). Ascending by r. O(v log v) for v vertices, plus O(v) per
/// group of copies.
std::vector<std::pair<std::size_t, std::size_t>> IdenticalRingPairs(
  const std::vector<std::size_t>& offsets,
  const std::vector<Point2>& vertices);

} // namespace tessera
