#include "tiles.h"

#include "cache_line.h"
#include "errors.h"
#include "large_pages.h"
#include "parallel_chunks.h"
#include "polygon_area.h"
#include "predicates_inline.h"
#include "tile_edges.h"

#include <algorithm>
#include <array>
#include <climits>
#include <cmath>
#include <cstring>
#include <limits>
#include <numeric>
#include <stdexcept>
#include <string>
#include <tuple>
#include <utility>

namespace tessera
{

namespace
{

using namespace tiles_detail;
using parallel::ChunkBounds;
using parallel::RunChunks;
using parallel::ThreadCount;

/// An index for a prefetch: ghost and free ids (negative) replaced by 0, to stay in bounds.
///
/// The project's prefetches are written in the loops themselves, never in a helper of their own:
/// GCC 12 drops a call to an inline helper that only prefetches unless it inlines the helper
/// first (its mod-ref analysis finds no effect in it; -fno-ipa-modref keeps them). A helper with
/// three prefetches lost all of them at -O1, -O2 and -O3, one with two at -O1 and -O2. Check
/// with objdump -d | grep -c prefetch after moving any.
inline std::int32_t NonNegative(std::int32_t id)
{
  return std::max(id, std::int32_t(0));
}

/// A triangle a, b, c (anticlockwise) as a face starting at its smallest id.
void AppendTriangleFace(DelaunayFaces& faces, std::int32_t a, std::int32_t b, std::int32_t c)
{
  if (a < b && a < c)
  {
    faces.PointIds.insert(faces.PointIds.end(), { a, b, c });
  }
  else if (b < c)
  {
    faces.PointIds.insert(faces.PointIds.end(), { b, c, a });
  }
  else
  {
    faces.PointIds.insert(faces.PointIds.end(), { c, a, b });
  }
  faces.Offsets.push_back(std::int32_t(faces.PointIds.size()));
}
} // namespace

namespace
{
constexpr std::int64_t MinimumTrianglesPerThread = 2 * TessellationDual::MinimumTilesPerThread;
/// Whether every corner of tile k lies on the line through a and b (two distinct corners of it),
/// exactly: an out-and-back sliver an ulp wide has three or more distinct corners and no area.
bool CornersCollinear(const TileMesh& tiles, std::size_t k, const Point2& a, const Point2& b)
{
  for (std::int64_t v = tiles.Offsets[k]; v < tiles.Offsets[k + 1]; ++v)
  {
    if (orient2d(a, b, tiles.Vertices[static_cast<std::size_t>(tiles.VertexIds[v])]) != 0)
    {
      return false;
    }
  }
  return true;
}

/// Whether tile k has fewer than 3 distinct corners, or only collinear ones.
bool TileCollapsed(const TileMesh& tiles, std::size_t k)
{
  std::array<Point2, 3> corners; // (no allocation per tile: a million tiles)
  std::size_t distinct = 0;
  for (std::int64_t v = tiles.Offsets[k]; v < tiles.Offsets[k + 1] && distinct < 3; ++v)
  {
    const Point2& p = tiles.Vertices[static_cast<std::size_t>(tiles.VertexIds[v])];
    if (std::none_of(corners.begin(),
          corners.begin() + static_cast<std::ptrdiff_t>(distinct),
          [&](const Point2& q) { return q.x == p.x && q.y == p.y; }))
    {
      corners[distinct++] = p;
    }
  }
  // Three or more distinct corners can still be collinear. Only a tile of area 0 is looked at
  // (its area is exactly 0 then), but such an area is not enough: a true tile of points some
  // 1e-165 apart has an area below the doubles, and is no sliver.
  const bool flat = distinct >= 3 && k < tiles.Areas.size() && tiles.Areas[k] == 0.0 &&
    CornersCollinear(tiles, k, corners[0], corners[1]);
  return distinct < 3 || flat;
}

} // namespace

// Chunks of tiles in parallel, each listing its own: at 10^7 tiles the serial pass over their
// corners took 0.17-0.19 s.
std::vector<std::int32_t> CollapsedTilePoints(const TileMesh& tiles)
{
  const std::int32_t count = std::int32_t(tiles.PointIds.size());
  const std::vector<std::int32_t> bounds =
    ChunkBounds(count, ThreadCount(count, TessellationDual::MinimumTilesPerThread));
  std::vector<std::vector<std::int32_t>> found(bounds.size() - 1);
  RunChunks(found.size(),
    [&](std::size_t chunk)
    {
      for (std::int32_t k = bounds[chunk]; k < bounds[chunk + 1]; ++k)
      {
        if (TileCollapsed(tiles, std::size_t(k)))
        {
          found[chunk].push_back(tiles.PointIds[std::size_t(k)]);
        }
      }
    });
  std::vector<std::int32_t> collapsed;
  for (const std::vector<std::int32_t>& part : found)
  {
    collapsed.insert(collapsed.end(), part.begin(), part.end());
  }
  std::sort(collapsed.begin(), collapsed.end());
  return collapsed;
}

void CheckWindowInExactRange(const DirichletTessellation& tessellation)
{
  const int exponent = tessellation.GetWindow().RangeScaleExponent();
  if (exponent != 0)
  {
    throw InputError(std::string("the window's coordinates are ") +
      (exponent < 0 ? "beyond 2^128" : "all below 2^-128") +
      ", outside the range where tiles are exact: scale points and window into it with "
      "ScaleIntoExactRange (window.h) before building the tessellation, and the tiles back with "
      "ScaleByPowerOfTwo (tiles.h) (by 2^" +
      std::to_string(exponent) + " here)");
  }
  tessellation.CheckPointsInExactRange();
}

TessellationDual::TessellationDual(const DirichletTessellation& tessellation)
  : Tess(tessellation)
{
  const std::size_t n = tessellation.PointCount();
  if (!tessellation.IsTwoDimensional())
  {
    this->LinePosition.assign(n, -1);
    const auto& line = tessellation.CollinearPoints();
    for (std::size_t k = 0; k < line.size(); ++k)
    {
      this->LinePosition[line[k]] = std::int32_t(k);
    }
    this->Order.assign(line.begin(), line.end());
    return;
  }
  this->OrderPoints();
  std::vector<std::uint8_t> cocircular;
  this->ComputeTriangleCentres(cocircular);
  this->LabelFaces(cocircular);
  std::vector<double>().swap(this->CentreError); // needed only to find co-circular pairs
}

// Each vertex where it first appears in the half-edge arrays read from the end (Order, with the
// half-edge in OrderEdge); a bit per point keeps the "seen" test in cache.
//
// Why from the end: a batch build's arrays start with the triangles of its serial sample, whose
// slots later insertions keep reusing all over the window, and go on with the triangles the
// regions made in their (Hilbert) insertion order. Read from the start, the first tenth of the
// points came out scattered and took twice as long to derive as any later tenth; read from the
// end, every point comes out where its last-made triangles are, in insertion order: tiles and
// contiguities at 1M took 153-202 ms instead of 269-275 ms on two threads.
//
// Chunks of the arrays in parallel, each with its own bits; a chunk's first appearances then
// count only if no earlier chunk saw the vertex, so the order is the serial one. Both loops are
// branch-free on the "seen" bit (vertex ids are random, so the branch was mispredicted often):
// every edge is written at the end of the list, which then grows only when its vertex is new.
// (1M points: 27-29 ms with a branch and push_back, 8.5 ms without.)
void TessellationDual::OrderPoints()
{
  const HalfEdgeArray& org = this->Tess.Origin();
  const std::size_t words = (this->Tess.PointCount() + 63) / 64;
  const std::int32_t edges = std::int32_t(org.size());
  const std::vector<std::int32_t> bounds =
    ChunkBounds(edges, ThreadCount(edges, 6 * MinimumTilesPerThread));
  const std::size_t chunks = bounds.size() - 1;
  std::vector<std::vector<std::uint64_t>> seen(chunks);
  std::vector<UninitializedVector<std::int32_t>> first(chunks);
  RunChunks(chunks,
    [&](std::size_t k)
    {
      std::vector<std::uint64_t>& bits = seen[k];
      bits.assign(words, 0);
      first[k].resize(std::size_t(bounds[k + 1] - bounds[k]));
      const std::int32_t* origin = org.data();
      std::int32_t* found = first[k].data();
      std::size_t count = 0;
      for (std::int32_t r = bounds[k]; r < bounds[k + 1]; ++r)
      {
        const std::int32_t e = edges - 1 - r;
        const std::int32_t v = origin[e];
        if (v >= 0) // ghost and free triangles' slots hold negative ids: rare, well predicted
        {
          std::uint64_t& word = bits[std::size_t(v) >> 6];
          const std::uint64_t bit = std::uint64_t(1) << (v & 63);
          found[count] = e;
          count += (word & bit) == 0 ? 1 : 0;
          word |= bit;
        }
      }
      first[k].resize(count);
    });
  std::size_t total = 0;
  for (const UninitializedVector<std::int32_t>& found : first)
  {
    total += found.size();
  }
  this->Order.resize(total);
  this->OrderEdge.resize(total);
  std::uint64_t* const earlier = seen[0].data(); // the vertices seen by chunks before k
  std::size_t count = 0;
  for (std::size_t k = 0; k < chunks; ++k)
  {
    for (const std::int32_t e : first[k])
    {
      const std::int32_t v = org[std::size_t(e)];
      this->Order[count] = v;
      this->OrderEdge[count] = e;
      count += k == 0 || !(earlier[std::size_t(v) >> 6] >> (v & 63) & 1U) ? 1 : 0;
    }
    for (std::size_t w = 0; k > 0 && w < words; ++w)
    {
      earlier[w] |= seen[k][w];
    }
  }
  this->Order.resize(count);
  this->OrderEdge.resize(count);
}

// ---------------------------------------------------------------------------------------------
// Faces: ghosts get Face = -2 - t (never merged), real triangles the id of
// the first triangle of their co-circular cluster.

// Every real triangle's centre (canonical: from its ids in ascending order), error bound and
// inside-the-window flag (right for every face that is a single triangle; MergeClusters redoes
// the degenerate ones), and which of its real neighbours with a larger index are exactly
// co-circular with it (cocircular: bit k for the neighbour across edge k; left empty when the
// build knows there are none). Chunks of triangles in parallel, each writing its own entries.
void TessellationDual::ComputeTriangleCentres(std::vector<std::uint8_t>& cocircular)
{
  const std::int32_t triangles = std::int32_t(this->Tess.Origin().size() / 3);
  this->Data.resize(std::size_t(triangles)); // not initialised: CentresOf writes every entry
  // The centres' error bounds serve only to find co-circular candidates.
  if (!this->Tess.KnownFreeOfCocircularTriangles())
  {
    ResizeOnLargePages(this->CentreError, std::size_t(triangles));
  }
  const std::vector<std::int32_t> bounds =
    ChunkBounds(triangles, ThreadCount(triangles, MinimumTrianglesPerThread));
  RunChunks(bounds.size() - 1, [&](std::size_t k) { this->CentresOf(bounds[k], bounds[k + 1]); });
  // Known free of co-circular triangles: no tests at all (LabelFaces has nothing to do).
  if (!this->Tess.KnownFreeOfCocircularTriangles())
  {
    AssignOnLargePages(cocircular, std::size_t(triangles), std::uint8_t(0));
    RunChunks(bounds.size() - 1,
      [&](std::size_t k) { this->CocircularEdgesOf(bounds[k], bounds[k + 1], cocircular.data()); });
  }
}

void TessellationDual::CentresOf(std::int32_t begin, std::int32_t end)
{
  const std::int32_t* org = this->Tess.Origin().data();
  const Point2* pts = this->Tess.Points().data();
  double* const errors = this->CentreError.empty() ? nullptr : this->CentreError.data();
  constexpr std::int32_t ahead = 16;
  const std::int32_t prefetchEnd = std::max(begin, end - ahead);
  for (std::int32_t t = begin; t < end; ++t)
  {
    if (t < prefetchEnd)
    {
      const std::int32_t* next = org + 3 * (t + ahead);
      __builtin_prefetch(pts + NonNegative(next[0]));
      __builtin_prefetch(pts + NonNegative(next[1]));
      __builtin_prefetch(pts + NonNegative(next[2]));
    }
    const std::int32_t a = org[3 * t], b = org[3 * t + 1], c = org[3 * t + 2];
    if (a < 0 || b < 0 || c < 0)
    {
      this->Data[t].Face = -2 - t; // a ghost or free triangle: its own face, never merged
      this->Data[t].Vertex = -1;
      continue;
    }
    this->Data[t].Face = t; // until LabelFaces merges it
    TriangleData& data = this->Data[t];
    double error = 0.0;
    const Point2 centre = TriangleCentre(pts, a, b, c, error);
    data.X = centre.x;
    data.Y = centre.y;
    data.Vertex = CentreInside(this->Tess, t, centre, error) ? 0 : -1;
    if (errors)
    {
      errors[t] = error;
    }
  }
}

void TessellationDual::CocircularEdgesOf(std::int32_t begin,
  std::int32_t end,
  std::uint8_t* cocircular) const
{
  const std::int32_t* org = this->Tess.Origin().data();
  const std::int32_t* twin = this->Tess.Twin().data();
  const TriangleData* data = this->Data.data();
  const double* error = this->CentreError.data();
  // The neighbours' centres, and their vertices for the exact test, are random loads: request
  // the centres and the neighbours' ids a few triangles ahead, and the vertex across each edge
  // (its id loaded by then) half as far ahead.
  const Point2* pts = this->Tess.Points().data();
  constexpr std::int32_t ahead = 12;
  const std::int32_t prefetchEnd = std::max(begin, end - ahead);
  for (std::int32_t t = begin; t < end; ++t)
  {
    if (t < prefetchEnd)
    {
      const std::int32_t* next = twin + 3 * (t + ahead);
      const std::int32_t* nearer = twin + 3 * (t + ahead / 2);
      for (std::int32_t k = 0; k < 3; ++k)
      {
        __builtin_prefetch(data + NonNegative(next[k]) / 3);
        __builtin_prefetch(error + NonNegative(next[k]) / 3);
        __builtin_prefetch(org + NonNegative(next[k]));
        __builtin_prefetch(pts + NonNegative(org[Tess::Prev(NonNegative(nearer[k]))]));
      }
    }
    if ((org[3 * t] | org[3 * t + 1] | org[3 * t + 2]) < 0)
    {
      continue;
    }
    std::uint8_t bits = 0;
    for (std::int32_t k = 0; k < 3; ++k)
    {
      const std::int32_t f = twin[3 * t + k];
      // A real neighbour further on (CentresOf labelled ghosts and free triangles negative: read
      // from the prefetched entry, not from the neighbour's vertices, a cache miss).
      if (f / 3 > t && data[f / 3].Face >= 0 && this->Cocircular(t, f))
      {
        bits |= std::uint8_t(1U << k);
      }
    }
    cocircular[t] = bits;
  }
}

// Whether the triangle across half-edge f has its opposite vertex on the circle
// of triangle t: exact, but skipped when the computed centres are further apart
// than their error bounds.
bool TessellationDual::Cocircular(std::int32_t t, std::int32_t f) const
{
  const std::int32_t u = f / 3;
  const double slack = this->CentreError[t] + this->CentreError[u];
  if (std::fabs(this->Data[t].X - this->Data[u].X) > slack ||
    std::fabs(this->Data[t].Y - this->Data[u].Y) > slack)
  {
    return false;
  }
  const auto& org = this->Tess.Origin();
  const std::vector<Point2>& pts = this->Tess.Points();
  return incircle_fast(
           pts[org[3 * t]], pts[org[3 * t + 1]], pts[org[3 * t + 2]], pts[org[Tess::Prev(f)]]) == 0;
}

namespace
{
// Appends the points of a degenerate face's boundary (its half-edges, in any order; each point
// leaves exactly one) as a polygon: the edge after x->y is the one leaving y, and the polygon
// starts at its smallest id. A face of a few points (a lattice's squares, most of them) finds
// each next edge by a linear search; a larger one through its edges sorted by their points (the
// search made k exactly co-circular points cost O(k^2): 236196 on one circle took 18 s).
void ChainBoundary(const std::int32_t* org,
  std::vector<std::int32_t>& boundary,
  std::vector<std::int32_t>& polygon)
{
  const auto byOrigin = [org](std::int32_t a, std::int32_t b) { return org[a] < org[b]; };
  const auto leaving = [org](std::int32_t edge, std::int32_t point) { return org[edge] < point; };
  const bool sorted = boundary.size() > 8;
  if (sorted)
  {
    std::sort(boundary.begin(), boundary.end(), byOrigin);
  }
  else
  {
    std::iter_swap(boundary.begin(), std::min_element(boundary.begin(), boundary.end(), byOrigin));
  }
  std::int32_t e = boundary.front();
  for (std::size_t step = 0; step < boundary.size(); ++step)
  {
    polygon.push_back(org[e]);
    const std::int32_t to = org[Tess::Next(e)];
    e = sorted
      ? *std::lower_bound(boundary.begin(), boundary.end(), to, leaving)
      : *std::find_if(
          boundary.begin(), boundary.end(), [org, to](std::int32_t g) { return org[g] == to; });
  }
}
} // namespace

// Ghosts (and free triangles) are their own faces, -2 - t. A real triangle is a face of its own
// (as CentresOf labelled it) unless it is exactly co-circular with a neighbour: then the whole
// connected cluster on that circle is one face, labelled by its smallest triangle index. Only a
// triangle with a co-circular neighbour further on can start a cluster (its smallest triangle
// has one). The floods read the co-circular edges ComputeTriangleCentres found (each adjacent
// pair was tested once, from its smaller triangle) instead of testing the pairs again: on a
// lattice, where every pair across a square's diagonal is co-circular, those tests were exact
// evaluations.
//
// Chunks of triangles merge clusters in parallel, each flooding from its triangles that have a
// co-circular bit and keeping a cluster only if no member comes before the triangle it started from
// (its smallest index, so exactly one chunk keeps it). The chunk that keeps a cluster labels its
// triangles and computes its centre (no other chunk reads or writes those entries: the floods read
// only the bits and the half-edge arrays); the clusters' polygons are then recorded in chunk order,
// i.e. by ascending smallest triangle, as a serial scan would.
struct TessellationDual::ClusterList
{
  std::vector<std::int32_t> Roots;
  std::vector<std::int32_t> PolygonStarts{ 0 };
  std::vector<std::int32_t> Polygons; ///< each anticlockwise from its smallest point id
};

void TessellationDual::LabelFaces(const std::vector<std::uint8_t>& cocircular)
{
  const std::int32_t triangles = std::int32_t(this->Data.size());
  if (std::none_of(
        cocircular.begin(), cocircular.end(), [](std::uint8_t bits) { return bits != 0; }))
  {
    return;
  }
  const std::vector<std::int32_t> bounds = ChunkBounds(triangles, ThreadCount(triangles));
  std::vector<ClusterList> found(bounds.size() - 1);
  RunChunks(bounds.size() - 1,
    [&](std::size_t k) { this->MergeClusters(bounds[k], bounds[k + 1], cocircular, found[k]); });
  this->RecordClusters(bounds, found);
}

// The clusters whose smallest triangle is in [begin, end): each one's triangles labelled with it,
// its polygon listed in found, and its centre taken from its points (FaceCentre) with its inside
// flag decided exactly (the rounded centre and its error bound settle almost every face,
// CircumcentreSide the rest).
void TessellationDual::MergeClusters(std::int32_t begin,
  std::int32_t end,
  const std::vector<std::uint8_t>& cocircular,
  ClusterList& found)
{
  const auto& org = this->Tess.Origin();
  const auto& twin = this->Tess.Twin();
  std::vector<std::uint8_t> visited(this->Data.size(), 0); // this chunk's floods only
  std::vector<std::int32_t> cluster, stack, boundary;
  // A cluster's other triangles are random loads (on a lattice, one per cluster, and they were
  // most of the time): request those of the clusters a few triangles ahead.
  constexpr std::int32_t ahead = 8;
  const std::int32_t prefetchEnd = std::max(begin, end - ahead);
  for (std::int32_t t = begin; t < end; ++t)
  {
    if (t < prefetchEnd)
    {
      const std::int32_t next = t + ahead;
      for (std::int32_t k = 0; k < 3; ++k)
      {
        if (cocircular[next] >> k & 1U)
        {
          const std::int32_t u = twin[3 * next + k] / 3;
          __builtin_prefetch(twin.data() + 3 * u);
          __builtin_prefetch(org.data() + 3 * u);
          __builtin_prefetch(visited.data() + u);
          __builtin_prefetch(this->Data.data() + u, 1);
        }
      }
    }
    if (!cocircular[t] || visited[t])
    {
      continue;
    }
    if (this->FloodCircle(t, cocircular, visited, cluster, stack, boundary))
    {
      this->KeepCluster(t, cluster, boundary, found);
    }
    // (else an earlier chunk keeps this cluster)
  }
}

// Floods t's circle through the co-circular edges (each recorded by its smaller triangle) into
// cluster; whether t is the cluster's smallest triangle. The flood lists the face's boundary edges
// as it goes (the edges it does not cross), so that no membership test reads the triangles
// outside: on a lattice those were random loads, four per face, and cost as much as the rest.
bool TessellationDual::FloodCircle(std::int32_t t,
  const std::vector<std::uint8_t>& cocircular,
  std::vector<std::uint8_t>& visited,
  std::vector<std::int32_t>& cluster,
  std::vector<std::int32_t>& stack,
  std::vector<std::int32_t>& boundary) const
{
  const auto& twin = this->Tess.Twin();
  visited[t] = 1;
  cluster.assign(1, t);
  stack.assign(1, t);
  boundary.clear();
  bool smallest = true;
  while (!stack.empty())
  {
    const std::int32_t s = stack.back();
    stack.pop_back();
    for (std::int32_t k = 0; k < 3; ++k)
    {
      const std::int32_t f = twin[3 * s + k];
      const std::int32_t u = f / 3;
      const bool across = u > s ? cocircular[s] >> k & 1U : cocircular[u] >> (f - 3 * u) & 1U;
      if (!across)
      {
        // Not across: u is off the circle (two adjacent triangles on one circle always have
        // their edge's bit), so this edge bounds the face.
        boundary.push_back(3 * s + k);
      }
      else if (!visited[u])
      {
        visited[u] = 1;
        cluster.push_back(u);
        stack.push_back(u);
        smallest = smallest && u > t;
      }
    }
  }
  return smallest;
}

// The cluster rooted at t (its smallest triangle): its triangles labelled with t, its polygon
// (the boundary chained, from the smallest id) listed in found, and its centre taken from its
// points with its inside flag decided exactly.
void TessellationDual::KeepCluster(std::int32_t t,
  const std::vector<std::int32_t>& cluster,
  std::vector<std::int32_t>& boundary,
  ClusterList& found)
{
  const std::size_t polygonStart = found.Polygons.size();
  ChainBoundary(this->Tess.Origin().data(), boundary, found.Polygons);
  found.PolygonStarts.push_back(std::int32_t(found.Polygons.size()));
  found.Roots.push_back(t);
  for (const std::int32_t member : cluster)
  {
    this->Data[member].Face = t;
    this->Data[member].Vertex = -1; // not a representative (the root's is set below)
  }
  double error = 0.0;
  const Point2 centre =
    FaceCentre(this->Tess.Points(), found.Polygons.data() + polygonStart, boundary.size(), error);
  TriangleData& data = this->Data[t];
  data.X = centre.x;
  data.Y = centre.y;
  data.Vertex = CentreInside(this->Tess, t, centre, error) ? 0 : -1;
}

// The chunks' clusters, in chunk order, as the degenerate faces' lists. Each chunk copies its own
// part; its clusters' roots lie in its range of triangles, so it also fills that range of the
// index (a serial pass took 21 ms on the 1000 x 1000 lattice).
void TessellationDual::RecordClusters(const std::vector<std::int32_t>& bounds,
  const std::vector<ClusterList>& found)
{
  const std::size_t chunks = found.size();
  std::vector<std::int32_t> faceBase(chunks + 1, 0), vertexBase(chunks + 1, 0);
  for (std::size_t k = 0; k < chunks; ++k)
  {
    faceBase[k + 1] = faceBase[k] + std::int32_t(found[k].Roots.size());
    vertexBase[k + 1] = vertexBase[k] + std::int32_t(found[k].Polygons.size());
  }
  this->DegenerateIndex.resize(this->Data.size());
  this->DegenerateReps.resize(std::size_t(faceBase[chunks]));
  this->DegenerateStarts.resize(std::size_t(faceBase[chunks]) + 1);
  this->DegenerateStarts[0] = 0;
  this->DegenerateVertices.resize(std::size_t(vertexBase[chunks]));
  RunChunks(chunks,
    [&](std::size_t k)
    {
      const ClusterList& list = found[k];
      std::fill(this->DegenerateIndex.begin() + bounds[k],
        this->DegenerateIndex.begin() + bounds[k + 1],
        -1);
      for (std::size_t c = 0; c < list.Roots.size(); ++c)
      {
        const std::int32_t face = faceBase[k] + std::int32_t(c);
        this->DegenerateIndex[list.Roots[c]] = face;
        this->DegenerateReps[face] = list.Roots[c];
        this->DegenerateStarts[face + 1] = vertexBase[k] + list.PolygonStarts[c + 1];
      }
      std::copy(list.Polygons.begin(),
        list.Polygons.end(),
        this->DegenerateVertices.begin() + vertexBase[k]);
    });
}

const std::int32_t* TessellationDual::DegeneratePolygon(std::int32_t face, std::int32_t& size) const
{
  if (this->DegenerateIndex.empty() || this->DegenerateIndex[face] < 0)
  {
    size = 0;
    return nullptr;
  }
  const std::int32_t k = this->DegenerateIndex[face];
  size = this->DegenerateStarts[k + 1] - this->DegenerateStarts[k];
  return this->DegenerateVertices.data() + this->DegenerateStarts[k];
}

// ---------------------------------------------------------------------------------------------
// Tile edges.

FaceView TessellationDual::View(std::int32_t label) const
{
  if (label < 0)
  {
    return FaceView();
  }
  return { label, this->Data[label].Centre(), this->Data[label].Inside() };
}

// Collinear case: the neighbours along the line (-1 where there is none).
std::int32_t TessellationDual::Neighbors1D(std::int32_t v, std::int32_t& next) const
{
  const auto& line = this->Tess.CollinearPoints();
  const std::int32_t k = this->LinePosition[v];
  next = k + 1 < std::int32_t(line.size()) ? line[k + 1] : -1;
  return k > 0 ? line[k - 1] : -1;
}

// Collinear case: two parallel edges; either cyclic order is anticlockwise, start at the
// smaller id.
void TessellationDual::CollinearTileEdges(std::int32_t v, std::vector<TileEdge>& edges) const
{
  edges.clear();
  TileEdge edge;
  std::int32_t next = -1;
  const std::int32_t previous = this->Neighbors1D(v, next);
  std::int32_t order[2] = { next, previous };
  if (previous >= 0 && (next < 0 || previous < next))
  {
    std::swap(order[0], order[1]);
  }
  for (const std::int32_t j : order)
  {
    if (j >= 0 && ClipEdge(this->Tess, v, j, FaceView(), FaceView(), edge))
    {
      edges.push_back(edge);
    }
  }
}

// ---------------------------------------------------------------------------------------------
// Results.

// Tiles and contiguities are computed for contiguous chunks of Order in parallel, then joined in
// order: the result does not depend on the number of threads. A TileSet's chunks fill arrays of
// their own (chunk 0 straight into the result), which the join appends. A TileMesh's and a
// graph's chunks write in place: each chunk's tiles have known places in the per-tile columns,
// and its vertex ids and pairs go to a region of the result sized from an estimate, which the
// join slides down against the region before (ChunkArray). At 10^7 points appending the second
// chunk's arrays took 650 ms, most of it first touches of the result's pages.
//
//   result:   [ chunk 0's ids ....... gap | chunk 1's ids ......... gap | ... ]
//   joined:   [ chunk 0's ids ....... chunk 1's ids ......... ... ]

struct TessellationDual::RingScratch
{
  std::vector<std::int32_t> Ring; ///< the half-edges leaving the point (planar case)
  std::vector<TileEdge> Edges;
  std::vector<Point2> Polygon;
  bool Interior = false;            ///< the polygon came from the ring of centres
  std::vector<std::int32_t> Labels; ///< an interior tile's faces (mesh)
  std::vector<std::pair<std::int32_t, std::int32_t>> SameCentre; ///< faces at one rounded point
  std::vector<std::pair<std::int32_t, std::uint8_t>> Around;
  std::vector<std::int32_t> Larger; ///< an interior tile's neighbours with larger ids
  TileEdge Edge;
  /// A clipped tile with many edges (mesh): the mesh vertices its edges end at, by place, so
  /// that MeshVertexOf finds a polygon vertex's without scanning every edge.
  struct EndAt
  {
    double X, Y;
    std::int32_t Order; ///< the end's position in Edges (Lo, Hi of each edge in turn)
    std::int32_t Vertex;
    bool operator<(const EndAt& o) const
    {
      return std::tie(this->X, this->Y, this->Order) < std::tie(o.X, o.Y, o.Order);
    }
  };
  std::vector<EndAt> Ends;
};

namespace tiles_detail
{
/// One chunk's share of an array that the chunks fill side by side: a region of the result,
/// written in place, and then, should the region's estimated size fall short, a vector of its own
/// (Spill) for the rest.
template<class T>
class ChunkArray
{
public:
  void Bind(T* begin, std::size_t capacity)
  {
    this->Begin = this->At = begin;
    this->End = begin + capacity;
  }
  void push_back(T value)
  {
    if (this->At != this->End)
    {
      *this->At++ = value;
    }
    else
    {
      this->Spill.push_back(value);
    }
  }
  std::size_t InRegion() const { return std::size_t(this->At - this->Begin); }
  std::size_t size() const { return this->InRegion() + this->Spill.size(); }
  const T* Region() const { return this->Begin; }
  const std::vector<T>& Spilled() const { return this->Spill; }

private:
  T* Begin = nullptr;
  T* At = nullptr;
  T* End = nullptr;
  std::vector<T> Spill;
};

/// Sizes result for the parts' regions of their arrays (capacity[k] elements for part k, in
/// order) and binds each part's to its own.
template<class T, class Part>
void BindRegions(UninitializedVector<T>& result,
  std::vector<Part>& parts,
  ChunkArray<T> Part::*array,
  const std::vector<std::size_t>& capacity)
{
  const std::size_t total = std::accumulate(capacity.begin(), capacity.end(), std::size_t(0));
  result.resize(total); // uninitialised: each chunk first touches its own region
  T* begin = result.data();
  for (std::size_t k = 0; k < parts.size(); ++k)
  {
    (parts[k].*array).Bind(begin, capacity[k]);
    begin += capacity[k];
  }
}

/// Joins the parts' arrays in order into result; returns where each part begins in the joined
/// array, and its end. Without a spill the regions slide down in order (part k's never lies
/// below where it belongs, as every part before it fitted its region); with one, the parts are
/// copied into a new array.
template<class T, class Part>
std::vector<std::int64_t> JoinRegions(UninitializedVector<T>& result,
  const std::vector<Part>& parts,
  ChunkArray<T> Part::*array)
{
  std::vector<std::int64_t> base(parts.size() + 1, 0);
  bool spilled = false;
  for (std::size_t k = 0; k < parts.size(); ++k)
  {
    base[k + 1] = base[k] + std::int64_t((parts[k].*array).size());
    spilled = spilled || !(parts[k].*array).Spilled().empty();
  }
  if (!spilled)
  {
    for (std::size_t k = 1; k < parts.size(); ++k)
    {
      const ChunkArray<T>& part = parts[k].*array;
      std::memmove(result.data() + base[k], part.Region(), part.InRegion() * sizeof(T));
    }
    result.resize(std::size_t(base.back()));
    return base;
  }
  UninitializedVector<T> joined(std::size_t(base.back()));
  for (std::size_t k = 0; k < parts.size(); ++k)
  {
    const ChunkArray<T>& part = parts[k].*array;
    T* to = std::copy(part.Region(), part.Region() + part.InRegion(), joined.data() + base[k]);
    std::copy(part.Spilled().begin(), part.Spilled().end(), to);
  }
  result.swap(joined);
  return base;
}

/// Room for a chunk of `tiles` tiles at `perTile` entries each, with a margin for a chunk whose
/// points have more neighbours than the average (a chunk is a compact region of the plane: the
/// excess is at most proportional to its border) and for the tiles the window clips.
inline std::size_t EstimatedRoom(std::size_t tiles, std::size_t perTile)
{
  return perTile * tiles + 16 * std::size_t(std::sqrt(double(tiles))) + 256;
}
} // namespace tiles_detail

// A chunk's mesh tiles. Its per-tile columns go straight to the result's, from tile Next on; its
// vertex ids to VertexIds (Offsets counting from its start until the join adds its base). Face
// centres and window corners have their final vertex ids already (NumberFaceVertices, then
// Derive). A crossing is appended to Crossings as it is met: chunk 0's is the result's Vertices,
// which already hold the faces and corners, so its ids are final too; a later chunk starts from
// an empty list of its own, and the join adds its base to the ids at ExtraSlots.
// Written as each tile is made, by its chunk's thread: on cache lines of its own (cache_line.h).
struct alignas(CacheLineBytes) TessellationDual::MeshPart
{
  TileMesh* Result = nullptr;
  std::int64_t Next = 0; ///< the result's index of this chunk's next tile
  tiles_detail::ChunkArray<std::int32_t> VertexIds;
  UninitializedVector<Point2>* Crossings = nullptr;
  UninitializedVector<Point2> OwnCrossings;
  std::int32_t CornerBase = 0; ///< vertex id of window corner 0
  /// The window corners by coordinates (x, y, index), for a binary search; one list for all parts.
  const std::vector<std::tuple<double, double, std::int32_t>>* Corners = nullptr;
  std::vector<std::int64_t> ExtraSlots;
  /// Pairs of face vertices a tile met at one point (distinct faces whose rounded centres
  /// coincide): the join makes each such group one vertex, so that every tile names it alike.
  std::vector<std::pair<std::int32_t, std::int32_t>> SameVertex;
};

// A chunk's contiguities, in its regions of the result's arrays; on cache lines of its own, as a
// MeshPart.
struct alignas(CacheLineBytes) TessellationDual::GraphPart
{
  tiles_detail::ChunkArray<std::int32_t> Pairs;
  tiles_detail::ChunkArray<std::uint8_t> Kinds;
};

TileSet TessellationDual::Tiles() const
{
  TileSet tiles;
  this->Derive(&tiles, nullptr, nullptr);
  return tiles;
}

ContiguityGraph TessellationDual::Contiguities() const
{
  ContiguityGraph graph;
  this->Derive(nullptr, nullptr, &graph);
  return graph;
}

TilesAndGraph TessellationDual::TilesAndContiguities() const
{
  TilesAndGraph both;
  this->Derive(&both.Tiles, nullptr, &both.Graph);
  return both;
}

TileMeshAndGraph TessellationDual::TileMeshAndContiguities(bool withContiguities)
{
  TileMeshAndGraph both;
  this->NumberFaceVertices(both.Tiles.Vertices);
  this->Derive(nullptr, &both.Tiles, withContiguities ? &both.Graph : nullptr);
  return both;
}

// Numbers the representatives whose centre is inside the window in the order of the triangle
// arrays (Vertex), and lists their centres in that order: a count per chunk of triangles, then
// each chunk numbers and copies its own.
void TessellationDual::NumberFaceVertices(UninitializedVector<Point2>& vertices)
{
  const std::int32_t triangles = std::int32_t(this->Data.size());
  const std::vector<std::int32_t> bounds =
    ChunkBounds(triangles, ThreadCount(triangles, MinimumTrianglesPerThread));
  const std::size_t chunks = bounds.size() - 1;
  std::vector<std::int32_t> first(chunks + 1, 0);
  RunChunks(chunks,
    [&](std::size_t k)
    {
      std::int32_t count = 0;
      for (std::int32_t t = bounds[k]; t < bounds[k + 1]; ++t)
      {
        count += this->Data[t].Inside() ? 1 : 0;
      }
      first[k + 1] = count;
    });
  for (std::size_t k = 0; k < chunks; ++k)
  {
    first[k + 1] += first[k];
  }
  // Room for what Derive appends (the window's corners, then the crossings, about as many as
  // the tiles along the window's boundary): growing a full vector doubles it, which at 10^7
  // points copied 305 MB into 610 MB of fresh pages.
  const std::size_t centres = std::size_t(first[chunks]);
  vertices.reserve(centres + this->Tess.GetWindow().Vertices().size() +
    4 * std::size_t(std::sqrt(double(centres))) + 64);
  vertices.resize(centres);
  RunChunks(chunks,
    [&](std::size_t k)
    {
      std::int32_t next = first[k];
      for (std::int32_t t = bounds[k]; t < bounds[k + 1]; ++t)
      {
        TriangleData& data = this->Data[t];
        if (data.Inside())
        {
          vertices[std::size_t(next)] = data.Centre();
          data.Vertex = next++;
        }
      }
    });
}

TileMesh MeshOfNumberedCorners(TileSet tiles, const std::vector<std::int32_t>& cornerVertexIds)
{
  if (cornerVertexIds.size() != tiles.Vertices.size())
  {
    throw std::logic_error("MeshOfNumberedCorners: " + std::to_string(cornerVertexIds.size()) +
      " vertex ids for " + std::to_string(tiles.Vertices.size()) + " corners");
  }
  TileMesh mesh;
  mesh.PointIds.assign(tiles.PointIds.begin(), tiles.PointIds.end());
  mesh.Offsets.assign(tiles.Offsets.begin(), tiles.Offsets.end());
  mesh.VertexIds.assign(cornerVertexIds.begin(), cornerVertexIds.end());
  for (std::size_t k = 0; k < cornerVertexIds.size(); ++k)
  {
    if (std::size_t(cornerVertexIds[k]) == mesh.Vertices.size()) // (first come: the next id)
    {
      mesh.Vertices.push_back(tiles.Vertices[k]);
    }
  }
  mesh.Areas.assign(tiles.Areas.begin(), tiles.Areas.end());
  mesh.NeighborCounts.assign(tiles.NeighborCounts.begin(), tiles.NeighborCounts.end());
  return mesh;
}

void ScaleByPowerOfTwo(TileMesh& mesh, int exponent)
{
  for (Point2& v : mesh.Vertices)
  {
    v = { std::ldexp(v.x, exponent), std::ldexp(v.y, exponent) };
  }
  for (double& area : mesh.Areas)
  {
    area = std::ldexp(area, 2 * exponent);
  }
}

/// The tiles fill the window, so their areas add up to its area. Points closer together than the
/// tile derivation's exact range allows (some 1e-60 of the window's size, where the products of
/// its window decisions underflow) can break that: an error then, rather than wrong tiles.
void CheckTilesFillWindow(const TileMesh& tiles,
  double windowArea,
  std::optional<double> cornerRounding)
{
  if (tiles.Areas.empty())
  {
    return;
  }
  if (!std::isfinite(windowArea) || windowArea == 0.0)
  {
    // (a window of 1e308 or 1e-200 on a side: no sum of areas can be compared with it)
    throw InputError("the window's area " + NumberText(windowArea) +
      " is beyond the doubles' range, so the tiles' areas cannot be checked against it: scale the "
      "points and the window (ScaleIntoExactRange) and measure the scaled tiles");
  }
  // (a plain sum: its rounding, some n ulps at most, is far inside the 1e-6 tolerance)
  const double total = std::accumulate(tiles.Areas.begin(), tiles.Areas.end(), 0.0);
  if (!(std::fabs(total - windowArea) <= 1e-6 * windowArea + cornerRounding.value_or(0.0)))
  {
    // (a C++ caller who gives no cornerRounding: a small slanted window far from the origin then
    // fails on its rounded corners alone, as a user's did, 2^-40 wide at 0.5)
    const std::string corners = cornerRounding
      ? ""
      : " (or, for a window with a slanted side, its corners' rounding: pass "
        "CornerRoundingOfTiles(window) as cornerRounding)";
    throw InputError("the tiles' areas add up to " + NumberText(total) +
      ", not the window's area " + NumberText(windowArea) +
      ": the points lie too close together, for the window's size, for exact tiles (their "
      "coordinates differ by some 1e-60 of it or less)" +
      corners);
  }
}

double CornerRoundingOfTiles(const Window& window)
{
  if (window.IsAxisAlignedRectangle())
  {
    return 0.0;
  }
  const std::vector<Point2>& corners = window.Vertices();
  double perimeter = 0.0;
  for (std::size_t k = 0; k < corners.size(); ++k)
  {
    const Point2& a = corners[k];
    const Point2& b = corners[(k + 1) % corners.size()];
    perimeter += std::hypot(b.x - a.x, b.y - a.y);
  }
  // (four ulps: a crossing of a slanted side is computed, t = -h(m) / h(d) then m + t d, and may
  // lie some two ulps off it, not only the half ulp of a correctly rounded corner)
  const double reach = window.Reach();
  return 4.0 * perimeter * (std::nextafter(reach, HUGE_VAL) - reach);
}

namespace
{
// Room for count tiles of a TileSet, and the leading 0 offset.
void ReserveTiles(TileSet& tiles, std::size_t count)
{
  tiles.PointIds.reserve(count);
  tiles.Offsets.reserve(count + 1);
  tiles.Areas.reserve(count);
  tiles.NeighborCounts.reserve(count);
  tiles.Vertices.reserve(6 * count + 16);
  tiles.Offsets.push_back(0);
}

// Keeps, of the vertices from `from` on, those that stand for themselves (representative[k] == k
// for vertex from + k; a representative comes before the vertices it stands for), in their order,
// and returns each vertex's new id: its own or its representative's.
std::vector<std::int32_t> KeepRepresentatives(UninitializedVector<Point2>& vertices,
  std::int32_t from,
  const std::vector<std::int32_t>& representative)
{
  std::vector<std::int32_t> renumbered(representative.size());
  std::int32_t kept = from;
  for (std::size_t k = 0; k < representative.size(); ++k)
  {
    if (representative[k] == std::int32_t(k))
    {
      vertices[std::size_t(kept)] = vertices[std::size_t(from) + k];
      renumbered[k] = kept++;
    }
    else
    {
      renumbered[k] = renumbered[std::size_t(representative[k])];
    }
  }
  vertices.resize(std::size_t(kept));
  return renumbered;
}

// Both tiles of a clipped edge compute its crossing with the window boundary from the same point
// pair in the same order (ClipEdge), so their copies have the same coordinates. Equal crossings
// become one vertex (the first listed), so that the tiles share their vertices along the window
// boundary too: crossings are the vertices from firstCrossing on, slots where VertexIds name them.
void MergeEqualCrossings(TileMesh& mesh,
  std::int32_t firstCrossing,
  const std::vector<std::int64_t>& slots)
{
  const std::int32_t count = std::int32_t(mesh.Vertices.size()) - firstCrossing;
  const Point2* crossing = mesh.Vertices.data() + firstCrossing;
  std::vector<std::int32_t> sorted(static_cast<std::size_t>(count));
  std::iota(sorted.begin(), sorted.end(), 0);
  std::sort(sorted.begin(),
    sorted.end(),
    [&](std::int32_t a, std::int32_t b)
    {
      return std::make_tuple(crossing[a].x, crossing[a].y, a) <
        std::make_tuple(crossing[b].x, crossing[b].y, b);
    });
  // Each crossing's representative: the first crossing equal to it.
  std::vector<std::int32_t> first(static_cast<std::size_t>(count));
  for (std::size_t s = 0; s < sorted.size(); ++s)
  {
    const bool repeat = s > 0 && crossing[sorted[s]] == crossing[sorted[s - 1]];
    first[std::size_t(sorted[s])] = repeat ? first[std::size_t(sorted[s - 1])] : sorted[s];
  }
  const std::vector<std::int32_t> renumbered =
    KeepRepresentatives(mesh.Vertices, firstCrossing, first);
  for (const std::int64_t slot : slots)
  {
    std::int32_t& id = mesh.VertexIds[std::size_t(slot)];
    id = renumbered[std::size_t(id - firstCrossing)];
  }
}

// Makes each group of vertices joined by the pairs one vertex (its smallest id), drops the others
// and renumbers: distinct faces whose rounded centres coincide, which a tile lists once (dropping
// the repeat) and its neighbours each by their own face. Rare; one pass over the ids when any.
void MergeSameVertices(TileMesh& mesh,
  const std::vector<std::pair<std::int32_t, std::int32_t>>& pairs)
{
  if (pairs.empty())
  {
    return;
  }
  std::vector<std::int32_t> root(mesh.Vertices.size());
  std::iota(root.begin(), root.end(), 0);
  const auto find = [&](std::int32_t v)
  {
    while (root[std::size_t(v)] != v)
    {
      root[std::size_t(v)] = root[std::size_t(root[std::size_t(v)])];
      v = root[std::size_t(v)];
    }
    return v;
  };
  for (const auto& [a, b] : pairs)
  {
    const std::int32_t ra = find(a), rb = find(b);
    root[std::size_t(std::max(ra, rb))] = std::min(ra, rb);
  }
  for (std::size_t v = 0; v < root.size(); ++v)
  {
    root[v] = find(std::int32_t(v)); // each group's smallest id
  }
  const std::vector<std::int32_t> renumbered = KeepRepresentatives(mesh.Vertices, 0, root);
  for (std::int32_t& id : mesh.VertexIds)
  {
    id = renumbered[std::size_t(id)];
  }
}

} // namespace

// The mesh's vertices: its face centres (numbered already), the window's corners when there are
// tiles to use them, then the crossings from the returned index on. Chunk 0's crossings go
// straight to the result; each chunk's vertex ids get their room in mesh.VertexIds.
std::int32_t TessellationDual::PrepareMeshParts(TileMesh& mesh,
  const std::vector<std::int32_t>& bounds,
  std::vector<MeshPart>& parts,
  std::vector<std::tuple<double, double, std::int32_t>>& sortedCorners) const
{
  const std::size_t count = std::size_t(bounds.back());
  const std::vector<Point2>& corners = this->Tess.GetWindow().Vertices();
  const std::int32_t cornerBase = std::int32_t(mesh.Vertices.size());
  if (count > 0)
  {
    mesh.Vertices.insert(mesh.Vertices.end(), corners.begin(), corners.end());
  }
  const std::int32_t firstCrossing = std::int32_t(mesh.Vertices.size());
  for (std::size_t k = 0; k < corners.size(); ++k)
  {
    sortedCorners.emplace_back(corners[k].x, corners[k].y, std::int32_t(k));
  }
  std::sort(sortedCorners.begin(), sortedCorners.end());
  mesh.PointIds.resize(count);
  mesh.Offsets.resize(count + 1);
  mesh.Offsets[0] = 0;
  mesh.Areas.resize(count);
  mesh.NeighborCounts.resize(count);
  std::vector<std::size_t> room;
  for (std::size_t k = 0; k + 1 < bounds.size(); ++k)
  {
    MeshPart& part = parts[k];
    part.Result = &mesh;
    part.Next = bounds[k];
    part.Crossings = k == 0 ? &mesh.Vertices : &part.OwnCrossings;
    part.CornerBase = cornerBase;
    part.Corners = &sortedCorners;
    // a tile has 6 vertices on average
    room.push_back(tiles_detail::EstimatedRoom(std::size_t(bounds[k + 1] - bounds[k]), 6));
  }
  tiles_detail::BindRegions(mesh.VertexIds, parts, &MeshPart::VertexIds, room);
  return firstCrossing;
}

// Each chunk's room in the graph's pairs and kinds: 3 pairs per point on average (each of the 3n
// Delaunay edges once), plus the diagonals of the degenerate faces, spread evenly (halfPerPoint).
void TessellationDual::PrepareGraphParts(ContiguityGraph& graph,
  const std::vector<std::int32_t>& bounds,
  double halfPerPoint,
  std::vector<GraphPart>& parts)
{
  using tiles_detail::EstimatedRoom;
  std::vector<std::size_t> pairRoom, kindRoom;
  for (std::size_t k = 0; k + 1 < bounds.size(); ++k)
  {
    const std::size_t size = std::size_t(bounds[k + 1] - bounds[k]);
    const std::size_t extra = std::size_t(std::ceil(halfPerPoint * double(size)));
    pairRoom.push_back(EstimatedRoom(size, 6) + 2 * extra);
    kindRoom.push_back(EstimatedRoom(size, 3) + extra);
  }
  tiles_detail::BindRegions(graph.Pairs, parts, &GraphPart::Pairs, pairRoom);
  tiles_detail::BindRegions(graph.Kinds, parts, &GraphPart::Kinds, kindRoom);
}

// The requested results (any pointer may be null) in one pass over the rings, so that asking
// for several walks each ring once: the walks are cache misses, and walking twice cost as much
// again as the contiguity tests.
void TessellationDual::Derive(TileSet* tiles, TileMesh* mesh, ContiguityGraph* graph) const
{
  CheckWindowInExactRange(this->Tess); // (the faces alone need no window: they are exact anywhere)
  // Half-neighbours: the diagonals of the degenerate faces whose centre is in the window.
  const std::int64_t halfPairs = graph ? this->HalfNeighbourPairCount() : 0;
  const bool half = halfPairs > 0;
  const std::int32_t count = std::int32_t(this->Order.size());
  const std::vector<std::int32_t> bounds =
    ChunkBounds(count, ThreadCount(count, MinimumTilesPerThread));
  const std::size_t chunks = bounds.size() - 1;
  const auto sizeOf = [&](std::size_t k) { return std::size_t(bounds[k + 1] - bounds[k]); };
  // Every chunk's tiles, chunk 0's too, on cache lines of their own: a chunk writes its vectors'
  // ends at every tile, and the caller's TileSet may share a line with what the other chunks read
  // at every tile (TilesOnly at 10^5 points took 9.4-10.3 ms or 13.7-14.0 ms as the stack fell).
  std::vector<OwnCacheLines<TileSet>> tileParts(tiles ? chunks : 0);
  std::vector<MeshPart> meshParts(mesh ? chunks : 0);
  std::vector<GraphPart> graphParts(graph ? chunks : 0);
  std::vector<std::tuple<double, double, std::int32_t>> sortedCorners;
  std::int32_t firstCrossing = 0;
  if (mesh)
  {
    firstCrossing = this->PrepareMeshParts(*mesh, bounds, meshParts, sortedCorners);
  }
  if (graph)
  {
    PrepareGraphParts(*graph, bounds, half ? double(halfPairs) / count : 0.0, graphParts);
  }
  RunChunks(chunks,
    [&](std::size_t k)
    {
      TileSet* chunkTiles = tiles ? &tileParts[k].Value : nullptr;
      if (chunkTiles)
      {
        ReserveTiles(*chunkTiles, k == 0 ? std::size_t(count) : sizeOf(k));
      }
      this->DeriveOf(bounds[k],
        bounds[k + 1],
        half,
        chunkTiles,
        mesh ? &meshParts[k] : nullptr,
        graph ? &graphParts[k] : nullptr);
    });
  const auto joinTiles = [&]()
  {
    if (tiles)
    {
      *tiles = tiles_detail::JoinTileParts(tileParts);
    }
    if (mesh)
    {
      this->JoinMeshParts(*mesh, bounds, meshParts, firstCrossing);
    }
  };
  const auto joinGraph = [&]()
  {
    if (graph)
    {
      tiles_detail::JoinRegions(graph->Pairs, graphParts, &GraphPart::Pairs);
      tiles_detail::JoinRegions(graph->Kinds, graphParts, &GraphPart::Kinds);
    }
  };
  parallel::RunSideBySide(chunks > 1 && graph && (tiles || mesh), joinTiles, joinGraph);
}

// Joins the mesh's chunks: their vertex ids slide together, a later chunk's offsets get its
// base, its crossings are appended to the vertices (their ids get the vertices' count before
// them), and then equal crossings and coinciding centres become one vertex each.
void TessellationDual::JoinMeshParts(TileMesh& mesh,
  const std::vector<std::int32_t>& bounds,
  std::vector<MeshPart>& parts,
  std::int32_t firstCrossing) const
{
  const std::vector<std::int64_t> base =
    tiles_detail::JoinRegions(mesh.VertexIds, parts, &MeshPart::VertexIds);
  std::vector<std::int64_t>& slots = parts[0].ExtraSlots; // chunk 0's are final already
  for (std::size_t k = 1; k < parts.size(); ++k)
  {
    for (std::int32_t t = bounds[k] + 1; t <= bounds[k + 1]; ++t)
    {
      mesh.Offsets[std::size_t(t)] += base[k];
    }
    const std::int32_t vertexBase = std::int32_t(mesh.Vertices.size());
    for (const std::int64_t slot : parts[k].ExtraSlots)
    {
      mesh.VertexIds[std::size_t(base[k] + slot)] += vertexBase;
      slots.push_back(base[k] + slot);
    }
    mesh.Vertices.insert(
      mesh.Vertices.end(), parts[k].OwnCrossings.begin(), parts[k].OwnCrossings.end());
  }
  MergeEqualCrossings(mesh, firstCrossing, slots);
  std::vector<std::pair<std::int32_t, std::int32_t>> same;
  for (const MeshPart& part : parts)
  {
    same.insert(same.end(), part.SameVertex.begin(), part.SameVertex.end());
  }
  MergeSameVertices(mesh, same);
}

// The number of half-neighbour pairs: the non-adjacent vertex pairs of the degenerate faces
// whose centre is in the window, m (m - 3) / 2 for a face of m points (m >= 4: none is zero).
std::int64_t TessellationDual::HalfNeighbourPairCount() const
{
  std::int64_t pairs = 0;
  for (const std::int32_t rep : this->DegenerateReps)
  {
    std::int32_t size = 0;
    if (this->Data[rep].Inside() && this->DegeneratePolygon(rep, size))
    {
      pairs += std::int64_t(size) * (size - 3) / 2;
    }
  }
  return pairs;
}

// v's half-neighbours with larger ids, appended to around with Kind 1: of each degenerate face
// around v (a run of ring triangles with one label, taken at its first) whose centre is in the
// window, the vertices other than v and its two neighbours along the face's polygon. A pair is
// a diagonal of one face only (a diagonal of a convex face lies inside it), so nothing repeats.
void TessellationDual::AppendHalfNeighboursOf(std::int32_t v,
  const std::vector<std::int32_t>& ring,
  std::vector<std::pair<std::int32_t, std::uint8_t>>& around) const
{
  std::int32_t previous = this->Data[ring.back() / 3].Face;
  for (const std::int32_t e : ring)
  {
    const std::int32_t face = this->Data[e / 3].Face;
    const bool first = face != previous;
    previous = face;
    std::int32_t size = 0;
    const std::int32_t* polygon = first && face >= 0 && this->Data[face].Inside()
      ? this->DegeneratePolygon(face, size)
      : nullptr;
    if (!polygon)
    {
      continue; // not the start of a run, a ghost, outside, or a single triangle
    }
    const std::int32_t at = std::int32_t(std::find(polygon, polygon + size, v) - polygon);
    for (std::int32_t k = 2; k + 1 < size; ++k)
    {
      const std::int32_t j = polygon[(at + k) % size];
      if (j > v)
      {
        around.emplace_back(j, std::uint8_t(1));
      }
    }
  }
}

// The results for the points Order[begin .. end), appended to tiles and graph (either may be
// null; tiles' Offsets already has its first 0). Each point's ring is collected once for both.
void TessellationDual::DeriveOf(std::int32_t begin,
  std::int32_t end,
  bool half,
  TileSet* tiles,
  MeshPart* mesh,
  GraphPart* graph) const
{
  RingScratch scratch;
  const bool planar = this->Tess.IsTwoDimensional();
  for (std::int32_t k = begin; k < end; ++k)
  {
    if (planar && (k - begin) % RingBatch == 0)
    {
      this->TouchRings(k, std::min(end, k + RingBatch));
    }
    const std::int32_t v = this->Order[k];
    if (planar)
    {
      CollectRing(this->Tess, this->OrderEdge[k], scratch.Ring);
    }
    if (tiles)
    {
      this->AppendTileOf(v, scratch, *tiles);
    }
    if (mesh)
    {
      this->AppendMeshTileOf(v, scratch, *mesh);
    }
    if (graph)
    {
      this->AppendContiguitiesOf(v, half, scratch, *graph);
    }
  }
}

// Point v's tile polygon into scratch.Polygon (scratch.Ring: its ring when planar; a strip
// between its line neighbours when the points are collinear); returns its number of sides. An
// interior tile sets scratch.Interior, and with labels (the mesh) also scratch.Labels and
// scratch.SameCentre; any other tile leaves its clipped edges in scratch.Edges.
std::int32_t TessellationDual::TilePolygonOf(std::int32_t v,
  RingScratch& scratch,
  bool withLabels) const
{
  scratch.Interior = false;
  if (this->Tess.IsTwoDimensional())
  {
    return RingTilePolygon(this->Tess,
      *this,
      v,
      scratch.Ring,
      scratch.Edges,
      scratch.Polygon,
      scratch.Interior,
      withLabels ? &scratch.Labels : nullptr,
      withLabels ? &scratch.SameCentre : nullptr);
  }
  this->CollinearTileEdges(v, scratch.Edges);
  return AssemblePolygon(this->Tess, scratch.Edges, scratch.Polygon);
}

void TessellationDual::AppendTileOf(std::int32_t v, RingScratch& scratch, TileSet& tiles) const
{
  const std::int32_t sides = this->TilePolygonOf(v, scratch, false);
  AppendTile(tiles, v, scratch.Polygon, sides);
}

// Point v's tile as mesh vertex ids: an interior tile's from its faces, any other's by matching
// its polygon's vertices to the faces and window corners its edges end at.
void TessellationDual::AppendMeshTileOf(std::int32_t v, RingScratch& scratch, MeshPart& mesh) const
{
  auto& ids = mesh.VertexIds;
  const std::vector<Point2>& polygon = scratch.Polygon;
  scratch.SameCentre.clear();
  const std::int32_t sides = this->TilePolygonOf(v, scratch, true);
  if (scratch.Interior)
  {
    for (const std::int32_t label : scratch.Labels)
    {
      ids.push_back(this->Data[label].Vertex);
    }
    for (const auto& [kept, dropped] : scratch.SameCentre)
    {
      mesh.SameVertex.emplace_back(this->Data[kept].Vertex, this->Data[dropped].Vertex);
    }
  }
  else
  {
    this->IndexEdgeEnds(scratch);
    for (const Point2& p : polygon)
    {
      ids.push_back(this->MeshVertexOf(p, scratch, mesh));
    }
  }
  TileMesh& result = *mesh.Result;
  const std::size_t tile = std::size_t(mesh.Next++);
  result.PointIds[tile] = v;
  result.Offsets[tile + 1] = std::int64_t(ids.size()); // from the chunk's start until the join
  result.Areas[tile] = CompensatedPolygonArea(polygon.data(), polygon.size());
  result.NeighborCounts[tile] = sides;
}

// The mesh vertex an edge end is, when it is a face centre inside the window; -1 otherwise.
std::int32_t TessellationDual::MeshVertexAt(const EdgeEnd& end) const
{
  return end.Constraint < 0 && end.Where >= 0 && this->Data[end.Where].Inside()
    ? this->Data[end.Where].Vertex
    : -1;
}

// The ends of a clipped tile's edges that are mesh vertices (MeshVertexAt), by place, when the
// tile has enough edges for a search per polygon vertex to cost: a tile with d sides cost O(d^2)
// (a point on a convex arc has a tile of as many sides as the arc has points: 1e5 of them on a
// parabola took 29 s through the filter). Empty for a few edges.
void TessellationDual::IndexEdgeEnds(RingScratch& scratch) const
{
  scratch.Ends.clear();
  if (scratch.Edges.size() <= 16)
  {
    return;
  }
  std::int32_t order = 0;
  for (const TileEdge& edge : scratch.Edges)
  {
    for (const EdgeEnd* end : { &edge.Lo, &edge.Hi })
    {
      const std::int32_t vertex = this->MeshVertexAt(*end);
      if (vertex >= 0)
      {
        scratch.Ends.push_back({ end->P.x, end->P.y, order, vertex });
      }
      ++order;
    }
  }
  std::sort(scratch.Ends.begin(), scratch.Ends.end());
}

// The vertex id of a clipped tile's polygon vertex p (about to be appended): a face centre inside
// the window that one of its edges ends at, a window corner, or else a crossing of the window
// boundary, a new vertex. Matched by exact coordinates: AssemblePolygon copies them (and keeps one
// of several ends at one point: the others are recorded as the same vertex).
std::int32_t TessellationDual::MeshVertexOf(const Point2& p,
  const RingScratch& scratch,
  MeshPart& mesh) const
{
  // The first end at p (in edge order) gives the vertex; the others at p are the same vertex.
  std::int32_t face = -1;
  const auto meet = [&](std::int32_t vertex)
  {
    if (face < 0)
    {
      face = vertex;
    }
    else if (vertex != face)
    {
      mesh.SameVertex.emplace_back(face, vertex);
    }
  };
  if (!scratch.Ends.empty())
  {
    using EndAt = RingScratch::EndAt;
    const EndAt key{ p.x, p.y, -1, -1 };
    for (auto at = std::lower_bound(scratch.Ends.begin(), scratch.Ends.end(), key);
         at != scratch.Ends.end() && at->X == p.x && at->Y == p.y;
         ++at)
    {
      meet(at->Vertex);
    }
  }
  else
  {
    for (const TileEdge& edge : scratch.Edges)
    {
      for (const EdgeEnd* end : { &edge.Lo, &edge.Hi })
      {
        const std::int32_t vertex = end->P == p ? this->MeshVertexAt(*end) : -1;
        if (vertex >= 0)
        {
          meet(vertex);
        }
      }
    }
  }
  if (face >= 0)
  {
    return face;
  }
  const auto& corners = *mesh.Corners;
  const auto corner =
    std::lower_bound(corners.begin(), corners.end(), std::make_tuple(p.x, p.y, std::int32_t(-1)));
  if (corner != corners.end() && std::get<0>(*corner) == p.x && std::get<1>(*corner) == p.y)
  {
    return mesh.CornerBase + std::get<2>(*corner);
  }
  mesh.ExtraSlots.push_back(std::int64_t(mesh.VertexIds.size()));
  mesh.Crossings->push_back(p);
  return std::int32_t(mesh.Crossings->size() - 1);
}

// A ring walk is a chain of dependent loads (twin, then the next triangle's twin ...), mostly
// cache misses: walk the rings of Order[begin .. end) side by side, one step of each in turn,
// so that their misses overlap, and bring in the triangles' faces and vertices on the way.
void TessellationDual::TouchRings(std::int32_t begin, std::int32_t end) const
{
  const std::int32_t* org = this->Tess.Origin().data();
  const std::int32_t* twin = this->Tess.Twin().data();
  const TriangleData* data = this->Data.data();
  std::int32_t start[RingBatch], at[RingBatch];
  const std::int32_t count = end - begin;
  for (std::int32_t s = 0; s < count; ++s)
  {
    start[s] = at[s] = this->OrderEdge[begin + s];
  }
  std::int32_t active = count;
  while (active > 0)
  {
    active = 0;
    for (std::int32_t s = 0; s < count; ++s)
    {
      const std::int32_t e = at[s];
      if (e < 0)
      {
        continue;
      }
      // Both ends of the triangle's records (they may straddle two cache lines).
      const std::int32_t t = e / 3;
      __builtin_prefetch(data + t);
      __builtin_prefetch(reinterpret_cast<const char*>(data + t + 1) - 1);
      __builtin_prefetch(org + 3 * t);
      __builtin_prefetch(org + 3 * t + 2);
      const std::int32_t next = twin[Tess::Prev(e)];
      at[s] = next == start[s] ? -1 : next;
      ++active;
    }
  }
}

namespace
{
// The contiguities of an interior tile without half-neighbours: every ring neighbour, each an
// edge neighbour (Kind 0). Gathered without a branch on the (unpredictable) neighbour ids and
// sorted as plain ints; larger is scratch.
template<class Graph>
void AppendRingNeighbours(const HalfEdgeArray& org,
  std::int32_t v,
  const std::vector<std::int32_t>& ring,
  std::vector<std::int32_t>& larger,
  Graph& graph)
{
  larger.resize(ring.size());
  std::size_t count = 0;
  for (const std::int32_t e : ring)
  {
    const std::int32_t j = org[Tess::Next(e)];
    larger[count] = j;
    count += j > v ? 1 : 0;
  }
  std::sort(larger.begin(), larger.begin() + std::ptrdiff_t(count));
  for (std::size_t k = 0; k < count; ++k)
  {
    graph.Pairs.push_back(v);
    graph.Pairs.push_back(larger[k]);
    graph.Kinds.push_back(0);
  }
}
} // namespace

// Point v's contiguities with larger ids, appended to graph (half: whether the tessellation has
// half-neighbours at all). An edge between two distinct real faces whose centres are both inside
// the window is kept whole (ClipEdge would return it at once); any other edge is clipped. When v's
// tile polygon was just found interior (TilePolygonOf; a graph alone never sets the flag), every
// ring edge is such an edge, and without half-neighbours (so without degenerate faces inside the
// window, and no diagonals) the ring alone gives the list.
void TessellationDual::AppendContiguitiesOf(std::int32_t v,
  bool half,
  RingScratch& scratch,
  GraphPart& graph) const
{
  const auto& org = this->Tess.Origin();
  if (scratch.Interior && !half)
  {
    AppendRingNeighbours(org, v, scratch.Ring, scratch.Larger, graph);
    return;
  }
  const auto& twin = this->Tess.Twin();
  auto& around = scratch.Around;
  TileEdge& edge = scratch.Edge;
  around.clear();
  if (!this->Tess.IsTwoDimensional())
  {
    std::int32_t next = -1;
    const std::int32_t previous = this->Neighbors1D(v, next);
    for (const std::int32_t j : { previous, next })
    {
      if (j > v && ClipEdge(this->Tess, v, j, FaceView(), FaceView(), edge))
      {
        around.emplace_back(j, 0);
      }
    }
  }
  else
  {
    for (const std::int32_t e : scratch.Ring)
    {
      const std::int32_t j = org[Tess::Next(e)];
      if (j > v)
      {
        const std::int32_t left = this->Data[e / 3].Face;
        const std::int32_t right = this->Data[twin[e] / 3].Face;
        if (left != right &&
          ((left >= 0 && right >= 0 && this->Data[left].Inside() && this->Data[right].Inside()) ||
            ClipEdge(this->Tess, v, j, this->View(right), this->View(left), edge)))
        {
          around.emplace_back(j, 0);
        }
      }
    }
  }
  if (half) // degenerate faces exist only in two dimensions: scratch.Ring is v's ring
  {
    this->AppendHalfNeighboursOf(v, scratch.Ring, around);
  }
  std::sort(around.begin(), around.end());
  for (const auto& [j, kind] : around)
  {
    graph.Pairs.push_back(v);
    graph.Pairs.push_back(j);
    graph.Kinds.push_back(kind);
  }
}

DelaunayFaces TessellationDual::Faces(bool splitDegenerate) const
{
  DelaunayFaces faces;
  faces.Offsets.push_back(0);
  if (!this->Tess.IsTwoDimensional())
  {
    return faces;
  }
  const auto& org = this->Tess.Origin();
  faces.Offsets.reserve(2 * this->Tess.AcceptedCount() + 1);
  faces.PointIds.reserve(6 * this->Tess.AcceptedCount());
  // In the order of the triangle arrays (a sequential pass: no ring walks). Each face is written
  // from its representative triangle, starting at its smallest id.
  for (std::int32_t t = 0; t < std::int32_t(this->Data.size()); ++t)
  {
    if (this->Data[t].Face != t)
    {
      continue;
    }
    std::int32_t size = 0;
    const std::int32_t* polygon = this->DegeneratePolygon(t, size);
    if (!polygon)
    {
      AppendTriangleFace(faces, org[3 * t], org[3 * t + 1], org[3 * t + 2]);
    }
    else if (!splitDegenerate)
    {
      faces.PointIds.insert(faces.PointIds.end(), polygon, polygon + size);
      faces.Offsets.push_back(std::int32_t(faces.PointIds.size()));
    }
    else
    {
      for (std::int32_t k = 1; k + 1 < size; ++k)
      {
        faces.PointIds.insert(faces.PointIds.end(), { polygon[0], polygon[k], polygon[k + 1] });
        faces.Offsets.push_back(std::int32_t(faces.PointIds.size()));
      }
    }
  }
  return faces;
}

TileSet ComputeTiles(const DirichletTessellation& tessellation)
{
  return TessellationDual(tessellation).Tiles();
}

ContiguityGraph ComputeContiguityGraph(const DirichletTessellation& tessellation)
{
  return TessellationDual(tessellation).Contiguities();
}

namespace
{
/// Result of one chunk of the fast Delaunay-faces pass.
struct FaceChunk
{
  std::size_t Faces = 0;
  bool Cocircular = false;
};

/// Triangles [begin, end): writes each real triangle as a face starting at its smallest id to
/// out (3 ids each, consecutive) and stops early if two adjacent real triangles are exactly
/// co-circular (then faces must be merged and the full dual is needed). One inlined, filtered
/// incircle per interior edge, from the triangle with the smaller index: far cheaper than the
/// dual's centres when, as for most data, no face is degenerate. When the batch build already
/// checked (KnownFreeOfCocircularTriangles), no point is read at all.
FaceChunk WriteTriangleFaces(const DirichletTessellation& tessellation,
  std::int32_t begin,
  std::int32_t end,
  std::int32_t* out)
{
  const bool check = !tessellation.KnownFreeOfCocircularTriangles();
  const std::int32_t* org = tessellation.Origin().data();
  const std::int32_t* twin = tessellation.Twin().data();
  const Point2* pts = tessellation.Points().data();
  FaceChunk chunk;
  std::int32_t* write = out;
  // The loads are random in space (ids are in input order): prefetch the points of triangles a
  // few steps ahead, and the neighbours' opposite vertices a little later.
  constexpr std::int32_t ahead = 16;
  const std::int32_t prefetchEnd = std::max(begin, end - ahead);
  for (std::int32_t t = begin; t < end; ++t)
  {
    if (check && t < prefetchEnd)
    {
      // Ghost and free ids are negative, a free triangle's twins -1: clamped to stay in bounds.
      const std::int32_t* next = org + 3 * (t + ahead);
      const std::int32_t* near = twin + 3 * (t + ahead / 2);
      for (int k = 0; k < 3; ++k)
      {
        __builtin_prefetch(pts + NonNegative(next[k]));
        const std::int32_t f = NonNegative(near[k]);
        __builtin_prefetch(pts + NonNegative(org[DirichletTessellation::Prev(f)]));
      }
    }
    const std::int32_t v[3] = { org[3 * t], org[3 * t + 1], org[3 * t + 2] };
    if ((v[0] | v[1] | v[2]) < 0)
    {
      continue; // ghost or free
    }
    // Rotate to the smallest id without a data-dependent branch.
    const int m = v[0] < v[1] && v[0] < v[2] ? 0 : (v[1] < v[2] ? 1 : 2);
    const int m1 = m == 2 ? 0 : m + 1;
    const int m2 = m == 0 ? 2 : m - 1;
    write[0] = v[m];
    write[1] = v[m1];
    write[2] = v[m2];
    write += 3;
    if (!check)
    {
      continue;
    }
    // The opposite vertices of the neighbours with a larger half-edge index (ghosts have the
    // vertex Ghost there), gathered without a branch, then tested.
    std::int32_t opposite[3];
    int count = 0;
    for (int k = 0; k < 3; ++k)
    {
      const std::int32_t e = 3 * t + k;
      const std::int32_t f = twin[e];
      const std::int32_t d = org[DirichletTessellation::Prev(f)];
      opposite[count] = d;
      count += (f > e) & (d >= 0);
    }
    const Point2 a = pts[v[0]], b = pts[v[1]], c = pts[v[2]];
    for (int k = 0; k < count; ++k)
    {
      if (incircle_fast(a, b, c, pts[opposite[k]]) == 0)
      {
        chunk.Cocircular = true;
        return chunk;
      }
    }
  }
  chunk.Faces = std::size_t(write - out) / 3;
  return chunk;
}
} // namespace

std::size_t DelaunayFaceCapacity(const DirichletTessellation& tessellation)
{
  return tessellation.Origin().size() / 3;
}

// The faces are the real triangles, each starting at its smallest id, in the order of the
// triangle arrays (as Faces() lists them), unless some face is degenerate. Chunks of triangles
// are written in parallel to their own parts of the output, then closed up: the same result for
// any number of threads.
std::int64_t WriteTriangularDelaunayFaces(const DirichletTessellation& tessellation,
  std::int32_t* pointIds,
  std::int32_t* offsets)
{
  if (!tessellation.IsTwoDimensional())
  {
    return -1;
  }
  const std::int32_t triangles = std::int32_t(DelaunayFaceCapacity(tessellation));
  const std::vector<std::int32_t> bounds = ChunkBounds(triangles, ThreadCount(triangles));
  const std::size_t chunks = bounds.size() - 1;
  std::vector<FaceChunk> results(chunks);
  RunChunks(chunks,
    [&](std::size_t k)
    {
      results[k] =
        WriteTriangleFaces(tessellation, bounds[k], bounds[k + 1], pointIds + 3 * bounds[k]);
    });
  std::size_t count = 0;
  for (std::size_t k = 0; k < chunks; ++k)
  {
    if (results[k].Cocircular)
    {
      return -1;
    }
    if (count != std::size_t(bounds[k]) && results[k].Faces > 0)
    {
      std::memmove(pointIds + 3 * count,
        pointIds + 3 * std::size_t(bounds[k]),
        3 * results[k].Faces * sizeof(std::int32_t));
    }
    count += results[k].Faces;
  }
  const std::vector<std::int32_t> offsetChunks =
    ChunkBounds(std::int32_t(count + 1), ThreadCount(std::int64_t(count + 1)));
  RunChunks(offsetChunks.size() - 1,
    [&](std::size_t c)
    {
      for (std::int32_t k = offsetChunks[c]; k < offsetChunks[c + 1]; ++k)
      {
        offsets[k] = 3 * k;
      }
    });
  return std::int64_t(count);
}

DelaunayFaces ComputeDelaunayFaces(const DirichletTessellation& tessellation, bool splitDegenerate)
{
  const std::size_t capacity = DelaunayFaceCapacity(tessellation);
  DelaunayFaces faces;
  faces.PointIds.resize(3 * capacity);
  faces.Offsets.resize(capacity + 1);
  const std::int64_t count =
    WriteTriangularDelaunayFaces(tessellation, faces.PointIds.data(), faces.Offsets.data());
  if (count < 0)
  {
    return TessellationDual(tessellation).Faces(splitDegenerate);
  }
  faces.PointIds.resize(3 * std::size_t(count));
  faces.Offsets.resize(std::size_t(count) + 1);
  return faces;
}
} // namespace tessera
