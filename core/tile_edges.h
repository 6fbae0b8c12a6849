#pragma once
// Internal to the tile derivations (tiles.cpp: the whole tessellation; local_tiles.cpp: chosen
// points): a tile edge clipped to the window, the faces it joins, and the polygon assembled from
// a ring of such edges. See tiles.h for the rules (exact decisions, rounded coordinates only).

#include "cache_line.h"
#include "dirichlet_tessellation.h"
#include "geometry.h"
#include "tiles.h"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

namespace tessera
{
namespace tiles_detail
{

using Tess = DirichletTessellation;

struct EdgeEnd
{
  Point2 P;
  int Constraint; ///< window constraint the end lies on; -1 for a face centre inside
  /// Where the end is exactly: a face (>= 0), window corner k (-2 - k), or a crossing of a
  /// window line elsewhere (-1). Two ends with the same Where >= 0 or <= -2 coincide exactly.
  std::int32_t Where;
};

struct TileEdge
{
  EdgeEnd Lo, Hi;
};

/// A face as a tile edge sees it; Face < 0 for a ghost (centre at infinity).
struct FaceView
{
  std::int32_t Face = -1;
  Point2 Centre;
  bool Inside = false;
};

// Circumcentre from the points in a fixed order (FaceCentre's; circumcentre.h: relative to the
// first, or to the second for a sliver whose short side is opposite the first); `error` bounds
// the rounding error of each coordinate (infinity when the triangle is too flat to say).
Point2 Circumcentre(const Point2& a, const Point2& b, const Point2& c, double& error);

/// Sorts three distinct point ids by their points in the engines' order (geometry.h:
/// ComesFirst) with three compare-exchanges that compile to conditional moves: which of a
/// triangle's points comes first is close to random, and a branch on it was mispredicted often
/// enough to slow the centres of a whole tessellation by a fifth.
inline void SortByCoordinates(const Point2* pts, std::int32_t& a, std::int32_t& b, std::int32_t& c)
{
  const auto exchange = [pts](std::int32_t& p, std::int32_t& q)
  {
    const bool swap = ComesFirst(pts[q], pts[p]);
    const std::int32_t first = swap ? q : p;
    q = swap ? p : q;
    p = first;
  };
  exchange(a, b);
  exchange(b, c);
  exchange(a, b);
}

/// The centre of triangle a, b, c from its points in the engines' order (FaceCentre's, for a
/// face of three points; inline: the full derivation runs it for every triangle).
inline Point2 TriangleCentre(const Point2* pts,
  std::int32_t a,
  std::int32_t b,
  std::int32_t c,
  double& error)
{
  SortByCoordinates(pts, a, b, c);
  return Circumcentre(pts[a], pts[b], pts[c], error);
}

/// The centre of a face with points ids[0, count) (count >= 3, in any order), from its first
/// three points in the engines' order (geometry.h: ComesFirst; any three points of a face
/// span its circle), so that every tile having it as a vertex gets the same bits whichever of
/// the face's triangles it reads, and whatever the numbering. `error` as Circumcentre's.
Point2 FaceCentre(const std::vector<Point2>& pts,
  const std::int32_t* ids,
  std::size_t count,
  double& error);

/// Whether the centre c (error bound `error`) of the face with representative triangle `face`
/// lies strictly inside the window, decided exactly.
bool CentreInside(const Tess& tess, std::int32_t face, const Point2& c, double error);

/// The part inside the window of the tile edge of `from` with `to` (anticlockwise around from),
/// between the centres of the faces on its right and left; false when nothing of positive length
/// is inside.
bool ClipEdge(const Tess& tess,
  std::int32_t from,
  std::int32_t to,
  const FaceView& right,
  const FaceView& left,
  TileEdge& out);

/// The tile polygon from its clipped edges (window corners added between an exit and the next
/// entry). Returns the number of sides (contiguities with points and window edges), decided
/// exactly.
std::int32_t AssemblePolygon(const Tess& tess,
  const std::vector<TileEdge>& edges,
  std::vector<Point2>& polygon);

/// Appends one tile (its polygon, compensated area and side count) to tiles.
void AppendTile(TileSet& tiles,
  std::int32_t point,
  const std::vector<Point2>& polygon,
  std::int32_t sides);

/// Appends every tile of from to tiles (joining chunks computed apart, in order).
void AppendTileSet(TileSet& tiles, const TileSet& from);

/// The chunks' tiles in chunk order, as one set: part 0 moved in (no copy; the full derivation
/// reserves room for all tiles in it), the others appended. The parts are left moved from.
TileSet JoinTileParts(std::vector<OwnCacheLines<TileSet>>& parts);

/// The per-tile columns TileSet and TileMesh share: one tile's (its offset is where its vertices
/// end, vertexEnd) ...
template<class Tiles>
void AppendTileColumns(Tiles& tiles,
  std::int32_t point,
  std::int64_t vertexEnd,
  double area,
  std::int32_t sides)
{
  tiles.PointIds.push_back(point);
  tiles.Offsets.push_back(vertexEnd);
  tiles.Areas.push_back(area);
  tiles.NeighborCounts.push_back(sides);
}

/// ... and every tile's of from, its offsets shifted by base (the vertices tiles had).
template<class Tiles>
void AppendTileColumns(Tiles& tiles, const Tiles& from, std::int64_t base)
{
  tiles.PointIds.insert(tiles.PointIds.end(), from.PointIds.begin(), from.PointIds.end());
  for (std::size_t k = 1; k < from.Offsets.size(); ++k)
  {
    tiles.Offsets.push_back(base + from.Offsets[k]);
  }
  tiles.Areas.insert(tiles.Areas.end(), from.Areas.begin(), from.Areas.end());
  tiles.NeighborCounts.insert(
    tiles.NeighborCounts.end(), from.NeighborCounts.begin(), from.NeighborCounts.end());
}

/// The half-edges leaving a point, anticlockwise from vertexEdge.
inline void CollectRing(const Tess& tess, std::int32_t vertexEdge, std::vector<std::int32_t>& ring)
{
  ring.clear();
  std::int32_t e = vertexEdge;
  do
  {
    ring.push_back(e);
    e = tess.RingNext(e);
  } while (e != vertexEdge);
}

/// The common case, without clipping: every face around the point (ring: its half-edges,
/// CollectRing) is a real triangle or merged face whose centre is strictly inside the window.
/// Then every tile edge runs from the centre on its right to the centre on its left, inside the
/// window, so the polygon is the ring of centres: exactly what RingTileEdges and AssemblePolygon
/// give (same start, at the edge to the smallest neighbour id; same dropping of rounded repeats),
/// for a fraction of the cost. A ring edge with one degenerate face on both sides (a lattice, say)
/// is a diagonal of that face, no tile edge: it is skipped, and never the start, as RingTileEdges
/// does.
///
///        c1 ------- c2          the faces around v: A (two triangles, diagonal v-d), B, C, ...
///         |  A   d  |           edges v-a, v-b: sides, centre on the right of each
///         |    /    |           edge v-d: A on both sides, no side
///         a--v------b
///
/// Returns the number of sides (the ring edges that are not diagonals), or 0, polygon and labels
/// unspecified, for any other point. With labels, also gives the face of each polygon vertex, and
/// appends to sameCentre the (kept, dropped) faces of each dropped repeat: distinct faces whose
/// rounded centres coincide.
template<class Faces>
std::int32_t InteriorTile(const Tess& tess,
  const Faces& faces,
  const std::vector<std::int32_t>& ring,
  std::vector<Point2>& polygon,
  std::vector<std::int32_t>* labels = nullptr,
  std::vector<std::pair<std::int32_t, std::int32_t>>* sameCentre = nullptr)
{
  const auto& org = tess.Origin();
  const std::size_t n = ring.size();
  // One pass round the ring: whether every face is real and inside (each is on the right of some
  // edge), the vertices from ring[0] on, and the start, to which they are then rotated. (A pass
  // for the start and a second writing from it looked every face up twice: a tenth of the cost
  // of an update's local tiles.)
  polygon.resize(n);
  if (labels)
  {
    labels->resize(n);
  }
  std::size_t first = n, firstSide = 0, sides = 0;
  std::int32_t previous = faces.Label(ring[n - 1] / 3); // the face right of ring[0]
  for (std::size_t k = 0; k < n; ++k)
  {
    const std::int32_t label = faces.Label(ring[k] / 3);
    if (label < 0)
    {
      return 0; // a ghost: an unbounded tile edge
    }
    if (label != previous)
    {
      // The tile edge along ring[k] starts at the centre on its right.
      const FaceView right = faces.View(previous);
      if (!right.Inside)
      {
        return 0;
      }
      if (first == n ||
        org[std::size_t(Tess::Next(ring[k]))] < org[std::size_t(Tess::Next(ring[first]))])
      {
        first = k;
        firstSide = sides;
      }
      polygon[sides] = right.Centre;
      if (labels)
      {
        (*labels)[sides] = previous;
      }
      ++sides;
    }
    previous = label;
  }
  if (first == n)
  {
    return 0;
  }
  const std::ptrdiff_t firstAt = std::ptrdiff_t(firstSide), end = std::ptrdiff_t(sides);
  std::rotate(polygon.begin(), polygon.begin() + firstAt, polygon.begin() + end);
  if (labels)
  {
    std::rotate(labels->begin(), labels->begin() + firstAt, labels->begin() + end);
  }
  polygon.resize(sides);
  if (!labels)
  {
    DropRepeatedVertices(polygon);
    return std::int32_t(sides);
  }
  labels->resize(sides);
  DropRepeatedVertices(polygon, *labels, sameCentre);
  return std::int32_t(sides);
}

// The clipped edges of v's tile, anticlockwise from the edge to its smallest
// neighbour id (so the polygon does not depend on where the ring starts, nor on
// the diagonals stored in degenerate faces). ring: the half-edges leaving v (CollectRing).
// faces.Label(t) is triangle t's face (-2 - t for a ghost), faces.View(label)
// its centre and inside flag.
template<class Faces>
void RingTileEdges(const Tess& tess,
  const Faces& faces,
  std::int32_t v,
  const std::vector<std::int32_t>& ring,
  std::vector<TileEdge>& edges)
{
  edges.clear();
  const auto& org = tess.Origin();
  const auto& twin = tess.Twin();
  std::size_t first = 0;
  std::int32_t smallest = std::numeric_limits<std::int32_t>::max();
  for (std::size_t k = 0; k < ring.size(); ++k)
  {
    // Diagonals of degenerate faces (the same face on both sides) depend on the insertion order:
    // they are never the start.
    const std::int32_t e = ring[k];
    const std::int32_t j = org[std::size_t(Tess::Next(e))];
    if (j >= 0 && j < smallest && faces.Label(e / 3) != faces.Label(twin[std::size_t(e)] / 3))
    {
      smallest = j;
      first = k;
    }
  }
  TileEdge edge;
  for (std::size_t k = 0; k < ring.size(); ++k)
  {
    const std::int32_t e = ring[(first + k) % ring.size()];
    const std::int32_t j = org[std::size_t(Tess::Next(e))];
    const std::int32_t left = faces.Label(e / 3);
    const std::int32_t right = faces.Label(twin[std::size_t(e)] / 3);
    if (j >= 0 && left != right && ClipEdge(tess, v, j, faces.View(right), faces.View(left), edge))
    {
      edges.push_back(edge);
    }
  }
}

/// v's tile polygon, ring being its half-edges (CollectRing): an interior tile straight from the
/// ring of centres (InteriorTile, the same bits; labels and sameCentre as there), any other from
/// its clipped edges, which stay in edges. interior says which; returns the number of sides. The
/// full derivation and the local one (local_tiles.cpp) both make their tiles here.
template<class Faces>
std::int32_t RingTilePolygon(const Tess& tess,
  const Faces& faces,
  std::int32_t v,
  const std::vector<std::int32_t>& ring,
  std::vector<TileEdge>& edges,
  std::vector<Point2>& polygon,
  bool& interior,
  std::vector<std::int32_t>* labels = nullptr,
  std::vector<std::pair<std::int32_t, std::int32_t>>* sameCentre = nullptr)
{
  const std::int32_t sides = InteriorTile(tess, faces, ring, polygon, labels, sameCentre);
  interior = sides > 0;
  if (interior)
  {
    return sides;
  }
  RingTileEdges(tess, faces, v, ring, edges);
  return AssemblePolygon(tess, edges, polygon);
}

/// Appends v's tile (RingTilePolygon); edges and polygon are scratch.
template<class Faces>
void AppendRingTile(const Tess& tess,
  const Faces& faces,
  std::int32_t v,
  const std::vector<std::int32_t>& ring,
  std::vector<TileEdge>& edges,
  std::vector<Point2>& polygon,
  TileSet& tiles)
{
  bool interior = false;
  const std::int32_t sides = RingTilePolygon(tess, faces, v, ring, edges, polygon, interior);
  AppendTile(tiles, v, polygon, sides);
}

} // namespace tiles_detail
} // namespace tessera
