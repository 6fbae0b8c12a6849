#pragma once
// Spatial insertion order for incremental Delaunay / Dirichlet construction: a biased randomized
// insertion order (BRIO, Amenta, Choi and Rote 2003) whose rounds are each sorted along a Hilbert
// curve. Successive points are then close to each other, so the nearest-neighbour walk from the
// last inserted point is short (Green and Sibson, section 2.3), while the random rounds keep the
// expected total work O(N log N) for any input.

#include "geometry.h"

#include <cstdint>
#include <vector>

namespace tessera
{

/// Hilbert index of the cell (x, y) of a 2^levels x 2^levels grid (levels <= 16).
std::uint32_t HilbertIndex(std::uint32_t x, std::uint32_t y, int levels);

/// The bounding box of the points of ids (at least one), in chunks on the cores.
Box2 BoundsOfIds(const std::vector<Point2>& points, const std::vector<std::int32_t>& ids);

/// ids (indices into points) sorted along a Hilbert curve over box (65536 cells a side, one scale
/// for both axes; ties keep their order): each point is then near the one before it, so a walk
/// from the last to the next is short. For a few points at a time; BrioHilbertOrder for batches.
void SortAlongHilbertCurve(const Point2* points, const Box2& box, std::vector<std::int32_t>& ids);

/// The ids (indices into points) of `ids` reordered: rounds of geometrically growing size
/// (each point goes to the last round with probability 1/2, to the one before with 1/4, ...,
/// decided by a hash of its id and `seed`, so the order is reproducible), each round sorted by
/// Hilbert index over the bounding box of the selected points. O(N) time (radix sort).
std::vector<std::int32_t> BrioHilbertOrder(const std::vector<Point2>& points,
  const std::vector<std::int32_t>& ids,
  std::uint64_t seed = 0);

/// The same, given box: the bounding box of the points of ids, for a caller that has it already
/// (the batch build finds it while validating the points).
std::vector<std::int32_t> BrioHilbertOrder(const std::vector<Point2>& points,
  const std::vector<std::int32_t>& ids,
  const Box2& box,
  std::uint64_t seed = 0);

} // namespace tessera
