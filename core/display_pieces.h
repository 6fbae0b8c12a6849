#pragma once
// Display pieces of a clipped tile: the region that Catchment::ClipInto's rings describe (signed
// rings, with zero-width bridges and shared stretches of the tile's boundary) as polygons that a
// renderer or a mesh filter reads as meant: simple rings, anticlockwise, no holes, no overlaps.
//
// ClipInto's rings are right for areas (their signed areas sum to the region's) but not for
// display: a hole in the tile is a clockwise ring that a polygon cell would fill, and two lobes of
// a tile that straddles a bay are one ring joined by a bridge along the tile's edge, which VTK's
// triangulation of a polygon does not take apart.
//
// The region is cut into x-monotone pieces (a vertical line meets each in one interval, so each
// is a simple polygon) by a vertical decomposition: at every vertex's x the plane is cut into
// slabs; inside a slab no edge starts, ends or (the rings do not cross) changes order, so the
// region there is a stack of trapezoids between consecutive edges, found by summing the edges'
// windings from below (bridges, whose two edges cancel, vanish). A trapezoid whose left side
// shares a stretch with the right side of a piece of the slab before continues that piece (the
// lowest such one not yet taken); where the stack changes (a hole or a bay begins or ends) pieces
// end and new ones begin. A region that is already x-monotone (most clipped tiles, concave ones
// included) comes out as one piece, its own ring, if it is a fan (below):
//
//   tile with a hole          slabs at the vertices' x        pieces
//   +---------------+         +----+-------+------+           +----+-------+------+
//   |    +-------+  |         |    +-------+      |           |    |   2   |      |
//   |    |       |  |   ->    |    |       |      |    ->     | 1  +-------+  1   |
//   |    +-------+  |         |    +-------+      |           |    +-------+      |
//   |               |         |    |       |      |           |    |   1   |      |
//   +---------------+         +----+-------+------+           +----+-------+------+
//
// Each piece is then made a fan about its first vertex: VTK draws a polygon, and its Cell Size and
// Integrate Variables measure it, as the triangles of its first point and each edge not at it,
// so a piece drawn from a vertex that does not see all of it (an L from an outer corner) was
// drawn over its concave corners and measured too large. A piece is started at a vertex that sees
// it all (exact orientation tests: every such triangle anticlockwise or flat), if one is found;
// otherwise it is cut in two by the vertical line through the middle of its vertices' x, and the
// parts are made fans in turn:
//
//   U round a hole: a fan about no vertex        cut at the middle x: two Ls, each started at
//   +---+   +---+                                its inner corner (*)
//   |   |   |   |                                +---+   +---+
//   |   +---+   |                                |   *---+   |
//   +-----------+                                +-----+*----+
//
// A hole inside a tile thus gives three or four pieces (the U round it cut in two, and the part
// above it, cut too where the hole is round), whatever its number of vertices (convex pieces
// would need about half of them); a tile under a wavy shore a piece a wave or so. Pieces do not
// overlap and their areas sum to the region's (each trapezoid is exactly the region inside its
// slab); their vertices are the rings' own, plus the points where a piece's vertical side meets an
// edge. Rounding is allowed for: rings of no area (ClipInto's leftovers of a ring that only runs
// along the tile's boundary) are dropped first, and slivers between edges that run along one line,
// no higher than a few ulps of the coordinates (times the edges' steepness), are no part of any
// piece, so that no piece has a spike along such a line that would cross itself once drawn.

#include "clip.h"

namespace tessera
{

/// The region of rings (ClippedRings as Catchment::ClipInto leaves them: each ring oriented with
/// the region on its left, the region where the sum of their winding numbers is positive) as
/// pieces: simple anticlockwise rings without holes, disjoint, covering the region, each a fan
/// about its first vertex.
ClippedRings DisplayPieces(const ClippedRings& rings);

/// y of the edge a-b at x (a.x < x < b.x or b.x < x < a.x), within the edge's heights, computed
/// from its left end whichever way it runs: where a vertical cut meets it, the same bits from
/// either ring that has the edge (as the slabs of DisplayPieces take it, and CutAtMeridian).
double CrossingHeight(const Point2& a, const Point2& b, double x);

/// A simple anticlockwise ring rotated to start at a vertex about which it is a fan (every
/// triangle of that vertex and an edge not at it anticlockwise or flat, exactly), if the search
/// finds one within 8 n + 64 orientation tests for n vertices; left as it is otherwise. Returns
/// whether it now starts at such a vertex. (For a piece whose edges were bent after DisplayPieces
/// made it a fan: its edges densified and taken to lon/lat, where a side that bows inwards leaves
/// the first vertex short of seeing the whole piece.)
bool StartAtFanApex(std::vector<Point2>& ring);

} // namespace tessera
