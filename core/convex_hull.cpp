// ConvexHullPositions: Akl and Toussaint's octagon filter, then Andrew's monotone chain on the
// points it keeps, with orient2d's exact signs; MoveHullToFront.
#include "convex_hull.h"

#include "predicates_inline.h"

#include <algorithm>
#include <array>
#include <limits>

namespace tessera
{
namespace
{

// The point reaching furthest in each of eight directions, anticlockwise from straight down
// (down, down-right, right, up-right, up, up-left, left, down-left), so that they lie on the hull
// in this order. The diagonal reaches are rounded sums: a point chosen there may not be the
// furthest, but it is one of the points, and that is all the filter needs.
using Extremes = std::array<Point2, 8>;
Extremes ExtremePoints(const Point2* points, std::int32_t count)
{
  // Reaches and positions in direction order; the updates are rare and their branches predicted.
  std::array<double, 8> reach;
  reach.fill(-std::numeric_limits<double>::infinity());
  std::array<std::int32_t, 8> at{};
  const auto keep = [&](int d, double r, std::int32_t k)
  {
    if (r > reach[d])
    {
      reach[d] = r;
      at[d] = k;
    }
  };
  for (std::int32_t k = 0; k < count; ++k)
  {
    const double x = points[k].x, y = points[k].y;
    const double sum = x + y, difference = x - y;
    keep(0, -y, k);
    keep(1, difference, k);
    keep(2, x, k);
    keep(3, sum, k);
    keep(4, y, k);
    keep(5, -difference, k);
    keep(6, -x, k);
    keep(7, -sum, k);
  }
  Extremes extremes;
  for (int d = 0; d < 8; ++d)
  {
    extremes[d] = points[at[d]];
  }
  return extremes;
}

// The extreme points in order, without the repeats of one point extreme in several directions.
std::vector<Point2> Octagon(const Extremes& extremes)
{
  std::vector<Point2> octagon;
  for (const Point2& p : extremes)
  {
    if (octagon.empty() || p != octagon.back())
    {
      octagon.push_back(p);
    }
  }
  while (octagon.size() > 1 && octagon.back() == octagon.front())
  {
    octagon.pop_back();
  }
  return octagon;
}

// Why a point strictly left of every edge of the octagon is no hull vertex, even where the rounded
// diagonal reaches left the octagon out of order (not convex): seen from such a point, each edge
// turns anticlockwise by more than nothing and less than a half turn, and the edges close, so they
// wind around it. Were it outside the octagon's hull or on its boundary, every vertex would lie
// within a half turn (closed) as seen from it, and a closed path of such steps cannot wind there.
// So it lies strictly inside the hull of some of the points.
bool InsideOctagon(const std::vector<Point2>& octagon, const Point2& p)
{
  const std::size_t n = octagon.size();
  for (std::size_t i = 0; i < n; ++i)
  {
    // (orient2d_fast: the floating-point filter decides nearly every point, exactly)
    if (orient2d_fast(octagon[i], octagon[i + 1 == n ? 0 : i + 1], p) <= 0)
    {
      return false;
    }
  }
  return true;
}

// Andrew's monotone chain over candidates sorted by x, then y: the lower chain left to right, then
// the upper one right to left, each dropping its last point before a turn that is not strictly
// anticlockwise (which also drops copies and points inside an edge).
std::vector<std::int32_t> MonotoneChain(const Point2* points, std::vector<std::int32_t>& candidates)
{
  if (candidates.size() < 3)
  {
    return {};
  }
  std::sort(candidates.begin(),
    candidates.end(),
    [points](std::int32_t i, std::int32_t j)
    {
      const Point2& a = points[i];
      const Point2& b = points[j];
      return a.x < b.x || (a.x == b.x && (a.y < b.y || (a.y == b.y && i < j)));
    });
  std::vector<std::int32_t> hull;
  const auto addTurningLeft = [&](std::int32_t k, std::size_t chainStart)
  {
    while (hull.size() >= chainStart + 2 &&
      orient2d_fast(points[hull[hull.size() - 2]], points[hull.back()], points[k]) <= 0)
    {
      hull.pop_back();
    }
    hull.push_back(k);
  };
  for (const std::int32_t k : candidates)
  {
    addTurningLeft(k, 0);
  }
  const std::size_t upperStart = hull.size() - 1; // (the rightmost point starts the upper chain)
  for (auto k = candidates.rbegin() + 1; k != candidates.rend(); ++k)
  {
    addTurningLeft(*k, upperStart);
  }
  hull.pop_back(); // the leftmost point again
  if (hull.size() < 3)
  {
    hull.clear();
  }
  return hull;
}

// An axis-aligned box whose corners are all strictly inside the octagon, so that a point strictly
// inside the box lies strictly inside the points' hull too (the hull is convex): four comparisons
// settle nearly every point, where the octagon takes eight orientations. Its sides start at the
// innermost of the three extreme points on each side, and it shrinks about its centre, by 1/64 of
// its sides and then by 1/8, until its corners are strictly inside: a corner often is one of the
// extreme points there (the one nearest the box's corner on both sides), on the octagon's edge.
// An empty box when neither does (every point then takes the octagon's test).
Box2 InnerBox(const Extremes& e, const std::vector<Point2>& octagon)
{
  const Box2 outer{ std::max({ e[5].x, e[6].x, e[7].x }),
    std::min({ e[1].x, e[2].x, e[3].x }),
    std::max({ e[7].y, e[0].y, e[1].y }),
    std::min({ e[3].y, e[4].y, e[5].y }) };
  for (const double shrink : { 1.0 / 64.0, 1.0 / 8.0 })
  {
    const double dx = shrink * (outer.XMax - outer.XMin);
    const double dy = shrink * (outer.YMax - outer.YMin);
    const Box2 box{ outer.XMin + dx, outer.XMax - dx, outer.YMin + dy, outer.YMax - dy };
    if (box.XMin < box.XMax && box.YMin < box.YMax &&
      InsideOctagon(octagon, { box.XMin, box.YMin }) &&
      InsideOctagon(octagon, { box.XMax, box.YMin }) &&
      InsideOctagon(octagon, { box.XMax, box.YMax }) &&
      InsideOctagon(octagon, { box.XMin, box.YMax }))
    {
      return box;
    }
  }
  return Box2{ 0.0, 0.0, 0.0, 0.0 };
}

bool StrictlyInside(const Box2& box, const Point2& p)
{
  return p.x > box.XMin && p.x < box.XMax && p.y > box.YMin && p.y < box.YMax;
}

} // namespace

std::vector<std::int32_t> ConvexHullPositions(const Point2* points,
  std::int32_t count,
  std::int32_t maxCandidates)
{
  if (count < 3)
  {
    return {};
  }
  const Extremes extremes = ExtremePoints(points, count);
  const std::vector<Point2> octagon = Octagon(extremes);
  // (With fewer than three extreme points, no point is inside the octagon: all are candidates.)
  const Box2 inner = InnerBox(extremes, octagon);
  std::vector<std::int32_t> candidates;
  for (std::int32_t k = 0; k < count; ++k)
  {
    if (!StrictlyInside(inner, points[k]) && !InsideOctagon(octagon, points[k]))
    {
      if (std::int32_t(candidates.size()) == maxCandidates)
      {
        return {};
      }
      candidates.push_back(k);
    }
  }
  return MonotoneChain(points, candidates);
}

std::int32_t MoveHullToFront(std::vector<Point2>& points,
  std::vector<std::int32_t>& ids,
  std::int32_t maxCandidates,
  std::int32_t maxHull)
{
  std::vector<std::int32_t> hull =
    ConvexHullPositions(points.data(), std::int32_t(points.size()), maxCandidates);
  if (std::int32_t(hull.size()) > maxHull)
  {
    return 0;
  }
  // In their order, not round the hull: inserted round a curved hull, each vertex lies inside the
  // circles of the triangles made before it, and an arc of H of them took some H^2 / 2 flips.
  // Ascending, hull[i] >= i, and the places below hull[i] that the swaps touch are 0 .. i - 1 and
  // hull[0 .. i - 1]: hull vertex i is still where it was.
  std::sort(hull.begin(), hull.end());
  for (std::int32_t i = 0; i < std::int32_t(hull.size()); ++i)
  {
    std::swap(points[i], points[hull[i]]);
    std::swap(ids[i], ids[hull[i]]);
  }
  return std::int32_t(hull.size());
}

} // namespace tessera
