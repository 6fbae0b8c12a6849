#include "dirichlet_tessellation.h"

#include "errors.h"
#include "predicates_inline.h"
#include "spatial_order.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace tessera
{
namespace
{

// Most points are far from the window's edges: decide those in floating point (the error of
// a*x + b*y + c is below 3 units of roundoff of |a*x| + |b*y| + |c|; 8 leaves a margin) and leave
// the rest to the exact Window::Contains.
bool ClearlyInside(const std::vector<HalfPlane>& constraints, const Point2& p)
{
  for (const HalfPlane& h : constraints)
  {
    const double ax = h.a * p.x, by = h.b * p.y;
    const double f = ax + by + h.c;
    const double bound =
      8.0 * 0x1p-53 * (std::fabs(ax) + std::fabs(by) + std::fabs(h.c)) + 0x1p-1000;
    if (!(f < -bound))
    {
      return false;
    }
  }
  return true;
}

bool LexicographicLess(const Point2& a, const Point2& b)
{
  return a.x < b.x || (a.x == b.x && a.y < b.y);
}

} // namespace

DirichletTessellation::DirichletTessellation(Window window)
  : TheWindow(std::move(window))
{
}

DirichletTessellation::DirichletTessellation(Window window, std::vector<Point2> points)
  : TheWindow(std::move(window))
  , Coordinates(std::move(points))
{
  if (this->Coordinates.size() > std::size_t(INT32_MAX / 8))
  {
    throw InputError("too many points: " + std::to_string(this->Coordinates.size()));
  }
  for (std::size_t id = 0; id < this->Coordinates.size(); ++id)
  {
    this->Validate(this->Coordinates[id], id);
  }
  std::vector<std::int32_t> inside;
  inside.reserve(this->Coordinates.size());
  const std::vector<HalfPlane>& constraints = this->TheWindow.EffectiveConstraints();
  for (std::size_t id = 0; id < this->Coordinates.size(); ++id)
  {
    const Point2& p = this->Coordinates[id];
    if (ClearlyInside(constraints, p) || this->TheWindow.Contains(p))
    {
      inside.push_back(std::int32_t(id));
    }
    else
    {
      this->Rejected.push_back(std::int32_t(id));
    }
  }
  this->BuildFrom(inside);
}

// Batch insertion in BRIO + Hilbert order. While building, vertex k is the k-th point of that
// order and Coordinates holds the points in that order: consecutive insertions then touch
// neighbouring memory instead of coordinates scattered by input id (the difference is a factor of
// about two at 1M points). At the end the vertices are renamed to input ids and the input order
// is restored, so the structure costs no more than with input ids throughout.
void DirichletTessellation::BuildFrom(std::vector<std::int32_t>& ids)
{
  // A triangulation of n points with its ghosts has exactly 2n - 2 triangles.
  const std::size_t triangles = ids.size() >= 3 ? 2 * ids.size() - 2 : 0;
  this->Origins.reserve(this->Origins.size() + 3 * triangles);
  this->Twins.reserve(this->Twins.size() + 3 * triangles);
  const std::vector<std::int32_t> order = BrioHilbertOrder(this->Coordinates, ids);
  ids.clear();
  ids.shrink_to_fit();
  std::vector<Point2> local(order.size());
  for (std::size_t k = 0; k < order.size(); ++k)
  {
    local[k] = this->Coordinates[order[k]];
  }
  std::vector<std::pair<std::int32_t, std::int32_t>> earlierDuplicates;
  earlierDuplicates.swap(this->DuplicatePairs);
  this->Coordinates.swap(local);
  this->BuildOrder = &order;
  for (std::size_t k = 0; k < order.size(); ++k)
  {
    this->InsertAcceptedPoint(std::int32_t(k));
  }
  this->BuildOrder = nullptr;
  this->Coordinates.swap(local);
  for (std::int32_t& v : this->Origins)
  {
    v = v >= 0 ? order[v] : v;
  }
  for (std::int32_t& v : this->Collinear)
  {
    v = order[v];
  }
  for (auto& pair : this->DuplicatePairs)
  {
    pair = { order[pair.first], order[pair.second] };
  }
  this->DuplicatePairs.insert(
    this->DuplicatePairs.end(), earlierDuplicates.begin(), earlierDuplicates.end());
}

void DirichletTessellation::Validate(const Point2& p, std::size_t id) const
{
  if (std::isnan(p.x) || std::isnan(p.y))
  {
    throw InputError("point " + std::to_string(id) + " has a NaN coordinate");
  }
  if (!std::isfinite(p.x) || !std::isfinite(p.y))
  {
    throw InputError("point " + std::to_string(id) + " has an infinite coordinate");
  }
}

std::int32_t DirichletTessellation::Insert(const Point2& p)
{
  const std::size_t id = this->Coordinates.size();
  this->Validate(p, id);
  if (id >= std::size_t(INT32_MAX / 8))
  {
    throw InputError("too many points: " + std::to_string(id + 1));
  }
  this->Coordinates.push_back(p);
  if (!this->TheWindow.Contains(p))
  {
    this->Rejected.push_back(std::int32_t(id));
  }
  else
  {
    this->InsertAcceptedPoint(std::int32_t(id));
  }
  return std::int32_t(id);
}

void DirichletTessellation::InsertAcceptedPoint(std::int32_t id)
{
  if (this->IsTwoDimensional())
  {
    this->InsertIntoTriangulation(id);
  }
  else
  {
    this->InsertCollinear(id);
  }
}

// ---------------------------------------------------------------------------------------------
// Collinear phase: the accepted points so far lie on one line; keep them sorted along it.

void DirichletTessellation::InsertCollinear(std::int32_t id)
{
  const std::vector<Point2>& pts = this->Coordinates;
  const Point2& p = pts[id];
  if (this->Collinear.size() >= 2 &&
    orient2d(pts[this->Collinear[0]], pts[this->Collinear[1]], p) != 0)
  {
    this->LeaveCollinearPhase(id);
    return;
  }
  auto at = std::lower_bound(this->Collinear.begin(),
    this->Collinear.end(),
    p,
    [&pts](std::int32_t k, const Point2& q) { return LexicographicLess(pts[k], q); });
  if (at != this->Collinear.end() && pts[*at] == p)
  {
    this->RecordDuplicate(id, *at, -1);
    if (this->InputId(id) < this->InputId(*at))
    {
      *at = id;
    }
    return;
  }
  this->Collinear.insert(at, id);
  ++this->Accepted;
}

// The first point off the line: make a triangle of it and two neighbouring points of the line,
// close it with three ghost triangles, and insert the rest of the line as ordinary points (they lie
// on the triangle's edge line, outside it or on its edge, which the general insertion handles).
//
//            p
//           / \          ghosts: (b,a,G) below a-b, (p,b,G) right of b-p, (a,p,G) left of p-a
//          /   \ .
//         a-----b
void DirichletTessellation::LeaveCollinearPhase(std::int32_t id)
{
  const std::vector<Point2>& pts = this->Coordinates;
  std::int32_t a = this->Collinear[0];
  std::int32_t b = this->Collinear[1];
  if (orient2d(pts[a], pts[b], pts[id]) < 0)
  {
    std::swap(a, b);
  }
  const std::vector<std::int32_t> rest(this->Collinear.begin() + 2, this->Collinear.end());
  this->Collinear.clear();
  this->Collinear.shrink_to_fit();
  const std::int32_t t0 = this->NewTriangle();
  const std::int32_t g1 = this->NewTriangle();
  const std::int32_t g2 = this->NewTriangle();
  const std::int32_t g3 = this->NewTriangle();
  this->SetTriangle(t0, a, b, id, 3 * g1, 3 * g2, 3 * g3);
  this->SetTriangle(g1, b, a, Ghost, 3 * t0, 3 * g3 + 2, 3 * g2 + 1);
  this->SetTriangle(g2, id, b, Ghost, 3 * t0 + 1, 3 * g1 + 2, 3 * g3 + 1);
  this->SetTriangle(g3, a, id, Ghost, 3 * t0 + 2, 3 * g2 + 2, 3 * g1 + 1);
  this->LastTriangle = t0;
  ++this->Accepted;
  this->Accepted -= rest.size();
  for (const std::int32_t r : rest)
  {
    this->InsertIntoTriangulation(r);
  }
}

// ---------------------------------------------------------------------------------------------
// Triangulation phase.

void DirichletTessellation::InsertIntoTriangulation(std::int32_t id)
{
  std::int32_t edge = -1;
  switch (this->Locate(this->Coordinates[id], edge))
  {
    case Location::OnVertex:
      this->RecordDuplicate(id, this->Origins[edge], edge);
      return;
    case Location::OnEdge:
      this->SplitEdge(edge, id);
      break;
    case Location::Inside:
    case Location::InGhost:
      this->SplitTriangle(edge / 3, id);
      break;
  }
  this->RestoreDelaunay();
  ++this->Accepted;
}

bool DirichletTessellation::IsGhostTriangle(std::int32_t t) const
{
  return this->Origins[3 * t] == Ghost || this->Origins[3 * t + 1] == Ghost ||
    this->Origins[3 * t + 2] == Ghost;
}

// Visibility walk from the last triangle created: cross any edge that has p strictly on its far
// side. In a Delaunay triangulation this walk cannot cycle. Reaching a ghost triangle means p is
// strictly outside the hull edge just crossed.
DirichletTessellation::Location DirichletTessellation::Locate(const Point2& p,
  std::int32_t& edge) const
{
  const std::vector<Point2>& pts = this->Coordinates;
  const std::vector<std::int32_t>& org = this->Origins;
  std::int32_t t = this->LastTriangle;
  if (this->IsGhostTriangle(t))
  {
    for (std::int32_t k = 0; k < 3; ++k)
    {
      const std::int32_t e = 3 * t + k;
      if (org[e] != Ghost && org[Next(e)] != Ghost)
      {
        t = this->Twins[e] / 3;
        break;
      }
    }
  }
  std::int32_t entered = -1;
  int sides[3];
  for (;;)
  {
    bool moved = false;
    for (std::int32_t k = 0; k < 3; ++k)
    {
      const std::int32_t e = 3 * t + k;
      if (e == entered)
      {
        sides[k] = 1; // p was strictly on this side when we crossed it
        continue;
      }
      sides[k] = orient2d_fast(pts[org[e]], pts[org[Next(e)]], p);
      if (sides[k] < 0)
      {
        const std::int32_t f = this->Twins[e];
        if (org[Prev(f)] == Ghost)
        {
          edge = f;
          return Location::InGhost;
        }
        t = f / 3;
        entered = f;
        moved = true;
        break;
      }
    }
    if (!moved)
    {
      break;
    }
  }
  for (std::int32_t k = 0; k < 3; ++k)
  {
    if (pts[org[3 * t + k]] == p)
    {
      edge = 3 * t + k;
      return Location::OnVertex;
    }
  }
  for (std::int32_t k = 0; k < 3; ++k)
  {
    if (sides[k] == 0)
    {
      edge = 3 * t + k;
      return Location::OnEdge;
    }
  }
  edge = 3 * t;
  return Location::Inside;
}

std::int32_t DirichletTessellation::NewTriangle()
{
  if (!this->FreeTriangles.empty())
  {
    const std::int32_t t = this->FreeTriangles.back();
    this->FreeTriangles.pop_back();
    return t;
  }
  const std::int32_t t = std::int32_t(this->Origins.size() / 3);
  this->Origins.resize(this->Origins.size() + 3);
  this->Twins.resize(this->Twins.size() + 3);
  return t;
}

void DirichletTessellation::SetTriangle(std::int32_t t,
  std::int32_t a,
  std::int32_t b,
  std::int32_t c,
  std::int32_t ta,
  std::int32_t tb,
  std::int32_t tc)
{
  const std::int32_t e = 3 * t;
  this->Origins[e] = a;
  this->Origins[e + 1] = b;
  this->Origins[e + 2] = c;
  this->Twins[e] = ta;
  this->Twins[e + 1] = tb;
  this->Twins[e + 2] = tc;
  if (ta >= 0)
  {
    this->Twins[ta] = e;
  }
  if (tb >= 0)
  {
    this->Twins[tb] = e + 1;
  }
  if (tc >= 0)
  {
    this->Twins[tc] = e + 2;
  }
}

// Every new triangle gets the new point p as its third vertex, so the edge to check against the
// empty-circle property is always its first half-edge; the flip stack holds triangle ids.
//
//          z                       z
//         / \                     /|\ .
//        /   \        ->         / p \ .
//       x-----y                 x-----y
void DirichletTessellation::SplitTriangle(std::int32_t t, std::int32_t p)
{
  const std::int32_t e = 3 * t;
  const std::int32_t x = this->Origins[e], y = this->Origins[e + 1], z = this->Origins[e + 2];
  const std::int32_t tx = this->Twins[e], ty = this->Twins[e + 1], tz = this->Twins[e + 2];
  const std::int32_t t1 = this->NewTriangle();
  const std::int32_t t2 = this->NewTriangle();
  this->SetTriangle(t, x, y, p, tx, 3 * t1 + 2, 3 * t2 + 1);
  this->SetTriangle(t1, y, z, p, ty, 3 * t2 + 2, 3 * t + 1);
  this->SetTriangle(t2, z, x, p, tz, 3 * t + 2, 3 * t1 + 1);
  this->FlipStack.push_back(t);
  this->FlipStack.push_back(t1);
  this->FlipStack.push_back(t2);
  this->LastTriangle = t;
}

// p lies strictly inside edge x->y (half-edge e); the far side may be a ghost (w = Ghost).
//
//          z                       z
//         / \                     /|\ .
//        x---y        ->         x-p-y
//         \ /                     \|/
//          w                       w
void DirichletTessellation::SplitEdge(std::int32_t e, std::int32_t p)
{
  const std::int32_t f = this->Twins[e];
  const std::int32_t x = this->Origins[e], y = this->Origins[Next(e)], z = this->Origins[Prev(e)];
  const std::int32_t w = this->Origins[Prev(f)];
  const std::int32_t oyz = this->Twins[Next(e)], ozx = this->Twins[Prev(e)];
  const std::int32_t oxw = this->Twins[Next(f)], owy = this->Twins[Prev(f)];
  const std::int32_t ta = e / 3, tb = f / 3;
  const std::int32_t tc = this->NewTriangle();
  const std::int32_t td = this->NewTriangle();
  this->SetTriangle(ta, y, z, p, oyz, 3 * tb + 2, 3 * td + 1);
  this->SetTriangle(tb, z, x, p, ozx, 3 * tc + 2, 3 * ta + 1);
  this->SetTriangle(tc, x, w, p, oxw, 3 * td + 2, 3 * tb + 1);
  this->SetTriangle(td, w, y, p, owy, 3 * ta + 2, 3 * tc + 1);
  this->FlipStack.push_back(ta);
  this->FlipStack.push_back(tb);
  this->FlipStack.push_back(tc);
  this->FlipStack.push_back(td);
  this->LastTriangle = ta;
}

// Whether the new point p (third vertex of triangle e / 3) lies strictly inside the circle of the
// triangle across edge e. For a ghost triangle the "circle" is the open half-plane beyond its hull
// edge.
bool DirichletTessellation::InConflict(std::int32_t e, std::int32_t p) const
{
  const std::vector<Point2>& pts = this->Coordinates;
  const std::int32_t f = this->Twins[e];
  const std::int32_t x = this->Origins[e], y = this->Origins[e + 1];
  const std::int32_t q = this->Origins[Prev(f)];
  if (q == Ghost)
  {
    return false; // e is a hull edge seen from inside: p is on the inner side
  }
  if (x == Ghost)
  {
    return orient2d_fast(pts[q], pts[y], pts[p]) > 0;
  }
  if (y == Ghost)
  {
    return orient2d_fast(pts[x], pts[q], pts[p]) > 0;
  }
  return incircle_fast(pts[y], pts[x], pts[q], pts[p]) > 0;
}

// Lawson flip of the first edge of triangle t (x->y, opposite the new point p) with the triangle
// (y, x, q) across it. Both results keep p third, so both are checked again.
//
//          p                       p
//         / \                     /|\ .
//        x---y        ->         x | y
//         \ /                     \|/
//          q                       q
void DirichletTessellation::Flip(std::int32_t t)
{
  const std::int32_t e = 3 * t;
  const std::int32_t x = this->Origins[e], y = this->Origins[e + 1], p = this->Origins[e + 2];
  const std::int32_t f = this->Twins[e];
  const std::int32_t t2 = f / 3;
  const std::int32_t q = this->Origins[Prev(f)];
  const std::int32_t oxq = this->Twins[Next(f)], oqy = this->Twins[Prev(f)];
  const std::int32_t oyp = this->Twins[e + 1], opx = this->Twins[e + 2];
  this->SetTriangle(t, x, q, p, oxq, 3 * t2 + 2, opx);
  this->SetTriangle(t2, q, y, p, oqy, oyp, 3 * t + 1);
  this->FlipStack.push_back(t);
  this->FlipStack.push_back(t2);
}

void DirichletTessellation::RestoreDelaunay()
{
  while (!this->FlipStack.empty())
  {
    const std::int32_t t = this->FlipStack.back();
    this->FlipStack.pop_back();
    if (this->InConflict(3 * t, this->Origins[3 * t + 2]))
    {
      this->Flip(t);
    }
  }
}

// ---------------------------------------------------------------------------------------------
// Duplicates: the smallest id among exact copies is the one kept, whatever the insertion order.

void DirichletTessellation::RecordDuplicate(std::int32_t id,
  std::int32_t kept,
  std::int32_t keptEdge)
{
  if (this->InputId(id) > this->InputId(kept))
  {
    this->DuplicatePairs.emplace_back(id, kept);
    return;
  }
  if (keptEdge >= 0)
  {
    this->Relabel(keptEdge, id);
  }
  for (auto& pair : this->DuplicatePairs)
  {
    if (pair.second == kept)
    {
      pair.second = id;
    }
  }
  this->DuplicatePairs.emplace_back(kept, id);
}

void DirichletTessellation::Relabel(std::int32_t edge, std::int32_t newId)
{
  std::int32_t e = edge;
  do
  {
    this->Origins[e] = newId;
    e = this->RingNext(e);
  } while (e != edge);
}

// ---------------------------------------------------------------------------------------------
// Status queries.

PointStatus DirichletTessellation::Status(std::int32_t id) const
{
  if (id < 0 || std::size_t(id) >= this->Coordinates.size())
  {
    throw InputError("point id " + std::to_string(id) + " is out of range");
  }
  if (std::find(this->Rejected.begin(), this->Rejected.end(), id) != this->Rejected.end())
  {
    return PointStatus::OutsideWindow;
  }
  if (std::find(this->RemovedPoints.begin(), this->RemovedPoints.end(), id) !=
    this->RemovedPoints.end())
  {
    return PointStatus::Removed;
  }
  for (const auto& pair : this->DuplicatePairs)
  {
    if (pair.first == id)
    {
      return PointStatus::Duplicate;
    }
  }
  return PointStatus::Accepted;
}

std::int32_t DirichletTessellation::DuplicateOf(std::int32_t id) const
{
  for (const auto& pair : this->DuplicatePairs)
  {
    if (pair.first == id)
    {
      return pair.second;
    }
  }
  return -1;
}

std::vector<std::int32_t> DirichletTessellation::RejectedIds() const
{
  std::vector<std::int32_t> ids = this->Rejected;
  std::sort(ids.begin(), ids.end());
  return ids;
}

std::vector<std::pair<std::int32_t, std::int32_t>> DirichletTessellation::Duplicates() const
{
  auto pairs = this->DuplicatePairs;
  std::sort(pairs.begin(), pairs.end());
  return pairs;
}

std::vector<std::int32_t> DirichletTessellation::RemovedIds() const
{
  std::vector<std::int32_t> ids = this->RemovedPoints;
  std::sort(ids.begin(), ids.end());
  return ids;
}

std::size_t DirichletTessellation::StructureBytes() const
{
  return this->Coordinates.capacity() * sizeof(Point2) +
    (this->Origins.capacity() + this->Twins.capacity() + this->FreeTriangles.capacity() +
      this->Collinear.capacity() + this->Rejected.capacity() + this->RemovedPoints.capacity() +
      this->FlipStack.capacity()) *
    sizeof(std::int32_t) +
    this->DuplicatePairs.capacity() * sizeof(std::pair<std::int32_t, std::int32_t>);
}

// ---------------------------------------------------------------------------------------------
// Removal.

std::int32_t DirichletTessellation::FindVertexEdge(std::int32_t id) const
{
  std::int32_t edge = -1;
  if (this->Locate(this->Coordinates[id], edge) == Location::OnVertex && this->Origins[edge] == id)
  {
    return edge;
  }
  return -1;
}

void DirichletTessellation::Remove(std::int32_t id)
{
  const PointStatus status = this->Status(id); // throws for an out-of-range id
  if (status == PointStatus::Removed)
  {
    throw InputError("point " + std::to_string(id) + " is already removed");
  }
  if (status == PointStatus::OutsideWindow)
  {
    this->Rejected.erase(std::find(this->Rejected.begin(), this->Rejected.end(), id));
    this->RemovedPoints.push_back(id);
    return;
  }
  if (status == PointStatus::Duplicate)
  {
    this->DuplicatePairs.erase(std::find_if(this->DuplicatePairs.begin(),
      this->DuplicatePairs.end(),
      [id](const auto& pair) { return pair.first == id; }));
    this->RemovedPoints.push_back(id);
    return;
  }
  std::int32_t edge = -1;
  std::vector<std::int32_t>::iterator onLine = this->Collinear.end();
  if (this->IsTwoDimensional())
  {
    edge = this->FindVertexEdge(id);
    if (edge < 0)
    {
      throw std::logic_error("accepted point not found in the triangulation");
    }
  }
  else
  {
    onLine = std::find(this->Collinear.begin(), this->Collinear.end(), id);
  }
  this->RemovedPoints.push_back(id);

  // A duplicate takes the removed point's place: the structure does not change.
  std::int32_t heir = -1;
  for (const auto& pair : this->DuplicatePairs)
  {
    if (pair.second == id && (heir < 0 || pair.first < heir))
    {
      heir = pair.first;
    }
  }
  if (heir >= 0)
  {
    this->DuplicatePairs.erase(std::find_if(this->DuplicatePairs.begin(),
      this->DuplicatePairs.end(),
      [heir](const auto& pair) { return pair.first == heir; }));
    for (auto& pair : this->DuplicatePairs)
    {
      if (pair.second == id)
      {
        pair.second = heir;
      }
    }
    if (edge >= 0)
    {
      this->Relabel(edge, heir);
    }
    else
    {
      *onLine = heir;
    }
    return;
  }

  --this->Accepted;
  if (!this->IsTwoDimensional())
  {
    this->Collinear.erase(onLine);
    return;
  }
  if (!this->RemoveInteriorVertex(edge))
  {
    this->RebuildWithout(id);
  }
}

// Re-triangulates the star of an interior vertex by cutting Delaunay ears (Devillers 1999): an ear
// (a, b, c) of the link polygon that turns left and whose circle contains no other link vertex is
// a triangle of the Delaunay triangulation without the vertex. Returns false (nothing changed)
// for a hull vertex, which the caller handles by rebuilding.
//
//        c---b                 c---b
//       / \ / \               /   / \ .
//      d---v---a     ->      d   /   a     ear (a, b, c) cut first; then the smaller polygon
//       \ / \ /               \ /   /
//        e---f                 e---f
bool DirichletTessellation::RemoveInteriorVertex(std::int32_t edge)
{
  std::vector<std::int32_t> ring;  // link vertices, anticlockwise
  std::vector<std::int32_t> outer; // outer[i]: twin of the link edge ring[i] -> ring[i+1]
  std::vector<std::int32_t> slots; // the star's triangles, reused
  std::int32_t e = edge;
  do
  {
    const std::int32_t j = this->Origins[Next(e)];
    if (j == Ghost)
    {
      return false;
    }
    ring.push_back(j);
    outer.push_back(this->Twins[Next(e)]);
    slots.push_back(e / 3);
    e = this->RingNext(e);
  } while (e != edge);

  struct Ear
  {
    std::int32_t A, B, C, TwinA, TwinB, TwinC;
  };
  std::vector<Ear> plan;
  const std::vector<Point2>& pts = this->Coordinates;
  std::size_t used = 0;
  while (ring.size() > 3)
  {
    const std::size_t n = ring.size();
    bool cut = false;
    for (std::size_t i = 0; i < n && !cut; ++i)
    {
      const std::size_t b = (i + 1) % n, c = (i + 2) % n;
      const Point2& pa = pts[ring[i]];
      const Point2& pb = pts[ring[b]];
      const Point2& pc = pts[ring[c]];
      if (orient2d_fast(pa, pb, pc) <= 0)
      {
        continue;
      }
      bool empty = true;
      for (std::size_t k = 0; k < n && empty; ++k)
      {
        if (k != i && k != b && k != c && incircle_fast(pa, pb, pc, pts[ring[k]]) > 0)
        {
          empty = false;
        }
      }
      if (!empty)
      {
        continue;
      }
      const std::int32_t t = slots[used++];
      plan.push_back({ ring[i], ring[b], ring[c], outer[i], outer[b], -1 });
      outer[i] = 3 * t + 2; // the new link edge ring[i] -> ring[c] faces this triangle's c -> a
      ring.erase(ring.begin() + std::ptrdiff_t(b));
      outer.erase(outer.begin() + std::ptrdiff_t(b));
      cut = true;
    }
    if (!cut)
    {
      return false; // cannot happen with exact predicates; rebuilding is always correct
    }
  }
  plan.push_back({ ring[0], ring[1], ring[2], outer[0], outer[1], outer[2] });
  for (std::size_t k = 0; k < plan.size(); ++k)
  {
    const Ear& ear = plan[k];
    this->SetTriangle(slots[k], ear.A, ear.B, ear.C, ear.TwinA, ear.TwinB, ear.TwinC);
  }
  for (std::size_t k = plan.size(); k < slots.size(); ++k)
  {
    const std::int32_t t = slots[k];
    this->Origins[3 * t] = this->Origins[3 * t + 1] = this->Origins[3 * t + 2] = Free;
    this->Twins[3 * t] = this->Twins[3 * t + 1] = this->Twins[3 * t + 2] = -1;
    this->FreeTriangles.push_back(t);
  }
  this->LastTriangle = slots[0];
  return true;
}

// Hull vertices (and the rare case where the rest becomes collinear) are removed by building the
// structure again from the remaining accepted points: O(N log N), but exactly the tessellation
// built without the point.
void DirichletTessellation::RebuildWithout(std::int32_t id)
{
  std::vector<char> isVertex(this->Coordinates.size(), 0);
  for (const std::int32_t v : this->Origins)
  {
    if (v >= 0 && v != id)
    {
      isVertex[v] = 1;
    }
  }
  std::vector<std::int32_t> ids;
  for (std::size_t v = 0; v < isVertex.size(); ++v)
  {
    if (isVertex[v])
    {
      ids.push_back(std::int32_t(v));
    }
  }
  this->Origins.clear();
  this->Twins.clear();
  this->FreeTriangles.clear();
  this->Collinear.clear();
  this->LastTriangle = 0;
  this->Accepted = 0;
  this->BuildFrom(ids);
}

} // namespace tessera
