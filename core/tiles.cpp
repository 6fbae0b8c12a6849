#include "tiles.h"

#include "polygon_area.h"
#include "predicates_inline.h"
#include "window_predicates.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace tessera
{
namespace tiles_detail
{

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

} // namespace tiles_detail

namespace
{

using namespace tiles_detail;

using Tess = DirichletTessellation;

// Circumcentre from the points in a fixed (ascending id) order, relative to the
// first one. `error` receives a bound on the rounding error of each coordinate:
// a first-order bound on the roundings of the differences, squares, products
// and quotient, times a safety factor of 4 (the exact circle comparison only
// uses it to skip pairs of triangles whose centres are certainly different;
// infinity when the triangle is too flat to say).
Point2 Circumcentre(const Point2& a, const Point2& b, const Point2& c, double& error)
{
  const double bx = b.x - a.x, by = b.y - a.y;
  const double cx = c.x - a.x, cy = c.y - a.y;
  const double b2 = bx * bx + by * by;
  const double c2 = cx * cx + cy * cy;
  const double d = 2.0 * (bx * cy - by * cx);
  const double ux = (cy * b2 - by * c2) / d, uy = (bx * c2 - cx * b2) / d;
  const double condition = 2.0 * (std::fabs(bx * cy) + std::fabs(by * cx)) / std::fabs(d);
  const double spread = 2.0 *
    (std::fabs(cy) * b2 + std::fabs(by) * c2 + std::fabs(bx) * c2 + std::fabs(cx) * b2) /
    std::fabs(d);
  constexpr double unit = 0x1p-53;
  error = 4.0 * 16.0 * unit *
    (spread + (std::fabs(ux) + std::fabs(uy)) * (condition + 1.0) + std::fabs(a.x) +
      std::fabs(a.y));
  if (!std::isfinite(error))
  {
    error = std::numeric_limits<double>::infinity();
  }
  return { a.x + ux, a.y + uy };
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
  faces.Offsets.push_back(std::int64_t(faces.PointIds.size()));
}

// The exact side of face's centre: any three of its points span its circle.
int FaceSide(const Tess& tess, std::int32_t face, const HalfPlane& h)
{
  const auto& org = tess.Origin();
  const std::vector<Point2>& pts = tess.Points();
  return CircumcentreSide(h, pts[org[3 * face]], pts[org[3 * face + 1]], pts[org[3 * face + 2]]);
}

// Whether the centre of the face with representative triangle `face` lies
// strictly inside the window, exactly: the rounded centre c and its error bound
// settle almost every face, CircumcentreSide the rest.
bool CentreInside(const Tess& tess, std::int32_t face, const Point2& c, double error)
{
  constexpr double unit = 0x1p-53;
  for (const HalfPlane& h : tess.GetWindow().EffectiveConstraints())
  {
    const double ax = h.a * c.x, by = h.b * c.y;
    const double value = (ax + by) + h.c;
    // The centre's coordinates are within `error` of the true ones; the evaluation adds at most
    // 3 roundings. NaN or infinity fails both tests and goes to the exact predicate.
    const double bound = (std::fabs(h.a) + std::fabs(h.b)) * error +
      4.0 * unit * ((std::fabs(ax) + std::fabs(by)) + std::fabs(h.c));
    if (value < -bound)
    {
      continue;
    }
    if (value > bound || FaceSide(tess, face, h) >= 0)
    {
      return false;
    }
  }
  return true;
}

bool ClipCanonical(const Tess& tess,
  std::int32_t a,
  std::int32_t b,
  const FaceView& lo,
  const FaceView& hi,
  TileEdge& out);

bool ClipEdge(const Tess& tess,
  std::int32_t from,
  std::int32_t to,
  const FaceView& right,
  const FaceView& left,
  TileEdge& out)
{
  if (from < to)
  {
    return ClipCanonical(tess, from, to, right, left, out);
  }
  TileEdge reversed;
  if (!ClipCanonical(tess, to, from, left, right, reversed))
  {
    return false;
  }
  out.Lo = reversed.Hi;
  out.Hi = reversed.Lo;
  return true;
}

// The part inside the window of the tile edge of a (lower id) with b: the
// bisector, parametrised as m + t * d with m the midpoint and d = (b - a)
// turned anticlockwise, from the centre of loFace (right of a->b; -1 for a
// ghost: t = -infinity) to the centre of hiFace (left of a->b), t_lo < t_hi.
//
// Every decision is exact (window_predicates.h): the window meets the bisector
// in the open interval (L, U), L the last crossing of a line entered along d,
// U the first crossing of a line left; the edge is kept iff
// max(t_lo, L) < min(t_hi, U), i.e. the open Voronoi edge meets the open
// window in a segment of positive length. A centre is compared with a crossing
// through the sign of the line at the centre: the centre lies on the bisector,
// so h(centre) = h(m) + t_centre h(d) = (t_centre - t_line) h(d).
// Only the coordinates (centre bits, crossings m + t d) are rounded.
//
// Ends exactly on the window boundary: an end at a face centre on a line
// keeps the centre's bits (every tile meeting there shares them) but carries
// the line, so the polygon follows the window from there. Where the end is a
// window corner (two lines cross the bisector at the same point) it takes the
// corner's bits; leaving, it is labelled with the earlier of the two lines and
// entering with the later, so the walk along the boundary from an exit to the
// next entry never goes round the window the wrong way (it only repeats the
// corner, which AssemblePolygon drops).
bool ClipCanonical(const Tess& tess,
  std::int32_t a,
  std::int32_t b,
  const FaceView& lo,
  const FaceView& hi,
  TileEdge& out)
{
  const std::int32_t loFace = lo.Face, hiFace = hi.Face;
  const bool loInside = loFace >= 0 && lo.Inside;
  const bool hiInside = hiFace >= 0 && hi.Inside;
  if (loInside && hiInside)
  {
    out.Lo = { lo.Centre, -1, loFace };
    out.Hi = { hi.Centre, -1, hiFace };
    return true;
  }
  const Point2& pa = tess.Points()[a];
  const Point2& pb = tess.Points()[b];
  const auto& constraints = tess.GetWindow().EffectiveConstraints();
  const int count = int(constraints.size());
  int lower = -1, upper = -1;                    // constraints giving L and U
  bool lowerCorner = false, upperCorner = false; // L (U) is also reached by an adjacent line
  for (int k = 0; k < count; ++k)
  {
    const HalfPlane& h = constraints[k];
    const int direction = BisectorDirectionSign(h, pa, pb);
    if (direction == 0)
    {
      if (MidpointSide(h, pa, pb) >= 0)
      {
        return false; // parallel, on or outside the line
      }
      continue;
    }
    int& best = direction > 0 ? upper : lower;
    bool& corner = direction > 0 ? upperCorner : lowerCorner;
    if (best < 0)
    {
      best = k;
      corner = false;
      continue;
    }
    // Exit: the smallest crossing; entry: the largest.
    const int order = CompareBisectorCrossings(h, constraints[best], pa, pb) * direction;
    if (order < 0)
    {
      best = k;
      corner = false;
    }
    else if (order == 0)
    {
      // A tie at a corner: keep the earlier line on exit, the later on entry.
      const bool kAfterBest = (best + 1) % count == k;
      const bool kBeforeBest = (k + 1) % count == best;
      if ((direction > 0 && kBeforeBest) || (direction < 0 && kAfterBest))
      {
        best = k;
      }
      corner = corner || kAfterBest || kBeforeBest;
    }
  }
  if (lower < 0 || upper < 0 ||
    CompareBisectorCrossings(constraints[lower], constraints[upper], pa, pb) >= 0)
  {
    return false;
  }
  const HalfPlane& hl = constraints[lower];
  const HalfPlane& hu = constraints[upper];
  // Centre vs L: sign(t_centre - L) = -FaceSide(face, hl) (the line is entered along d);
  // centre vs U: sign(t_centre - U) = FaceSide(face, hu).
  int loVsL = 1, hiVsU = -1;
  if (loFace >= 0 && !loInside)
  {
    if (FaceSide(tess, loFace, hu) >= 0)
    {
      return false; // t_lo >= U
    }
    loVsL = -FaceSide(tess, loFace, hl);
  }
  if (hiFace >= 0 && !hiInside)
  {
    if (FaceSide(tess, hiFace, hl) >= 0)
    {
      return false; // t_hi <= L
    }
    hiVsU = FaceSide(tess, hiFace, hu);
  }
  const std::vector<Point2>& corners = tess.GetWindow().Vertices();
  // Window corner k is where constraint k-1 meets k: for a tie between k and k+1 it is k+1.
  const auto cornerIndex = [&](int line, bool exit) { return exit ? (line + 1) % count : line; };
  const auto cornerOf = [&](int line, bool exit)
  {
    return EdgeEnd{
      corners[std::size_t(cornerIndex(line, exit))], line, -2 - cornerIndex(line, exit)
    };
  };
  const double mx = 0.5 * (pa.x + pb.x), my = 0.5 * (pa.y + pb.y);
  const double dx = -(pb.y - pa.y), dy = pb.x - pa.x;
  const auto crossing = [&](const HalfPlane& h)
  {
    const double t = -(h.a * mx + h.b * my + h.c) / (h.a * dx + h.b * dy);
    return Point2{ mx + t * dx, my + t * dy };
  };
  if (loFace < 0 || loVsL < 0)
  {
    out.Lo = lowerCorner ? cornerOf(lower, false) : EdgeEnd{ crossing(hl), lower, -1 };
  }
  else if (loVsL == 0)
  {
    out.Lo = lowerCorner ? cornerOf(lower, false) : EdgeEnd{ lo.Centre, lower, loFace };
  }
  else
  {
    out.Lo = { lo.Centre, -1, loFace };
  }
  if (hiFace < 0 || hiVsU > 0)
  {
    out.Hi = upperCorner ? cornerOf(upper, true) : EdgeEnd{ crossing(hu), upper, -1 };
  }
  else if (hiVsU == 0)
  {
    out.Hi = upperCorner ? cornerOf(upper, true) : EdgeEnd{ hi.Centre, upper, hiFace };
  }
  else
  {
    out.Hi = { hi.Centre, -1, hiFace };
  }
  return true;
}

// Returns the number of sides (contiguities with points and window edges), decided exactly.
std::int32_t AssemblePolygon(const Tess& tess,
  const std::vector<TileEdge>& edges,
  std::vector<Point2>& polygon)
{
  const std::vector<Point2>& corners = tess.GetWindow().Vertices();
  const int count = int(corners.size());
  polygon.clear();
  if (edges.empty())
  {
    polygon = corners;
    return count;
  }
  // Sides: one per tile edge, plus the window pieces between an exit and the next entry, counted
  // from the exact decisions (the rounded vertices may coincide where the true ones do not).
  std::int32_t sides = std::int32_t(edges.size());
  for (std::size_t s = 0; s < edges.size(); ++s)
  {
    const TileEdge& edge = edges[s];
    polygon.push_back(edge.Lo.P);
    if (edge.Hi.Constraint < 0)
    {
      continue; // a face centre: the next edge starts there
    }
    polygon.push_back(edge.Hi.P);
    const EdgeEnd& next = edges[(s + 1) % edges.size()].Lo;
    if (next.Constraint < 0 || (next.Where == edge.Hi.Where && next.Where != -1))
    {
      continue; // leaves and re-enters at one point: no window side
    }
    // Leave on constraint a, follow the window boundary through corners a+1 ..
    // b, re-enter on b: pieces of lines a .. b, less those of zero length (leaving
    // at corner a+1, or entering at corner b).
    const int exit = edge.Hi.Constraint;
    const int entry = next.Constraint;
    sides += (entry - exit + count) % count + 1;
    sides -= edge.Hi.Where == -2 - (exit + 1) % count ? 1 : 0;
    sides -= next.Where == -2 - entry ? 1 : 0;
    for (int k = exit; k != entry;)
    {
      k = (k + 1) % count;
      polygon.push_back(corners[k]);
    }
  }
  // Repeated vertices (an end exactly at a corner, or distinct ends rounded to
  // one point) are dropped.
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
  return sides;
}

// The clipped edges of v's tile, anticlockwise from the edge to its smallest
// neighbour id (so the polygon does not depend on where the ring starts, nor on
// the diagonals stored in degenerate faces).
// faces.Label(t) is triangle t's face (-2 - t for a ghost), faces.View(label)
// its centre and inside flag.
template<class Faces>
void RingTileEdges(const Tess& tess,
  const Faces& faces,
  std::int32_t v,
  std::int32_t vertexEdge,
  std::vector<TileEdge>& edges,
  std::vector<std::int32_t>& ring)
{
  edges.clear();
  const auto& org = tess.Origin();
  const auto& twin = tess.Twin();
  ring.clear();
  std::size_t first = 0;
  std::int32_t smallest = std::numeric_limits<std::int32_t>::max();
  std::int32_t e = vertexEdge;
  do
  {
    // Diagonals of degenerate faces (the same face on both sides) depend on the insertion order:
    // they are never the start.
    const std::int32_t j = org[Tess::Next(e)];
    if (j >= 0 && j < smallest && faces.Label(e / 3) != faces.Label(twin[e] / 3))
    {
      smallest = j;
      first = ring.size();
    }
    ring.push_back(e);
    e = tess.RingNext(e);
  } while (e != vertexEdge);
  TileEdge edge;
  for (std::size_t k = 0; k < ring.size(); ++k)
  {
    e = ring[(first + k) % ring.size()];
    const std::int32_t j = org[Tess::Next(e)];
    const std::int32_t left = faces.Label(e / 3);
    const std::int32_t right = faces.Label(twin[e] / 3);
    if (j >= 0 && left != right && ClipEdge(tess, v, j, faces.View(right), faces.View(left), edge))
    {
      edges.push_back(edge);
    }
  }
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

// ---------------------------------------------------------------------------------------------
// Local derivation: only the faces around given points.

namespace
{

// Faces around chosen points, labelled on demand with the full derivation's rules: a face is the
// cluster of exactly co-circular triangles (connected, since the points on an empty circle are
// triangulated by triangles on that circle), labelled by its smallest triangle index, with its
// centre from its three smallest point ids (one triangle: its sorted ids) through the same
// Circumcentre, so the bits match TessellationDual's.
class LocalFaces
{
public:
  LocalFaces(const Tess& tess, std::size_t expectedTriangles)
    : T(tess)
  {
    std::size_t capacity = 64;
    while (capacity < 2 * expectedTriangles)
    {
      capacity *= 2;
    }
    this->Keys.assign(capacity, -1);
    this->Values.assign(capacity, -1);
  }

  std::int32_t Label(std::int32_t t) const
  {
    const std::int32_t entry = this->Find(t);
    return entry < 0 ? -2 - t : this->Entries[entry].Label;
  }

  FaceView View(std::int32_t label) const
  {
    if (label < 0)
    {
      return FaceView();
    }
    const Entry& entry = this->Entries[this->Find(label)];
    return { label, entry.Centre, entry.Inside };
  }

  /// The points of triangle t's face (none for a ghost); t must be resolved.
  void FacePoints(std::int32_t t, const std::int32_t*& begin, const std::int32_t*& end) const
  {
    const std::int32_t index = this->Find(t);
    if (index < 0)
    {
      begin = end = nullptr;
      return;
    }
    const Entry& entry = this->Entries[index];
    begin = this->Points.data() + entry.PointStart;
    end = begin + entry.PointCount;
  }

  // Ghost: a vertex is Tess::Ghost (inline here: this runs for every ring triangle).
  bool Ghost(std::int32_t t) const
  {
    const std::int32_t* v = this->T.Origin().data() + 3 * t;
    return v[0] < 0 || v[1] < 0 || v[2] < 0;
  }

  void Resolve(std::int32_t t)
  {
    if (this->Ghost(t) || this->Find(t) >= 0)
    {
      return; // ghosts stay unlisted: Label gives -2 - t
    }
    const auto& org = this->T.Origin();
    const auto& twin = this->T.Twin();
    const std::vector<Point2>& pts = this->T.Points();
    // Flood the triangles on t's circle; members are marked with a placeholder entry.
    constexpr std::int32_t Pending = -2;
    this->Cluster.assign(1, t);
    this->Insert(t, Pending);
    for (std::size_t k = 0; k < this->Cluster.size(); ++k)
    {
      const std::int32_t s = this->Cluster[k];
      for (std::int32_t side = 0; side < 3; ++side)
      {
        const std::int32_t f = twin[3 * s + side];
        const std::int32_t u = f / 3;
        if (!this->Ghost(u) && this->Find(u) == -1 &&
          incircle_fast(
            pts[org[3 * t]], pts[org[3 * t + 1]], pts[org[3 * t + 2]], pts[org[Tess::Prev(f)]]) ==
            0)
        {
          this->Insert(u, Pending);
          this->Cluster.push_back(u);
        }
      }
    }
    Entry entry;
    entry.Label = *std::min_element(this->Cluster.begin(), this->Cluster.end());
    entry.PointStart = std::int32_t(this->Points.size());
    if (this->Cluster.size() == 1)
    {
      std::int32_t a = org[3 * t], b = org[3 * t + 1], c = org[3 * t + 2];
      if (b < a)
      {
        std::swap(a, b);
      }
      if (c < b)
      {
        std::swap(b, c);
      }
      if (b < a)
      {
        std::swap(a, b);
      }
      this->Points.insert(this->Points.end(), { a, b, c });
    }
    else
    {
      for (const std::int32_t s : this->Cluster)
      {
        this->Points.insert(this->Points.end(), { org[3 * s], org[3 * s + 1], org[3 * s + 2] });
      }
      std::sort(this->Points.begin() + entry.PointStart, this->Points.end());
      this->Points.erase(std::unique(this->Points.begin() + entry.PointStart, this->Points.end()),
        this->Points.end());
    }
    entry.PointCount = std::int32_t(this->Points.size()) - entry.PointStart;
    const std::int32_t* ids = this->Points.data() + entry.PointStart;
    double error = 0.0;
    entry.Centre = Circumcentre(pts[ids[0]], pts[ids[1]], pts[ids[2]], error);
    entry.Inside = CentreInside(this->T, entry.Label, entry.Centre, error);
    const std::int32_t index = std::int32_t(this->Entries.size());
    this->Entries.push_back(entry);
    for (const std::int32_t s : this->Cluster)
    {
      this->Values[this->Slot(s)] = index;
    }
  }

private:
  struct Entry
  {
    std::int32_t Label = -1;
    Point2 Centre;
    bool Inside = false;
    std::int32_t PointStart = 0;
    std::int32_t PointCount = 0;
  };

  std::size_t Slot(std::int32_t t) const
  {
    const std::size_t mask = this->Keys.size() - 1;
    std::size_t slot = (std::uint32_t(t) * 2654435761U) & mask;
    while (this->Keys[slot] != t && this->Keys[slot] != -1)
    {
      slot = (slot + 1) & mask;
    }
    return slot;
  }
  /// Entry index of t; -1 when t is not listed, -2 while its cluster is being flooded.
  std::int32_t Find(std::int32_t t) const
  {
    const std::size_t slot = this->Slot(t);
    return this->Keys[slot] == t ? this->Values[slot] : -1;
  }
  void Insert(std::int32_t t, std::int32_t value)
  {
    if (2 * (this->Used + 1) > this->Keys.size())
    {
      std::vector<std::int32_t> keys(2 * this->Keys.size(), -1), values(2 * this->Keys.size(), -1);
      keys.swap(this->Keys);
      values.swap(this->Values);
      for (std::size_t k = 0; k < keys.size(); ++k)
      {
        if (keys[k] != -1)
        {
          const std::size_t slot = this->Slot(keys[k]);
          this->Keys[slot] = keys[k];
          this->Values[slot] = values[k];
        }
      }
    }
    const std::size_t slot = this->Slot(t);
    this->Keys[slot] = t;
    this->Values[slot] = value;
    ++this->Used;
  }

  const Tess& T;
  std::vector<std::int32_t> Keys, Values; // open addressing: triangle -> entry index
  std::size_t Used = 0;
  std::vector<Entry> Entries;
  std::vector<std::int32_t> Points; // per entry, its face's point ids, ascending
  std::vector<std::int32_t> Cluster;
};

// For each accepted id (first occurrence), a half-edge leaving it: one pass over the half-edge
// arrays, stopped once every id is found. Returns (id, edge) pairs in the order of ids; ids that
// are not vertices (rejected, duplicate, removed) never occur in the arrays and are dropped.
// (Status() is not asked: it costs O(removed points) per call.)
std::vector<std::pair<std::int32_t, std::int32_t>> VertexEdges(const Tess& tess,
  const std::vector<std::int32_t>& ids)
{
  std::vector<std::pair<std::int32_t, std::int32_t>> found;
  std::vector<std::int32_t> slot(tess.PointCount(), -1);
  for (const std::int32_t id : ids)
  {
    if (id >= 0 && std::size_t(id) < tess.PointCount() && slot[id] < 0)
    {
      slot[id] = std::int32_t(found.size());
      found.emplace_back(id, -1);
    }
  }
  std::size_t missing = found.size();
  const auto& org = tess.Origin();
  for (std::size_t e = 0; e < org.size() && missing > 0; ++e)
  {
    const std::int32_t v = org[e];
    if (v >= 0 && slot[v] >= 0 && found[slot[v]].second < 0)
    {
      found[slot[v]].second = std::int32_t(e);
      --missing;
    }
  }
  found.erase(std::remove_if(found.begin(),
                found.end(),
                [](const std::pair<std::int32_t, std::int32_t>& f) { return f.second < 0; }),
    found.end());
  return found;
}

void AppendMates(const Tess& tess,
  const LocalFaces& faces,
  std::int32_t v,
  const std::vector<std::int32_t>& ring,
  std::vector<std::int32_t>& scratch,
  FaceMateLists& mates)
{
  scratch.clear();
  const auto& org = tess.Origin();
  for (const std::int32_t e : ring)
  {
    const std::int32_t* begin = nullptr;
    const std::int32_t* end = nullptr;
    faces.FacePoints(e / 3, begin, end);
    scratch.insert(scratch.end(), begin, end);
    if (org[Tess::Next(e)] >= 0)
    {
      scratch.push_back(org[Tess::Next(e)]);
    }
  }
  std::sort(scratch.begin(), scratch.end());
  scratch.erase(std::unique(scratch.begin(), scratch.end()), scratch.end());
  mates.PointIds.push_back(v);
  for (const std::int32_t j : scratch)
  {
    if (j != v)
    {
      mates.Ids.push_back(j);
    }
  }
  mates.Offsets.push_back(std::int64_t(mates.Ids.size()));
}

// The collinear case: from the full derivation (no faces; the line is short-lived).
TileSet CollinearTilesOf(const Tess& tess,
  const std::vector<std::int32_t>& ids,
  FaceMateLists* mates)
{
  const TileSet all = TessellationDual(tess).Tiles();
  std::vector<std::int32_t> index(tess.PointCount(), -1);
  for (std::size_t k = 0; k < all.PointIds.size(); ++k)
  {
    index[all.PointIds[k]] = std::int32_t(k);
  }
  const auto& line = tess.CollinearPoints();
  std::vector<std::int32_t> position(tess.PointCount(), -1);
  for (std::size_t k = 0; k < line.size(); ++k)
  {
    position[line[k]] = std::int32_t(k);
  }
  TileSet tiles;
  tiles.Offsets.push_back(0);
  for (const std::int32_t id : ids)
  {
    if (id < 0 || std::size_t(id) >= index.size() || index[id] < 0)
    {
      continue;
    }
    const std::size_t k = std::size_t(index[id]);
    index[id] = -1; // repeats are skipped
    tiles.PointIds.push_back(id);
    tiles.Vertices.insert(tiles.Vertices.end(),
      all.Vertices.begin() + all.Offsets[k],
      all.Vertices.begin() + all.Offsets[k + 1]);
    tiles.Offsets.push_back(std::int64_t(tiles.Vertices.size()));
    tiles.Areas.push_back(all.Areas[k]);
    tiles.NeighborCounts.push_back(all.NeighborCounts[k]);
    if (mates)
    {
      mates->PointIds.push_back(id);
      const std::int32_t p = position[id];
      std::int32_t pair[2] = { p > 0 ? line[p - 1] : -1,
        p + 1 < std::int32_t(line.size()) ? line[p + 1] : -1 };
      std::sort(pair, pair + 2);
      for (const std::int32_t j : pair)
      {
        if (j >= 0)
        {
          mates->Ids.push_back(j);
        }
      }
      mates->Offsets.push_back(std::int64_t(mates->Ids.size()));
    }
  }
  return tiles;
}

TileSet LocalTiles(const Tess& tess,
  const std::vector<std::int32_t>& ids,
  bool wantTiles,
  FaceMateLists* mates)
{
  if (mates)
  {
    *mates = FaceMateLists();
    mates->Offsets.push_back(0);
  }
  if (!tess.IsTwoDimensional())
  {
    return CollinearTilesOf(tess, ids, mates);
  }
  TileSet tiles;
  tiles.Offsets.push_back(0);
  const std::vector<std::pair<std::int32_t, std::int32_t>> starts = VertexEdges(tess, ids);
  LocalFaces faces(tess, 8 * starts.size());
  std::vector<TileEdge> edges;
  std::vector<Point2> polygon;
  std::vector<std::int32_t> ring, scratch;
  for (const auto& [v, start] : starts)
  {
    // Label the faces of the ring first (RingTileEdges reads them).
    std::int32_t e = start;
    do
    {
      faces.Resolve(e / 3);
      e = tess.RingNext(e);
    } while (e != start);
    RingTileEdges(tess, faces, v, start, edges, ring);
    if (mates)
    {
      AppendMates(tess, faces, v, ring, scratch, *mates);
    }
    if (!wantTiles)
    {
      continue;
    }
    const std::int32_t sides = AssemblePolygon(tess, edges, polygon);
    tiles.PointIds.push_back(v);
    tiles.Vertices.insert(tiles.Vertices.end(), polygon.begin(), polygon.end());
    tiles.Offsets.push_back(std::int64_t(tiles.Vertices.size()));
    tiles.Areas.push_back(CompensatedPolygonArea(polygon.data(), polygon.size()));
    tiles.NeighborCounts.push_back(sides);
  }
  return tiles;
}

} // namespace

TileSet ComputeTilesOf(const DirichletTessellation& tessellation,
  const std::vector<std::int32_t>& ids,
  FaceMateLists* mates)
{
  return LocalTiles(tessellation, ids, true, mates);
}

FaceMateLists ComputeFaceMatesOf(const DirichletTessellation& tessellation,
  const std::vector<std::int32_t>& ids)
{
  FaceMateLists mates;
  LocalTiles(tessellation, ids, false, &mates);
  return mates;
}

} // namespace tessera
