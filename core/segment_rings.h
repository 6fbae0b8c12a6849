#pragma once
// Closed rings from loose line segments, joined where they share a point id, or (for segments given
// by their ends) where their ends have equal coordinates: a contour line as vtkCutter or
// ParaView's Contour gives it (one two-point line cell per segment), taken as a window or
// catchment boundary.
//
//     a---b        segments (a,b) (c,b) (c,d) (d,a), in any order and either direction,
//     |   |        give the ring a, b, c, d (the first segment's direction);
//     d---c        a chain that ends, or a point where three segments meet, gives none.
//
// Segments given by their ends are first cut back to their closed paths: a chain that ends (an
// open branch of a contour, a spur off a ring) is unjoined, and the rings through the point it
// left are joined without it. Where four (six, ...) segments meet, as where a contour passes
// through a saddle point, they are paired by angle, each with the next round the point, so that the
// rings touch there and never cross; a ring that then comes back to a point is cut there into two:
//
//     +---+            the eight segments of two squares meeting at their corner p
//     |   |            give the two squares, touching at p (by the even-odd rule the region
//     +---p---+        is the same however the segments are paired: that rule counts
//         |   |        crossings of segments, not rings)
//         +---+

#include "geometry.h"

#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace tessera
{

struct SegmentRings
{
  /// Ring k's point ids are Ids[Offsets[k], Offsets[k + 1]) (the first is not repeated at the end).
  std::vector<std::size_t> Offsets{ 0 };
  std::vector<std::int64_t> Ids;
  /// Indices (into the segments given) of the segments in no ring, ascending: those of a chain
  /// that does not close, and of every chain through a point of other than two segments
  /// (JoinSegmentsIntoRings; JoinSegmentsAtEqualEnds: through a point of an odd number of segments
  /// on closed paths, or a junction it cannot pair), and those whose two ends are one point.
  std::vector<std::size_t> Unjoined;
};

/// Joins segments (pairs of point ids) into closed rings. Every point of a ring has exactly two
/// segments, so a ring is unambiguous; a component with any other point is left unjoined whole
/// (ids carry no coordinates to pair more by angle). O(s log s) for s segments.
SegmentRings JoinSegmentsIntoRings(
  const std::vector<std::pair<std::int64_t, std::int64_t>>& segments);

/// Rings of points, from JoinSegmentsAtEqualEnds.
struct PointRings
{
  /// Ring k's vertices are Vertices[Offsets[k], Offsets[k + 1]) (the first not repeated).
  std::vector<std::size_t> Offsets{ 0 };
  std::vector<Point2> Vertices;
  /// As SegmentRings::Unjoined, but for a segment of no length at a point of a joined ring, which
  /// adds nothing to the ring and is not listed (vtkContourFilter gives one between two ids of one
  /// point).
  std::vector<std::size_t> Unjoined;
};

/// Joins segments given by their ends (segment s from ends[2s] to ends[2s + 1]) into closed rings,
/// ends meeting where their coordinates are equal: a contour keeps one point id per point, but
/// line features read from a file may repeat a point under two ids. As JoinSegmentsIntoRings,
/// but chains that end are cut away first (unjoined), where an even number of the remaining
/// segments, four or more, meet at a point they are paired by angle (exactly: orient2d), and no
/// ring stands on a point twice (see the sketches above). A closed path stays unjoined where it
/// passes through a point of an odd number of such segments (three paths between two points), or
/// through a junction where two segments leave in one direction; an end with a NaN coordinate meets
/// no other, so its chain is a dead end.
PointRings JoinSegmentsAtEqualEnds(const std::vector<Point2>& ends);

} // namespace tessera
