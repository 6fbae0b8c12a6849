#pragma once
// Where the walk to a streamed point should start when points arrive in no spatial order: the
// triangles of the triangulation indexed by the Hilbert index of a vertex, so that a point finds
// triangles near it by one binary search.
//
// Streaming Insert walks from the triangle made last. Points in random order walked O(sqrt n)
// triangles each from there; jump and walk (random samples, the nearest taken) cut that to about
// n^(1/3), but every step and every sample is a cache miss: 10^6 uniform points in random order
// took 21-30 s streamed, 40 times a batch. The index is built again once as many points were
// inserted or removed since as it held (Stale), so it always holds most of the triangles near any
// point: the indexed triangle next to p along the curve is then a few triangles from p (O(n log n)
// in all, and 8 bytes a triangle).

#include "geometry.h"

#include <cstdint>
#include <utility>
#include <vector>

namespace tessera
{

class WalkHints
{
public:
  /// Indexes the triangles (origins: halfEdges vertices, a triple per triangle, the half-edges'
  /// origins; a negative entry is the ghost vertex or a free triangle's mark) by their first real
  /// vertex. changes: the caller's count of insertions and removals so far, for Stale.
  void Build(const std::int32_t* origins,
    std::size_t halfEdges,
    const std::vector<Point2>& points,
    std::size_t changes);
  /// Whether the index is to be built (again): never built, cleared, or changes (counted as for
  /// Build) have grown since by half the triangles it was built for, about its points (the
  /// triangles have doubled, or a churn of removals and insertions freed and reused them
  /// elsewhere: after 90% of 2x10^5 points were removed, the next 1.8x10^5 took 2.5 s, 0.18 s
  /// fresh).
  bool Stale(std::size_t changes) const
  {
    return this->Built == 0 || changes - this->ChangesAtBuild >= this->Built / 2;
  }
  /// The triangle count at the last Build (0: never built, or cleared).
  std::size_t BuiltFor() const { return this->Built; }
  /// Forgets the index: for a triangulation whose triangles were renumbered or made again, where
  /// it would name triangles elsewhere (a walk from the last triangle then ran O(sqrt n) again).
  void Clear()
  {
    this->Built = 0;
    this->Entries.clear();
  }
  /// Writes up to 3 triangles indexed beside p along the curve into near; returns how many (0
  /// before a Build, or where the points' box has no extent to scale). They may since have been
  /// changed or freed: the caller checks.
  int Near(const Point2& p, std::int32_t near[3]) const;
  std::size_t Bytes() const { return this->Entries.capacity() * sizeof(Entry); }

private:
  using Entry = std::pair<std::uint32_t, std::int32_t>; // (Hilbert index, triangle)
  std::uint32_t Key(const Point2& p) const;

  Box2 Box;
  double Scale = 0.0;
  std::vector<Entry> Entries;
  std::size_t Built = 0;          ///< triangles at the last Build (0: never built, or cleared)
  std::size_t ChangesAtBuild = 0; ///< Build's changes
};

} // namespace tessera
