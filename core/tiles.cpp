#include "tiles.h"

#include "polygon_area.h"
#include "predicates_inline.h"
#include "tile_edges.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace tessera
{

namespace
{

using namespace tiles_detail;

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
  faces.Offsets.push_back(std::int64_t(faces.PointIds.size()));
}
} // namespace

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
    this->Order = line;
    return;
  }
  // First appearance of each vertex in the half-edge arrays; a bit per point
  // keeps the "seen" test in cache.
  std::vector<std::uint64_t> seen((n + 63) / 64, 0);
  this->Order.reserve(tessellation.AcceptedCount());
  this->OrderEdge.reserve(tessellation.AcceptedCount());
  const auto& org = tessellation.Origin();
  for (std::size_t e = 0; e < org.size(); ++e)
  {
    const std::int32_t v = org[e];
    if (v >= 0 && !(seen[std::size_t(v) >> 6] >> (v & 63) & 1U))
    {
      seen[std::size_t(v) >> 6] |= std::uint64_t(1) << (v & 63);
      this->Order.push_back(v);
      this->OrderEdge.push_back(std::int32_t(e));
    }
  }
  this->ComputeTriangleCentres();
  this->LabelFaces();
  this->ComputeCentres();
}

// ---------------------------------------------------------------------------------------------
// Faces: ghosts get Face = -2 - t (never merged), real triangles the id of
// the first triangle of their co-circular cluster.

// Every real triangle's centre (canonical: from its ids in ascending order) and
// error bound.
void TessellationDual::ComputeTriangleCentres()
{
  const auto& org = this->Tess.Origin();
  const std::vector<Point2>& pts = this->Tess.Points();
  const std::size_t triangles = org.size() / 3;
  this->Data.resize(triangles);
  this->CentreError.resize(triangles);
  for (std::size_t t = 0; t < triangles; ++t)
  {
    std::int32_t a = org[3 * t], b = org[3 * t + 1], c = org[3 * t + 2];
    if (a < 0 || b < 0 || c < 0)
    {
      continue;
    }
    // Sort the three ids (a rotation and at most one swap).
    if (b < a && b < c)
    {
      std::swap(a, b);
      std::swap(b, c);
    }
    else if (c < a && c < b)
    {
      std::swap(a, c);
      std::swap(b, c);
    }
    if (c < b)
    {
      std::swap(b, c);
    }
    this->Data[t].Centre = Circumcentre(pts[a], pts[b], pts[c], this->CentreError[t]);
  }
}

// Whether the triangle across half-edge f has its opposite vertex on the circle
// of triangle t: exact, but skipped when the computed centres are further apart
// than their error bounds.
bool TessellationDual::Cocircular(std::int32_t t, std::int32_t f) const
{
  const std::int32_t u = f / 3;
  const double slack = this->CentreError[t] + this->CentreError[u];
  if (std::fabs(this->Data[t].Centre.x - this->Data[u].Centre.x) > slack ||
    std::fabs(this->Data[t].Centre.y - this->Data[u].Centre.y) > slack)
  {
    return false;
  }
  const auto& org = this->Tess.Origin();
  const std::vector<Point2>& pts = this->Tess.Points();
  return incircle_fast(
           pts[org[3 * t]], pts[org[3 * t + 1]], pts[org[3 * t + 2]], pts[org[Tess::Prev(f)]]) == 0;
}

