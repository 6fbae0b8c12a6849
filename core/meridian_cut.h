#pragma once
// Pieces cut at a meridian: a GIS reads a polygon in lon/lat within -180 .. 180 degrees (RFC 7946,
// 3.1.9), so a tile across the 180th meridian (its longitudes continuous here, 179.5 to 180.5)
// must be written as a western and an eastern part. Each piece is cut by the vertical line
// x = at (the edges are straight in lon/lat, so the cut is exact):
//
//   piece across x = at       west part   east part
//   +-----|-----+             +----+      +-----+
//   |     |     |      ->     |    |      |     |
//   +-----|-----+             +----+      +-----+
//
// A crossing point is computed from the edge's lower end (by x, then y), so that two pieces that
// share an edge share its crossing point too, and their parts still meet vertex for vertex
// (piece_outlines.h joins them). A piece that leaves its side and comes back is cut by
// Sutherland-Hodgman into one ring joined by bridges along the line, and a piece with an edge or
// a vertex on the line gives spikes along it; every edge along the line is then cut at each of
// the side's points on the line, so that such stretches are walked once each way and cancel
// when the parts are joined.

#include "clip.h"

#include <array>
#include <cstddef>
#include <vector>

namespace tessera
{

/// Rings first .. last - 1 of pieces cut at x = at: [0] their parts with x <= at, [1] those with
/// x >= at (a vertex on the line is in both), parts of fewer than 3 vertices left out, edges along
/// the line cut at the side's points on it. The parts are for OutlinesOfPieces, side by side (two
/// sets: joined, a piece's two parts would join again across the line); alone, a part may run
/// along the line and back.
std::array<ClippedRings, 2> CutAtMeridian(const ClippedRings& pieces,
  std::size_t first,
  std::size_t last,
  double at);

/// The longitudes of a ring (lonLat) within MeridianSnapDegrees of the 180th meridian (or a copy
/// of it 360 degrees on) set to it exactly, unless every vertex is that near (a ring thinner than
/// that along the line keeps its area, as it was). Points of a border along that meridian come
/// back from the plane at 180 and at 179.99999999999997 by rounding, and such a tile was cut
/// there into its real part and a sliver a few nanometres wide, written as a second polygon of
/// its feature. The areal average snaps its pieces in lon/lat so (its tiles' cells and outlines).
void SnapToMeridian(std::vector<Point2>& lonLat);

/// 1e-10 degrees: about 11 micrometres along the equator, some 3500 ulps of 180 (a point
/// projected and back comes within a few).
constexpr double MeridianSnapDegrees = 1e-10;

} // namespace tessera
