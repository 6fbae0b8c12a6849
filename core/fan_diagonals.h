#pragma once
// A simple ring that no vertex sees whole, split into fans along diagonals between its own
// vertices. VTK draws a polygon, and its Cell Size and Integrate Variables measure it, as the fan
// of triangles from its first point; a display piece made a fan in the plane and bent on its way
// to lon/lat (its long sides bowing in) can have no such point left, and was drawn over itself:
// a strip of 397 vertices along 41 N measured 24% too large. Split along a diagonal into two
// halves, and each half again until it is a fan; a diagonal joins two vertices already there, so
// the parts add no vertex and the piece's borders with its neighbours stay as they were:
//
//   a bent strip, no vertex sees it all        split at a diagonal between vertices
//   +-----....______                           +-----....__|___
//    \              ''''----+                   \          |    ''''----+
//     +-----....______      /          ->        +-----....|______      /
//                     ''''-+                               |      ''''-+

#include "geometry.h"

#include <vector>

namespace tessera
{

/// ring (simple, anticlockwise) as rings that are fans about their first vertex (every triangle
/// of that vertex and an edge not at it anticlockwise or flat, exactly), split along diagonals
/// (exact tests: inside the ring at both ends, touching no edge and no vertex), each halving a
/// part's vertices as near as one found does: from every vertex to the one half the ring on,
/// then an eighth and a quarter of the ring nearer or farther, within 16 n + 4096 edge tests a
/// part. A part for which none is found is left as it is, not a fan; so are the parts once there
/// are 64 (at most 64 in all).
std::vector<std::vector<Point2>> FansByDiagonals(const std::vector<Point2>& ring);

} // namespace tessera