void TessellationDual::LabelFaces()
{
  const auto& org = this->Tess.Origin();
  const auto& twin = this->Tess.Twin();
  const std::int32_t triangles = std::int32_t(org.size() / 3);
  for (TriangleData& data : this->Data)
  {
    data.Face = -1;
  }
  for (std::int32_t t = 0; t < triangles; ++t)
  {
    if (this->Tess.IsFreeTriangle(t) || this->Tess.IsGhostTriangle(t))
    {
      this->Data[t].Face = -2 - t;
    }
  }
  std::vector<std::int32_t> cluster, stack, boundary;
  for (std::int32_t t = 0; t < triangles; ++t)
  {
    if (this->Data[t].Face != -1)
    {
      continue;
    }
    this->Data[t].Face = t;
    for (std::int32_t k = 0; k < 3; ++k)
    {
      const std::int32_t f = twin[3 * t + k];
      if (this->Data[f / 3].Face == -1 && this->Cocircular(t, f))
      {
        this->MergeCocircular(t, cluster, stack, boundary);
        break;
      }
    }
  }
}

// Flood the cluster of triangles sharing root's circle, then chain its boundary
// half-edges into the face polygon (anticlockwise, rotated to start at its
// smallest id).
void TessellationDual::MergeCocircular(std::int32_t root,
  std::vector<std::int32_t>& cluster,
  std::vector<std::int32_t>& stack,
  std::vector<std::int32_t>& boundary)
{
  const auto& org = this->Tess.Origin();
  const auto& twin = this->Tess.Twin();
  cluster.assign(1, root);
  stack.assign(1, root);
  while (!stack.empty())
  {
    const std::int32_t s = stack.back();
    stack.pop_back();
    for (std::int32_t k = 0; k < 3; ++k)
    {
      const std::int32_t f = twin[3 * s + k];
      const std::int32_t u = f / 3;
      if (this->Data[u].Face == -1 && this->Cocircular(root, f))
      {
        this->Data[u].Face = root;
        cluster.push_back(u);
        stack.push_back(u);
      }
    }
  }
  boundary.clear();
  for (const std::int32_t s : cluster)
  {
    for (std::int32_t k = 0; k < 3; ++k)
    {
      const std::int32_t e = 3 * s + k;
      if (this->Data[twin[e] / 3].Face != root)
      {
        boundary.push_back(e);
      }
    }
  }
  // Chain: the boundary edge after x->y leaves y. Start at the smallest id.
  std::size_t first = 0;
  for (std::size_t k = 1; k < boundary.size(); ++k)
  {
    if (org[boundary[k]] < org[boundary[first]])
    {
      first = k;
    }
  }
  if (this->DegenerateIndex.empty())
  {
    this->DegenerateIndex.assign(this->Data.size(), -1);
    this->DegenerateStarts.push_back(0);
  }
  this->DegenerateIndex[root] = std::int32_t(this->DegenerateReps.size());
  this->DegenerateReps.push_back(root);
  std::int32_t e = boundary[first];
  for (std::size_t step = 0; step < boundary.size(); ++step)
  {
    this->DegenerateVertices.push_back(org[e]);
    const std::int32_t to = org[Tess::Next(e)];
    for (const std::int32_t g : boundary)
    {
      if (org[g] == to)
      {
        e = g;
        break;
      }
    }
  }
  this->DegenerateStarts.push_back(std::int32_t(this->DegenerateVertices.size()));
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

// Degenerate faces take their centre from their three smallest ids; every face
// gets its inside-the-window flag, decided exactly: the rounded centre and its
// error bound settle almost every face, CircumcentreSide the rest.
void TessellationDual::ComputeCentres()
{
  const std::vector<Point2>& pts = this->Tess.Points();
  for (const std::int32_t rep : this->DegenerateReps)
  {
    std::int32_t size = 0;
    const std::int32_t* polygon = this->DegeneratePolygon(rep, size);
    std::int32_t ids[3] = { 0, 0, 0 };
    std::partial_sort_copy(polygon, polygon + size, ids, ids + 3);
    this->Data[rep].Centre =
      Circumcentre(pts[ids[0]], pts[ids[1]], pts[ids[2]], this->CentreError[rep]);
  }
  for (std::int32_t t = 0; t < std::int32_t(this->Data.size()); ++t)
  {
    if (this->Data[t].Face == t)
    {
      this->Data[t].Inside =
        CentreInside(this->Tess, t, this->Data[t].Centre, this->CentreError[t]) ? 1 : 0;
    }
  }
  std::vector<double>().swap(this->CentreError);
}

// ---------------------------------------------------------------------------------------------
// Tile edges.

FaceView TessellationDual::View(std::int32_t label) const
{
  if (label < 0)
  {
    return FaceView();
  }
  return { label, this->Data[label].Centre, this->Data[label].Inside != 0 };
}

// Collinear case: the neighbours along the line (-1 where there is none).
std::int32_t TessellationDual::Neighbors1D(std::int32_t v, std::int32_t& next) const
{
  const auto& line = this->Tess.CollinearPoints();
  const std::int32_t k = this->LinePosition[v];
  next = k + 1 < std::int32_t(line.size()) ? line[k + 1] : -1;
  return k > 0 ? line[k - 1] : -1;
}

void TessellationDual::TileEdgesOf(std::int32_t v,
  std::int32_t vertexEdge,
  std::vector<TileEdge>& edges,
  std::vector<std::int32_t>& ring) const
{
  if (this->Tess.IsTwoDimensional())
  {
    RingTileEdges(this->Tess, *this, v, vertexEdge, edges, ring);
    return;
  }
  // Two parallel edges; either cyclic order is anticlockwise, start at the
  // smaller id.
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

TileSet TessellationDual::Tiles() const
{
  TileSet tiles;
  const std::size_t accepted = this->Tess.AcceptedCount();
  tiles.PointIds.reserve(accepted);
  tiles.Offsets.reserve(accepted + 1);
  tiles.Areas.reserve(accepted);
  tiles.NeighborCounts.reserve(accepted);
  tiles.Vertices.reserve(6 * accepted + 16);
  tiles.Offsets.push_back(0);
  std::vector<TileEdge> edges;
  std::vector<Point2> polygon;
  std::vector<std::int32_t> ring;
  const bool planar = this->Tess.IsTwoDimensional();
  for (std::size_t k = 0; k < this->Order.size(); ++k)
  {
    const std::int32_t v = this->Order[k];
    this->TileEdgesOf(v, planar ? this->OrderEdge[k] : -1, edges, ring);
    const std::int32_t sides = AssemblePolygon(this->Tess, edges, polygon);
    tiles.PointIds.push_back(v);
    tiles.Vertices.insert(tiles.Vertices.end(), polygon.begin(), polygon.end());
    tiles.Offsets.push_back(std::int64_t(tiles.Vertices.size()));
    tiles.Areas.push_back(CompensatedPolygonArea(polygon.data(), polygon.size()));
    tiles.NeighborCounts.push_back(sides);
  }
  return tiles;
}

ContiguityGraph TessellationDual::Contiguities() const
{
  ContiguityGraph graph;
  // Half-neighbours: non-adjacent vertices of a degenerate face whose centre is
  // in the window.
  std::vector<std::pair<std::int32_t, std::int32_t>> half;
  for (const std::int32_t rep : this->DegenerateReps)
  {
    if (!this->Data[rep].Inside)
    {
      continue;
    }
    std::int32_t size = 0;
    const std::int32_t* polygon = this->DegeneratePolygon(rep, size);
    for (std::int32_t x = 0; x < size; ++x)
    {
      for (std::int32_t y = x + 2; y < size; ++y)
      {
        if (!(x == 0 && y == size - 1))
        {
          half.emplace_back(std::min(polygon[x], polygon[y]), std::max(polygon[x], polygon[y]));
        }
      }
    }
  }
  std::sort(half.begin(), half.end());

  const bool planar = this->Tess.IsTwoDimensional();
  const auto& org = this->Tess.Origin();
  const auto& twin = this->Tess.Twin();
  std::vector<std::pair<std::int32_t, std::uint8_t>> around;
  TileEdge edge;
  graph.Pairs.reserve(6 * this->Tess.AcceptedCount());
  graph.Kinds.reserve(3 * this->Tess.AcceptedCount());
  for (std::size_t index = 0; index < this->Order.size(); ++index)
  {
    const std::int32_t v = this->Order[index];
    around.clear();
    if (!planar)
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
      const std::int32_t start = this->OrderEdge[index];
      std::int32_t e = start;
      do
      {
        const std::int32_t j = org[Tess::Next(e)];
        const std::int32_t left = this->Data[e / 3].Face;
        const std::int32_t right = this->Data[twin[e] / 3].Face;
        if (j > v && left != right &&
          ClipEdge(this->Tess, v, j, this->View(right), this->View(left), edge))
        {
          around.emplace_back(j, 0);
        }
        e = this->Tess.RingNext(e);
      } while (e != start);
    }
    for (auto at = std::lower_bound(half.begin(), half.end(), std::make_pair(v, std::int32_t(-1)));
         at != half.end() && at->first == v;
         ++at)
    {
      around.emplace_back(at->second, 1);
    }
    std::sort(around.begin(), around.end());
    for (const auto& [j, kind] : around)
    {
      graph.Pairs.push_back(v);
      graph.Pairs.push_back(j);
      graph.Kinds.push_back(kind);
    }
  }
  return graph;
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
      faces.Offsets.push_back(std::int64_t(faces.PointIds.size()));
    }
    else
    {
      for (std::int32_t k = 1; k + 1 < size; ++k)
      {
        faces.PointIds.insert(faces.PointIds.end(), { polygon[0], polygon[k], polygon[k + 1] });
        faces.Offsets.push_back(std::int64_t(faces.PointIds.size()));
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
/// Whether two adjacent real triangles are exactly co-circular somewhere (then faces must be
/// merged and the full dual is needed). One inlined, filtered incircle per interior edge: far
/// cheaper than the dual's centres when, as for most data, no face is degenerate.
bool HasCocircularNeighbours(const DirichletTessellation& tessellation)
{
  const auto& org = tessellation.Origin();
  const auto& twin = tessellation.Twin();
  const std::vector<Point2>& pts = tessellation.Points();
  for (std::int32_t e = 0; e < std::int32_t(org.size()); ++e)
  {
    const std::int32_t f = twin[e];
    if (f < e)
    {
      continue;
    }
    const std::int32_t t = e / 3, u = f / 3;
    if (org[3 * t] == DirichletTessellation::Free || tessellation.IsGhostTriangle(t) ||
      tessellation.IsGhostTriangle(u))
    {
      continue;
    }
    const std::int32_t d = org[DirichletTessellation::Prev(f)];
    if (incircle_fast(pts[org[3 * t]], pts[org[3 * t + 1]], pts[org[3 * t + 2]], pts[d]) == 0)
    {
      return true;
    }
  }
  return false;
}
} // namespace

DelaunayFaces ComputeDelaunayFaces(const DirichletTessellation& tessellation, bool splitDegenerate)
{
  if (!tessellation.IsTwoDimensional() || HasCocircularNeighbours(tessellation))
  {
    return TessellationDual(tessellation).Faces(splitDegenerate);
  }
  // No degenerate face: the faces are the real triangles, each starting at its smallest id, in
  // the order of the triangle arrays (as Faces() lists them).
  const auto& org = tessellation.Origin();
  DelaunayFaces faces;
  faces.Offsets.reserve(2 * tessellation.AcceptedCount() + 1);
  faces.PointIds.reserve(6 * tessellation.AcceptedCount());
  faces.Offsets.push_back(0);
  for (std::int32_t t = 0; t < std::int32_t(org.size() / 3); ++t)
  {
    const std::int32_t a = org[3 * t], b = org[3 * t + 1], c = org[3 * t + 2];
    if (a < 0 || b < 0 || c < 0)
    {
      continue; // ghost or free
    }
    AppendTriangleFace(faces, a, b, c);
  }
  return faces;
}
} // namespace tessera
