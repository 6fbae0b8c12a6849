#pragma once
// Borders that display pieces of neighbouring tiles share, made the same vertex for vertex, so that
// the pieces still meet exactly once their edges are cut into steps and made lon/lat.
//
// In the plane, two tiles' pieces meet along a common tile edge, but not always at the same
// vertices: display_pieces.h cuts a tile's part of the catchment with vertical lines, and where a
// cut meets the tile's edge it adds a vertex there that the neighbour's piece does not have (a
// T-junction). Straight in the plane, the border is a curve in lon/lat, which each side cut into
// steps at its own points follows with its own chords:
//
//        piece A: a ------------------------------ b        a ----- m ------------------- b
//        piece B: a ------------ m --------------- b   ->   (in lon/lat the chords a-b and
//                             (B's cut)                       a-m-b part by a chord's sagitta)
//
// so the pieces overlapped and left gaps a few millimetres wide (a GIS's topology check flagged
// them, and their union had a hole for every such stretch). Here every vertex of a piece that lies
// on another piece's edge (within the rounding of the cut points) is added to that edge, and edges
// are cut into steps at points that depend only on the edge's two ends, not on the way it runs.

#include "clip.h"

#include <vector>

namespace tessera
{

/// pieces (simple rings, as DisplayPieces gives them, of any number of tiles) with each vertex of
/// a piece that lies inside an edge of another piece added to that edge, in order along it. "Lies
/// inside": within 64 ulps of the largest coordinate of the edge from its line, between its ends
/// and not within that distance of either end. First, copies of one point in different pieces
/// within 64 ulps of each other (each piece computed its own: a cut of both tiles at one x, a
/// crossing computed from either end) are made one, the smallest by x then y, unless a piece has
/// two vertices among them or a vertex would turn its corner the other way (made one, they would
/// fold its ring), or one lies beyond 64 ulps of the smallest (a chain of near copies). Any finite
/// coordinates (the tests run on them scaled by a power of two); pieces with a NaN or infinite
/// coordinate are returned as they are. By a grid of about one vertex a cell, each edge listed in
/// the cells along it: O(V + cells the edges cross) for V vertices.
ClippedRings ShareBorderVertices(const ClippedRings& pieces);

/// Points along a ring's edges in the plane so that no piece is longer than step (closing edge
/// included; the first vertex is not repeated). An edge is cut into the same points, to the bit,
/// whichever way a ring runs along it: they are counted from its lexicographically smaller end.
void DensifyRingSymmetrically(const Point2* ring,
  std::size_t count,
  double step,
  std::vector<Point2>& out);

} // namespace tessera
