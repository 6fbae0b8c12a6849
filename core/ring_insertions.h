#pragma once
// Points added to rings inside their edges, in order along each edge: the last step of making
// borders that two rings share the same vertex for vertex (shared_borders.h for display pieces,
// snap_to_segments.h for the caller's polygons), which both find their points in their own way
// and then write the rings again with them.
//
//     ring:  a ---------------- b        insertions on edge a -> b at T = 0.7 (p) and 0.3 (q):
//                                        a -- q -------- p -- b
//
// A point equal to the vertex just written (the same point found on the edge from two rings) is
// added once.

#include "geometry.h"

#include <cstddef>
#include <vector>

namespace tessera
{

/// A point to add inside the edge that starts at vertex Edge (its index in the flat vertices), at
/// parameter T along it (0 at that vertex, 1 at the next).
struct RingInsertion
{
  std::size_t Edge;
  double T;
  Point2 Vertex;
};

/// Whether InsertIntoRings says where each vertex came from (InsertedRings::SegmentOf).
enum class SegmentNumbers
{
  Kept,
  Dropped ///< (SegmentOf left empty: a vector as long as the vertices, not built)
};

/// Rings (flat offsets) with points added, and where each vertex came from.
struct InsertedRings
{
  std::vector<std::size_t> Offsets; ///< one per ring, plus the end; starts at 0
  std::vector<Point2> Vertices;
  /// Per vertex: the number within its ring of the edge it starts or was added inside (empty with
  /// SegmentNumbers::Dropped).
  std::vector<std::size_t> SegmentOf;
  std::size_t Inserted = 0; ///< points added (those equal to the vertex before them aside)
};

/// Sorts insertions by edge, then by T: the order InsertIntoRings takes them in. (Not stable:
/// insertions of one edge and one T keep the order std::sort leaves them in.)
void SortAlongEdges(std::vector<RingInsertion>& insertions);

/// The rings (ring r is vertices[offsets[r], offsets[r + 1])) with each insertion written after
/// the start of its edge, unless it equals the vertex written just before it. insertions: sorted
/// by SortAlongEdges, each edge a vertex of a ring. O(vertices + insertions).
InsertedRings InsertIntoRings(const std::vector<std::size_t>& offsets,
  const std::vector<Point2>& vertices,
  const std::vector<RingInsertion>& insertions,
  SegmentNumbers segments);

} // namespace tessera
