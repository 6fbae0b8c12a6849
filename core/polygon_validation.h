#pragma once
// Validation of a polygon given as rings (flat arrays), before it is used as a region by the
// even-odd rule: finite coordinates, at least 3 distinct vertices per ring, no ring touching or
// crossing itself or another ring. Every decision about segments uses the exact orient2d, so a
// polygon is accepted or rejected the same way whatever its magnitude or offset.

#include "geometry.h"

#include <cstddef>
#include <vector>

namespace tessera
{

/// Rings without repeated consecutive vertices (a closing vertex equal to the first is a repeat).
struct CleanRings
{
  /// RingOffsets[r] .. RingOffsets[r+1] are the vertices of ring r; RingOffsets.back() equals
  /// Vertices.size().
  std::vector<std::size_t> RingOffsets;
  std::vector<Point2> Vertices;
  /// For each kept vertex, its index within its ring in the caller's numbering. Segment k of a
  /// clean ring runs from vertex k to vertex k+1 (cyclically); in the caller's numbering it is
  /// segment SourceIndex[k], because of a run of repeats the last one is kept.
  std::vector<std::size_t> SourceIndex;
};

/// Checks the rings and returns them without repeated consecutive vertices. ringOffsets has one
/// entry per ring plus a final one equal to vertices.size(), starting at 0 and non-decreasing.
/// Throws InputError naming the ring and vertex or segment indices (the caller's numbering) for:
/// malformed offsets; a NaN or infinite coordinate; a ring with fewer than 3 distinct vertices;
/// two segments of one ring that touch or cross other than at their shared vertex (collinear
/// overlap of neighbouring segments included); two rings that touch or cross.
/// segmentOf, for rings the caller made by cutting its own into pieces (densified edges): per
/// vertex, the caller's number of the segment that starts there, which messages then use (and
/// SourceIndex holds).
CleanRings ValidateRings(const std::vector<std::size_t>& ringOffsets,
  const std::vector<Point2>& vertices,
  const std::vector<std::size_t>* segmentOf = nullptr);

/// Whether the closed segments ab and cd have a point in common, exactly.
bool SegmentsIntersect(const Point2& a, const Point2& b, const Point2& c, const Point2& d);

} // namespace tessera
