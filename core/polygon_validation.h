#pragma once
// Validation of a polygon given as rings (flat arrays), before it is used as a region by the
// even-odd rule: finite coordinates, at least 3 distinct vertices per ring, no ring touching or
// crossing itself, and no two rings crossing. Two rings may touch at points, as OGC's simple
// features allow (a hole touching its shell at a vertex, parts of a multipolygon meeting at a
// corner), and share stretches of boundary (sub-catchments given as adjacent polygons, a lake on
// the outline): as long as no two rings cross, each ring's inside holds another's or is apart from
// it, and the even-odd region is the sum of the rings' regions with signs by nesting. Every
// decision about segments uses the exact orient2d, so a polygon is accepted or rejected the same
// way whatever its magnitude or offset.

#include "geometry.h"

#include <cstddef>
#include <utility>
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
  /// Per ordered pair of rings that meet (touch or share boundary), ascending by (Ring, Other):
  /// whether the boundary of Ring, off Other, lies inside Other (then Ring's inside is within
  /// Other's: Other encloses it), rather than outside.
  struct RingContact
  {
    std::size_t Ring;
    std::size_t Other;
    bool Inside;
  };
  std::vector<RingContact> RingContacts;
  /// Where another ring's vertex touches a segment inside it: the segment (its first vertex's
  /// index in Vertices) and the point, in no particular order, perhaps more than once.
  std::vector<std::pair<std::size_t, Point2>> ContactsInsideSegments;
};

/// Throws InputError, naming the offset, unless ringOffsets has one entry per ring plus a final one
/// equal to vertexCount, starting at 0 and non-decreasing: what every reader of flat rings needs
/// before it reads a vertex (ValidateRings checks it first).
void CheckRingOffsets(const std::vector<std::size_t>& ringOffsets, std::size_t vertexCount);

/// Checks the rings and returns them without repeated consecutive vertices. ringOffsets has one
/// entry per ring plus a final one equal to vertices.size(), starting at 0 and non-decreasing.
/// Throws InputError naming the ring and vertex or segment indices (the caller's numbering) for:
/// malformed offsets; a NaN or infinite coordinate; a ring with fewer than 3 distinct vertices;
/// two segments of one ring that touch or cross other than at their shared vertex (collinear
/// overlap of neighbouring segments included); two rings that cross, at a point inside segments
/// or where they meet or part (one ring's boundary off the other lying partly inside the other
/// and partly outside); two rings that run along each other all the way round (a ring given twice).
/// segmentOf, for rings the caller made by cutting its own into pieces (densified edges): per
/// vertex, the caller's number of the segment that starts there, which messages then use (and
/// SourceIndex holds).
CleanRings ValidateRings(const std::vector<std::size_t>& ringOffsets,
  const std::vector<Point2>& vertices,
  const std::vector<std::size_t>* segmentOf = nullptr);

/// The rings with every point of ContactsInsideSegments made a vertex of its segment (SourceIndex
/// the segment's), so that rings meet at vertices only. A map then applied to
/// every vertex, with the segments densified (the areal average's projection), keeps them meeting
/// there: the point of a segment would otherwise land on one side of its image or the other.
CleanRings WithContactsAsVertices(const CleanRings& rings);

/// Exact orientation of a ring that ValidateRings accepted (1 anticlockwise, -1 clockwise): at its
/// lexicographically smallest vertex the ring turns convexly, and the neighbours cannot be
/// collinear with it (validation refuses such overlaps).
int RingOrientation(const Point2* ring, std::size_t count);

/// Whether all the points lie on one line, exactly (so do fewer than three distinct points).
bool AllOnOneLine(const Point2* points, std::size_t count);

/// Whether the closed segments ab and cd have a point in common, exactly.
bool SegmentsIntersect(const Point2& a, const Point2& b, const Point2& c, const Point2& d);

/// The winding number of the ring around p (the signed crossings of the ray from p towards +x,
/// exact); for a p on the ring, either value. Its parity is the even-odd membership.
int RingWinding(const Point2* ring, std::size_t count, const Point2& p);

} // namespace tessera
