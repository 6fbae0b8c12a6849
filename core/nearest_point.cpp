// DirichletTessellation::NearestPoint and NearestPoints: the accepted point nearest a place, by the
// walk of Green and Sibson's section 2.3 run as a query: from a vertex, step to the neighbour
// nearest the place while one is strictly nearer. Every comparison is exact (compare_distance).
//
// Why the descent ends at a nearest point. If v is not nearest q, the segment from v to q leaves
// v's tile at a point x into the tile of a neighbour u; x is as near u as v, so
//
//        v ------x------ q         |qu| <= |qx| + |xu| = |qx| + |xv| = |qv|,
//                 \                with equality only for u on the segment beyond x, that is u = v:
//                  u               u is strictly nearer, and the descent goes on.
//
// So it may start at any vertex: NearestPoint starts at a vertex of the triangle holding q (found
// by the walk from the last triangle made), NearestPoints at the point found for the query before.
#include "dirichlet_tessellation.h"

#include "errors.h"
#include "predicates_inline.h"
#include "spatial_order.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <string>
#include <unordered_set>
#include <utility>

namespace tessera
{

namespace
{

/// Throws InputError naming q (which: "the query point", "query point 3") when it is not finite;
/// the name is made only then (a batch of 10^6 queries built a string each).
template<typename Which>
void CheckQuery(const Point2& q, const Which& which)
{
  if (!std::isfinite(q.x) || !std::isfinite(q.y))
  {
    throw InputError(which() + " (" + NumberText(q.x) + ", " + NumberText(q.y) + ") is not finite");
  }
}

/// Whether a is nearer q than b, or as near with the smaller id.
bool Nearer(const std::vector<Point2>& points, const Point2& q, std::int32_t a, std::int32_t b)
{
  const int c = compare_distance(q, points[a], points[b]);
  return c < 0 || (c == 0 && a < b);
}

/// The nearest to q of the collinear points (a scan; -1 when there are none).
std::int32_t NearestCollinear(const DirichletTessellation& t, const Point2& q)
{
  std::int32_t best = -1;
  for (const std::int32_t id : t.CollinearPoints())
  {
    best = best < 0 || Nearer(t.Points(), q, id, best) ? id : best;
  }
  return best;
}

/// visit(e, w) for each half-edge e leaving the origin of start, w its other (real) end.
template<typename Visit>
void EachNeighbour(const DirichletTessellation& t, std::int32_t start, const Visit& visit)
{
  const HalfEdgeArray& origin = t.Origin();
  std::int32_t e = start;
  do
  {
    if (const std::int32_t w = origin[DirichletTessellation::Next(e)];
        w != DirichletTessellation::Ghost)
    {
      visit(e, w);
    }
    e = t.RingNext(e);
  } while (e != start);
}

/// The descent from the origin of edge (a half-edge leaving a vertex) to a point nearest q, then
/// the smallest id among the points as near. edge ends leaving the descent's last vertex.
std::int32_t DescendToNearest(const DirichletTessellation& t, const Point2& q, std::int32_t& edge)
{
  const std::vector<Point2>& pts = t.Points();
  const HalfEdgeArray& origin = t.Origin();
  std::int32_t v = origin[edge];
  for (;;)
  {
    std::int32_t step = -1;
    EachNeighbour(t,
      edge,
      [&](std::int32_t e, std::int32_t w)
      {
        if (compare_distance(q, pts[w], pts[v]) < 0 &&
          (step < 0 || Nearer(pts, q, w, origin[DirichletTessellation::Next(step)])))
        {
          step = e;
        }
      });
    if (step < 0)
    {
      break;
    }
    v = origin[DirichletTessellation::Next(step)];
    edge = t.Twin()[step];
  }
  // Points as near as v lie with it on a circle about q that holds no point: a face of the
  // triangulation, whose points are joined around it; the smallest id among them.
  std::int32_t best = v;
  std::vector<std::pair<std::int32_t, std::int32_t>> tied{ { v, edge } }; // (point, edge leaving)
  // The ties found, in a set made at the first one (a query without ties allocates nothing): a
  // scan of the list made the centre of m points on a circle O(m^2), 0.24 s at m = 26244.
  std::unordered_set<std::int32_t> seen;
  const auto firstTie = [&](std::int32_t w)
  {
    if (seen.empty())
    {
      seen.insert(v);
    }
    return seen.insert(w).second;
  };
  for (std::size_t k = 0; k < tied.size(); ++k)
  {
    EachNeighbour(t,
      tied[k].second,
      [&](std::int32_t e, std::int32_t w)
      {
        if (compare_distance(q, pts[w], pts[v]) == 0 && firstTie(w))
        {
          tied.push_back({ w, t.Twin()[e] });
          best = std::min(best, w);
        }
      });
  }
  return best;
}

} // namespace

std::int32_t DirichletTessellation::NearestPoint(const Point2& q) const
{
  CheckQuery(q, [] { return std::string("the query point"); });
  if (!this->IsTwoDimensional())
  {
    return NearestCollinear(*this, q);
  }
  std::int32_t edge = -1;
  if (this->Locate(this->Serial, q, edge) == Location::InGhost)
  {
    edge = this->Twins[edge]; // (the hull edge's real side)
  }
  return DescendToNearest(*this, q, edge);
}

std::vector<std::int32_t> DirichletTessellation::NearestPoints(
  const std::vector<Point2>& queries) const
{
  for (std::size_t k = 0; k < queries.size(); ++k)
  {
    CheckQuery(queries[k], [k] { return "query point " + std::to_string(k); });
  }
  std::vector<std::int32_t> nearest(queries.size(), -1);
  if (queries.empty() || !this->IsTwoDimensional())
  {
    for (std::size_t k = 0; k < queries.size(); ++k)
    {
      nearest[k] = NearestCollinear(*this, queries[k]);
    }
    return nearest;
  }
  std::vector<std::int32_t> order(queries.size());
  std::iota(order.begin(), order.end(), 0);
  const Box2 box = BoundsOfIds(queries, order);
  if (std::isfinite(box.XMax - box.XMin) && std::isfinite(box.YMax - box.YMin))
  {
    SortAlongHilbertCurve(queries.data(), box, order); // (else, queries 1e308 apart, as given)
  }
  // The first walk goes from the last triangle made; each later descent from the point before.
  std::int32_t edge = -1;
  if (this->Locate(this->Serial, queries[order[0]], edge) == Location::InGhost)
  {
    edge = this->Twins[edge];
  }
  for (const std::int32_t k : order)
  {
    nearest[k] = DescendToNearest(*this, queries[k], edge);
  }
  return nearest;
}

} // namespace tessera
