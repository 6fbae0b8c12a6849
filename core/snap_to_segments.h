#pragma once
// Vertices put onto the segments of other rings that pass within a tolerance of them: shared
// borders of adjacent polygons drawn with T-junctions (a vertex on the border that only one of
// the two polygons has, as sub-catchment layers often have), written with rounded coordinates.
//
// Why. Two polygons that share a border meet exactly only where each vertex of the border is a
// vertex of both. A T-junction vertex, rounded to the 6 decimals GeoJSON writers use (RFC 7946),
// lies up to some 7e-7 degrees off the other polygon's straight edge: on one side the rings cross
// in lon/lat; on the other they do not, but once the edges are cut into pieces and projected, the
// two sides of the border no longer match and cross by rounding. Either was refused, so a
// sub-basin layer could not be averaged as a whole. Made a vertex of the other ring's segment too,
// the vertex is on both borders, exactly:
//
//        A                      A
//   P----T----Q     ->     P----T----Q      (B's segment P-Q becomes P-T-Q: T, a hair off P-Q,
//        B                      B            is now a vertex of both rings)
//
// The segment bends by at most the tolerance. A vertex within the tolerance of a segment's end is
// left alone (two vertices of one place drawn apart: not a T-junction), as are vertices of the
// segment's own ring.

#include "geometry.h"
#include "ring_insertions.h"

#include <cstddef>
#include <vector>

namespace tessera
{

/// The snapped rings: Offsets (one per ring, plus the end), Vertices, SegmentOf (per vertex, the
/// caller's number of the segment that starts there within its ring; a vertex put onto a segment
/// takes that segment's, as ValidateRings' segmentOf takes it) and Inserted (vertices put onto
/// other rings' segments): the rings with their insertions as InsertIntoRings writes them.
using SnappedRings = InsertedRings;

/// The rings (flat offsets, as ValidateRings takes them) with every vertex that lies within
/// `tolerance` of another ring's segment (strictly between its ends, and farther than the
/// tolerance from both) made a vertex of that segment, in order along it, with its own
/// coordinates. Non-finite vertices and segments of zero length are passed over (ValidateRings
/// names them). Near-linear in the vertices: segments are indexed on a grid. Throws InputError
/// naming an offset that does not fit the vertices (CheckRingOffsets, polygon_validation.h).
SnappedRings SnapVerticesOntoSegments(const std::vector<std::size_t>& offsets,
  const std::vector<Point2>& vertices,
  double tolerance);

} // namespace tessera
