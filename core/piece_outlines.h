#pragma once
// The outline of a region given as pieces: the boundary rings of a union of simple polygons that
// meet along borders they share vertex for vertex (a tile's display pieces, display_pieces.h, once
// shared_borders.h made their borders alike), grouped into polygons with holes as a GIS wants a
// tile: one feature, an outer ring and its holes, rather than the pieces a renderer needs.
//
// Each piece is walked anticlockwise, so an edge that two pieces share is walked once each way;
// such pairs cancel, and the edges left are the region's boundary, with the region on their left.
// They are chained into rings. Where the boundary passes a vertex twice (two lobes, or a hole and
// the outline, meeting at a point), a ring leaves by the first edge clockwise from the one it came
// in by, so that it bounds one sector there and never crosses itself; a ring that comes back to
// a vertex (a hole touching the outline, which that turn joins to it) is then cut there into its
// loops. Every ring is simple, and rings only touch at points (as OGC's valid polygons may):
//
//   pieces of a tile round a hole     shared edges cancel     outer ring (anticlockwise) and
//   +----+-------+-----+              +-------------------+   hole (clockwise), one polygon
//   |    |   2   |     |              |                   |   +-------------------+
//   | 1  +-------+  3  |      ->      |    +-------+      |   |    +-<-----+      |
//   |    +-------+     |              |    |       |      |   |    v  hole ^      |
//   |    |   4   |     |              |    +-------+      |   |    +---->--+      |
//   +----+-------+-----+              +-------------------+   +------->-----------+
//
// Rings are then sorted by their signed area: anticlockwise ones are outer boundaries, clockwise
// ones holes, and each hole goes with the smallest outer ring that holds it (an island in a lake
// in a tile is an outer ring of its own). Every test is exact (orientation predicates), so the
// result depends on the pieces' coordinates only, not on rounding.

#include "clip.h"

#include <cstddef>
#include <vector>

namespace tessera
{

/// Polygons with holes: polygon p is rings PolygonOffsets[p] .. PolygonOffsets[p + 1] - 1 of Rings,
/// its outer ring (anticlockwise) first, then its holes (clockwise). Rings are not closed (the
/// first vertex is not repeated).
struct RegionOutlines
{
  ClippedRings Rings;
  std::vector<std::size_t> PolygonOffsets{ 0 };
};

/// The outline of the union of pieces' rings first .. last - 1 (simple rings, anticlockwise, that
/// do not overlap and meet along shared edges vertex for vertex). A vertex that lies on a
/// neighbour's edge without being one of its vertices (a T-junction) leaves both edges, a thin
/// ring pair, in the outline; ShareBorderVertices removes such vertices first. Repeated
/// consecutive vertices are passed over; rings of no area left by the chaining are dropped, and so
/// are rings whose area's sign is not their turn at their lowest vertex (a bow tie left where
/// pieces overlap by a sliver, as they can along a window's slit some ulps wide). A hole
/// that no outer ring holds (only possible for pieces that overlap) goes with the largest outer
/// ring, and is dropped when there is none (pieces given clockwise). Polygons come in the order of
/// their outer rings' lowest vertices (by x, then y). O(E log E) for E edges, plus a point-in-ring
/// test per hole and outer ring that holds its box.
RegionOutlines OutlinesOfPieces(const ClippedRings& pieces, std::size_t first, std::size_t last);

/// The outline of one tile's display pieces as DisplayPieces gives them: their borders made alike
/// first (ShareBorderVertices: a piece's side can span a hole's end and its neighbour's, a
/// T-junction), so that the stretches they share cancel.
RegionOutlines OutlinesOfTilePieces(const ClippedRings& pieces);

/// more's polygons appended to all's (offsets shifted), for outlines of several regions in one.
void AppendOutlines(const RegionOutlines& more, RegionOutlines& all);

} // namespace tessera
