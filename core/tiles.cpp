#include "tiles.h"

#include "predicates_inline.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace tessera
{
namespace
{

using Tess = DirichletTessellation;

// Circumcentre from the points in a fixed (ascending id) order, relative to the first one.
Point2 Circumcentre(const Point2& a, const Point2& b, const Point2& c)
{
  const double bx = b.x - a.x, by = b.y - a.y;
  const double cx = c.x - a.x, cy = c.y - a.y;
  const double b2 = bx * bx + by * by;
  const double c2 = cx * cx + cy * cy;
  const double d = 2.0 * (bx * cy - by * cx);
  return { a.x + (cy * b2 - by * c2) / d, a.y + (bx * c2 - cx * b2) / d };
}

// Neumaier's compensated sum of the shoelace terms, relative to the first vertex so that the
// terms do not cancel catastrophically far from the origin.
double PolygonArea(const Point2* v, std::size_t n)
{
  double sum = 0.0, compensation = 0.0;
  for (std::size_t k = 1; k + 1 < n; ++k)
  {
    const double ax = v[k].x - v[0].x, ay = v[k].y - v[0].y;
    const double bx = v[k + 1].x - v[0].x, by = v[k + 1].y - v[0].y;
    for (const double term : { ax * by, -(ay * bx) })
    {
      const double t = sum + term;
      compensation += std::fabs(sum) >= std::fabs(term) ? (sum - t) + term : (term - t) + sum;
      sum = t;
    }
  }
  return 0.5 * (sum + compensation);
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
    return;
  }
  this->VertexEdge.assign(n, -1);
  const auto& org = tessellation.Origin();
  for (std::size_t e = 0; e < org.size(); ++e)
  {
    if (org[e] >= 0 && this->VertexEdge[org[e]] < 0)
    {
      this->VertexEdge[org[e]] = std::int32_t(e);
    }
  }
  this->LabelFaces();
  this->ComputeCentres();
}

// ---------------------------------------------------------------------------------------------
// Faces: ghosts get FaceOf = -2 - t (never merged), real triangles the id of the first triangle
// of their co-circular cluster.

void TessellationDual::LabelFaces()
{
  const auto& org = this->Tess.Origin();
  const auto& twin = this->Tess.Twin();
  const std::vector<Point2>& pts = this->Tess.Points();
  const std::int32_t triangles = std::int32_t(org.size() / 3);
  this->FaceOf.assign(std::size_t(triangles), -1);
  for (std::int32_t t = 0; t < triangles; ++t)
  {
    if (this->Tess.IsFreeTriangle(t) || this->Tess.IsGhostTriangle(t))
    {
      this->FaceOf[t] = -2 - t;
    }
  }
  std::vector<std::int32_t> cluster, stack, boundary;
  for (std::int32_t t = 0; t < triangles; ++t)
  {
    if (this->FaceOf[t] != -1)
    {
      continue;
    }
    this->FaceOf[t] = t;
    const Point2& a = pts[org[3 * t]];
    const Point2& b = pts[org[3 * t + 1]];
    const Point2& c = pts[org[3 * t + 2]];
    for (std::int32_t k = 0; k < 3; ++k)
    {
      const std::int32_t f = twin[3 * t + k];
      if (this->FaceOf[f / 3] == -1 && incircle_fast(a, b, c, pts[org[Tess::Prev(f)]]) == 0)
      {
        this->MergeCocircular(t, cluster, stack, boundary);
        break;
      }
    }
  }
}

// Flood the cluster of triangles sharing root's circle, then chain its boundary half-edges into
// the face polygon (anticlockwise, rotated to start at its smallest id).
void TessellationDual::MergeCocircular(std::int32_t root,
  std::vector<std::int32_t>& cluster,
  std::vector<std::int32_t>& stack,
  std::vector<std::int32_t>& boundary)
{
  const auto& org = this->Tess.Origin();
  const auto& twin = this->Tess.Twin();
  const std::vector<Point2>& pts = this->Tess.Points();
  const Point2& a = pts[org[3 * root]];
  const Point2& b = pts[org[3 * root + 1]];
  const Point2& c = pts[org[3 * root + 2]];
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
      if (this->FaceOf[u] == -1 && incircle_fast(a, b, c, pts[org[Tess::Prev(f)]]) == 0)
      {
        this->FaceOf[u] = root;
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
      if (this->FaceOf[twin[e] / 3] != root)
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
    this->DegenerateIndex.assign(this->FaceOf.size(), -1);
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

void TessellationDual::ComputeCentres()
{
  const auto& org = this->Tess.Origin();
  const std::vector<Point2>& pts = this->Tess.Points();
  const auto& constraints = this->Tess.GetWindow().EffectiveConstraints();
  this->Centre.resize(this->FaceOf.size());
  this->Inside.assign(this->FaceOf.size(), 0);
  for (std::int32_t t = 0; t < std::int32_t(this->FaceOf.size()); ++t)
  {
    if (this->FaceOf[t] != t)
    {
      continue;
    }
    std::int32_t ids[3];
    std::int32_t size = 0;
    const std::int32_t* polygon = this->DegeneratePolygon(t, size);
    if (polygon)
    {
      std::int32_t sorted[64];
      if (size <= 64)
      {
        std::partial_sort_copy(polygon, polygon + size, sorted, sorted + 3);
      }
      else
      {
        std::vector<std::int32_t> all(polygon, polygon + size);
        std::partial_sort(all.begin(), all.begin() + 3, all.end());
        std::copy(all.begin(), all.begin() + 3, sorted);
      }
      std::copy(sorted, sorted + 3, ids);
    }
    else
    {
      ids[0] = org[3 * t];
      ids[1] = org[3 * t + 1];
      ids[2] = org[3 * t + 2];
      std::sort(ids, ids + 3);
    }
    const Point2 c = Circumcentre(pts[ids[0]], pts[ids[1]], pts[ids[2]]);
    this->Centre[t] = c;
    bool inside = std::isfinite(c.x) && std::isfinite(c.y);
    for (const HalfPlane& h : constraints)
    {
      inside = inside && h.a * c.x + h.b * c.y + h.c < 0.0;
    }
    this->Inside[t] = inside ? 1 : 0;
  }
}

// ---------------------------------------------------------------------------------------------
// Tile edges.

std::int32_t TessellationDual::CanonicalStart(std::int32_t edge) const
{
  const auto& org = this->Tess.Origin();
  std::int32_t best = -1, bestId = std::numeric_limits<std::int32_t>::max();
  std::int32_t e = edge;
  do
  {
    const std::int32_t j = org[Tess::Next(e)];
    if (j >= 0 && j < bestId)
    {
      bestId = j;
      best = e;
    }
    e = this->Tess.RingNext(e);
  } while (e != edge);
  return best;
}

bool TessellationDual::ClipEdge(std::int32_t from,
  std::int32_t to,
  std::int32_t rightFace,
  std::int32_t leftFace,
  TileEdge& out) const
{
  if (from < to)
  {
    return this->ClipCanonical(from, to, rightFace, leftFace, out);
  }
  TileEdge reversed;
  if (!this->ClipCanonical(to, from, leftFace, rightFace, reversed))
  {
    return false;
  }
  out.Lo = reversed.Hi;
  out.Hi = reversed.Lo;
  return true;
}

// The part inside the window of the tile edge of a (lower id) with b: the bisector, parametrised
// as m + t * d with m the midpoint and d = (b - a) turned anticlockwise, from the centre of loFace
// (right of a->b; -1 for a ghost: t = -infinity) to the centre of hiFace (left of a->b).
bool TessellationDual::ClipCanonical(std::int32_t a,
  std::int32_t b,
  std::int32_t loFace,
  std::int32_t hiFace,
  TileEdge& out) const
{
  const bool loInside = loFace >= 0 && this->Inside[loFace];
  const bool hiInside = hiFace >= 0 && this->Inside[hiFace];
  if (loInside && hiInside)
  {
    out.Lo = { this->Centre[loFace], -1 };
    out.Hi = { this->Centre[hiFace], -1 };
    return true;
  }
  const Point2& pa = this->Tess.Points()[a];
  const Point2& pb = this->Tess.Points()[b];
  const double mx = 0.5 * (pa.x + pb.x), my = 0.5 * (pa.y + pb.y);
  const double dx = -(pb.y - pa.y), dy = pb.x - pa.x;
  const double infinity = std::numeric_limits<double>::infinity();
  double lower = -infinity, upper = infinity;
  int lowerConstraint = -1, upperConstraint = -1;
  const auto& constraints = this->Tess.GetWindow().EffectiveConstraints();
  for (std::size_t k = 0; k < constraints.size(); ++k)
  {
    const HalfPlane& h = constraints[k];
    const double f0 = h.a * mx + h.b * my + h.c;
    const double f1 = h.a * dx + h.b * dy;
    if (f1 > 0.0)
    {
      const double t = -f0 / f1;
      if (t < upper)
      {
        upper = t;
        upperConstraint = int(k);
      }
    }
    else if (f1 < 0.0)
    {
      const double t = -f0 / f1;
      if (t > lower)
      {
        lower = t;
        lowerConstraint = int(k);
      }
    }
    else if (f0 >= 0.0)
    {
      return false;
    }
  }
  if (lowerConstraint < 0 || upperConstraint < 0 || !(lower < upper))
  {
    return false;
  }
  const double dd = dx * dx + dy * dy;
  const auto parameter = [&](const Point2& c) { return ((c.x - mx) * dx + (c.y - my) * dy) / dd; };
  if (loFace >= 0 && !loInside && parameter(this->Centre[loFace]) >= upper)
  {
    return false; // the whole edge lies beyond the window
  }
  if (hiFace >= 0 && !hiInside && parameter(this->Centre[hiFace]) <= lower)
  {
    return false;
  }
  out.Lo = loInside ? EdgeEnd{ this->Centre[loFace], -1 }
                    : EdgeEnd{ { mx + lower * dx, my + lower * dy }, lowerConstraint };
  out.Hi = hiInside ? EdgeEnd{ this->Centre[hiFace], -1 }
                    : EdgeEnd{ { mx + upper * dx, my + upper * dy }, upperConstraint };
  return true;
}

// Collinear case: the neighbours along the line (-1 where there is none).
std::int32_t TessellationDual::Neighbors1D(std::int32_t v, std::int32_t& next) const
{
  const auto& line = this->Tess.CollinearPoints();
  const std::int32_t k = this->LinePosition[v];
  next = k + 1 < std::int32_t(line.size()) ? line[k + 1] : -1;
  return k > 0 ? line[k - 1] : -1;
}

void TessellationDual::TileEdgesOf(std::int32_t v, std::vector<TileEdge>& edges) const
{
  edges.clear();
  TileEdge edge;
  if (!this->Tess.IsTwoDimensional())
  {
    // Two parallel edges; either cyclic order is anticlockwise, start at the smaller id.
    std::int32_t next = -1;
    const std::int32_t previous = this->Neighbors1D(v, next);
    std::int32_t order[2] = { next, previous };
    if (previous >= 0 && (next < 0 || previous < next))
    {
      std::swap(order[0], order[1]);
    }
    for (const std::int32_t j : order)
    {
      if (j >= 0 && this->ClipEdge(v, j, -1, -1, edge))
      {
        edges.push_back(edge);
      }
    }
    return;
  }
  const auto& org = this->Tess.Origin();
  const auto& twin = this->Tess.Twin();
  const std::int32_t start = this->CanonicalStart(this->VertexEdge[v]);
  std::int32_t e = start;
  do
  {
    const std::int32_t j = org[Tess::Next(e)];
    const std::int32_t left = this->FaceOf[e / 3];
    const std::int32_t right = this->FaceOf[twin[e] / 3];
    if (j >= 0 && left != right &&
      this->ClipEdge(v, j, right < 0 ? -1 : right, left < 0 ? -1 : left, edge))
    {
      edges.push_back(edge);
    }
    e = this->Tess.RingNext(e);
  } while (e != start);
}

void TessellationDual::AssemblePolygon(const std::vector<TileEdge>& edges,
  std::vector<Point2>& polygon) const
{
  const std::vector<Point2>& corners = this->Tess.GetWindow().Vertices();
  const int count = int(corners.size());
  polygon.clear();
  if (edges.empty())
  {
    polygon = corners;
    return;
  }
  for (std::size_t s = 0; s < edges.size(); ++s)
  {
    const TileEdge& edge = edges[s];
    polygon.push_back(edge.Lo.P);
    if (edge.Hi.Constraint < 0)
    {
      continue; // a face centre: the next edge starts there
    }
    polygon.push_back(edge.Hi.P);
    // Leave on constraint a, follow the window boundary through corners a+1 .. b, re-enter on b.
    const int exit = edge.Hi.Constraint;
    const int entry = edges[(s + 1) % edges.size()].Lo.Constraint;
    if (entry < 0)
    {
      continue;
    }
    for (int k = exit; k != entry;)
    {
      k = (k + 1) % count;
      polygon.push_back(corners[k]);
    }
  }
  // Sides of zero length (an edge ending exactly at a corner) are not contiguities.
  std::size_t kept = 0;
  for (std::size_t k = 0; k < polygon.size(); ++k)
  {
    if (kept == 0 || polygon[k] != polygon[kept - 1])
    {
      polygon[kept++] = polygon[k];
    }
  }
  while (kept > 1 && polygon[kept - 1] == polygon[0])
  {
    --kept;
  }
  polygon.resize(kept);
}

// ---------------------------------------------------------------------------------------------
// Results.

TileSet TessellationDual::Tiles() const
{
  TileSet tiles;
  const std::int32_t n = std::int32_t(this->Tess.PointCount());
  const std::size_t accepted = this->Tess.AcceptedCount();
  tiles.PointIds.reserve(accepted);
  tiles.Offsets.reserve(accepted + 1);
  tiles.Areas.reserve(accepted);
  tiles.NeighborCounts.reserve(accepted);
  tiles.Vertices.reserve(6 * accepted + 16);
  tiles.Offsets.push_back(0);
  std::vector<TileEdge> edges;
  std::vector<Point2> polygon;
  const bool planar = this->Tess.IsTwoDimensional();
  for (std::int32_t v = 0; v < n; ++v)
  {
    if (planar ? this->VertexEdge[v] < 0 : this->LinePosition[v] < 0)
    {
      continue;
    }
    this->TileEdgesOf(v, edges);
    this->AssemblePolygon(edges, polygon);
    tiles.PointIds.push_back(v);
    tiles.Vertices.insert(tiles.Vertices.end(), polygon.begin(), polygon.end());
    tiles.Offsets.push_back(std::int64_t(tiles.Vertices.size()));
    tiles.Areas.push_back(PolygonArea(polygon.data(), polygon.size()));
    tiles.NeighborCounts.push_back(std::int32_t(polygon.size()));
  }
  return tiles;
}

ContiguityGraph TessellationDual::Contiguities() const
{
  ContiguityGraph graph;
  // Half-neighbours: non-adjacent vertices of a degenerate face whose centre is in the window.
  std::vector<std::pair<std::int32_t, std::int32_t>> half;
  for (const std::int32_t rep : this->DegenerateReps)
  {
    if (!this->Inside[rep])
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
  std::size_t nextHalf = 0;

  const std::int32_t n = std::int32_t(this->Tess.PointCount());
  const bool planar = this->Tess.IsTwoDimensional();
  const auto& org = this->Tess.Origin();
  const auto& twin = this->Tess.Twin();
  std::vector<std::pair<std::int32_t, std::uint8_t>> around;
  TileEdge edge;
  graph.Pairs.reserve(6 * this->Tess.AcceptedCount());
  graph.Kinds.reserve(3 * this->Tess.AcceptedCount());
  for (std::int32_t v = 0; v < n; ++v)
  {
    around.clear();
    if (!planar)
    {
      if (this->LinePosition[v] < 0)
      {
        continue;
      }
      std::int32_t next = -1;
      const std::int32_t previous = this->Neighbors1D(v, next);
      for (const std::int32_t j : { previous, next })
      {
        if (j > v && this->ClipEdge(v, j, -1, -1, edge))
        {
          around.emplace_back(j, 0);
        }
      }
    }
    else if (this->VertexEdge[v] >= 0)
    {
      const std::int32_t start = this->VertexEdge[v];
      std::int32_t e = start;
      do
      {
        const std::int32_t j = org[Tess::Next(e)];
        const std::int32_t left = this->FaceOf[e / 3];
        const std::int32_t right = this->FaceOf[twin[e] / 3];
        if (j > v && left != right &&
          this->ClipEdge(v, j, right < 0 ? -1 : right, left < 0 ? -1 : left, edge))
        {
          around.emplace_back(j, 0);
        }
        e = this->Tess.RingNext(e);
      } while (e != start);
    }
    while (nextHalf < half.size() && half[nextHalf].first == v)
    {
      around.emplace_back(half[nextHalf++].second, 1);
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
  const auto& twin = this->Tess.Twin();
  const std::int32_t n = std::int32_t(this->Tess.PointCount());
  faces.Offsets.reserve(2 * this->Tess.AcceptedCount() + 1);
  faces.PointIds.reserve(6 * this->Tess.AcceptedCount());
  // Each face is emitted from its smallest vertex v, found there as the face on the left of its
  // boundary edge v -> j; faces at v go out in ascending j.
  std::vector<std::pair<std::int32_t, std::int32_t>> around;
  for (std::int32_t v = 0; v < n; ++v)
  {
    if (this->VertexEdge[v] < 0)
    {
      continue;
    }
    around.clear();
    const std::int32_t start = this->VertexEdge[v];
    std::int32_t e = start;
    do
    {
      const std::int32_t face = this->FaceOf[e / 3];
      if (face >= 0 && face != this->FaceOf[twin[e] / 3])
      {
        std::int32_t size = 0;
        const std::int32_t* polygon = this->DegeneratePolygon(face, size);
        const std::int32_t t = e / 3;
        const std::int32_t smallest =
          polygon ? polygon[0] : std::min({ org[3 * t], org[3 * t + 1], org[3 * t + 2] });
        if (smallest == v)
        {
          around.emplace_back(org[Tess::Next(e)], e);
        }
      }
      e = this->Tess.RingNext(e);
    } while (e != start);
    std::sort(around.begin(), around.end());
    for (const auto& [j, edge] : around)
    {
      std::int32_t size = 0;
      const std::int32_t* polygon = this->DegeneratePolygon(this->FaceOf[edge / 3], size);
      if (!polygon)
      {
        faces.PointIds.insert(faces.PointIds.end(), { v, j, org[Tess::Prev(edge)] });
        faces.Offsets.push_back(std::int64_t(faces.PointIds.size()));
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

DelaunayFaces ComputeDelaunayFaces(const DirichletTessellation& tessellation, bool splitDegenerate)
{
  return TessellationDual(tessellation).Faces(splitDegenerate);
}

} // namespace tessera
