#pragma once
// Internal to tessera_core: the geometric steps that both ways of clipping a tile by a catchment
// use (the Sutherland-Hodgman clipping in clip.cpp, the crossings' sums in crossing_area.cpp).
// Not part of the public API.

#include "geometry.h"
#include "predicates_inline.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

namespace tessera
{

// Where segment p-q meets the line a->b, interpolated from the endpoint nearer the line, so that
// the same segment gives the same point in either direction (neighbouring tiles then agree).
inline Point2 LineCrossing(const Point2& p, const Point2& q, const Point2& a, const Point2& b)
{
  const double ex = b.x - a.x;
  const double ey = b.y - a.y;
  const double dp = ex * (p.y - a.y) - ey * (p.x - a.x);
  const double dq = ex * (q.y - a.y) - ey * (q.x - a.x);
  const bool fromP = std::fabs(dp) < std::fabs(dq) ||
    (std::fabs(dp) == std::fabs(dq) && (p.x < q.x || (p.x == q.x && p.y <= q.y)));
  const Point2& s = fromP ? p : q;
  const Point2& t = fromP ? q : p;
  const double ds = fromP ? dp : dq;
  const double dt = fromP ? dq : dp;
  double f = ds / (ds - dt);
  // The exact signs decided that the segment crosses; rounded distances may disagree slightly.
  if (!(f >= 0.0))
  {
    f = 0.0;
  }
  f = std::min(f, 1.0);
  Point2 x{ s.x + f * (t.x - s.x), s.y + f * (t.y - s.y) };
  x.x = std::min(std::max(x.x, std::min(p.x, q.x)), std::max(p.x, q.x));
  x.y = std::min(std::max(x.y, std::min(p.y, q.y)), std::max(p.y, q.y));
  return x;
}

// Replaces points by their convex hull: anticlockwise, strictly convex (no repeated or collinear
// vertices), by Andrew's monotone chain with exact orientations. Empty or under 3 points when the
// points are collinear.
inline void ConvexHull(std::vector<Point2>& points, std::vector<Point2>& hull)
{
  std::sort(points.begin(), points.end(), ComesFirst);
  hull.clear();
  for (const Point2& p : points)
  {
    while (hull.size() >= 2 && orient2d_fast(hull[hull.size() - 2], hull.back(), p) <= 0)
    {
      hull.pop_back();
    }
    hull.push_back(p);
  }
  const std::size_t lower = hull.size();
  for (std::size_t i = points.size() - 1; i-- > 0;)
  {
    while (hull.size() > lower && orient2d_fast(hull[hull.size() - 2], hull.back(), points[i]) <= 0)
    {
      hull.pop_back();
    }
    hull.push_back(points[i]);
  }
  hull.pop_back(); // the first point again
  std::swap(points, hull);
}

// Whether p lies in the convex tile or on its boundary, exactly: left of or on every edge's line
// (strictly: left of every one), repeated vertices giving no edge. A tile not quite convex, by
// rounding, then holds p too: p lies in its kernel.
inline bool TileHoldsPoint(const Point2* tile,
  std::size_t count,
  const Point2& p,
  bool strictly = false)
{
  for (std::size_t k = 0; k < count; ++k)
  {
    const Point2& a = tile[k];
    const Point2& b = tile[k + 1 == count ? 0 : k + 1];
    if ((a.x != b.x || a.y != b.y) && orient2d_fast(a, b, p) < (strictly ? 1 : 0))
    {
      return false;
    }
  }
  return true;
}

// Whether a tile of this area inside box might be no more than the clipping's rounding
// (RoundingAreaBound of a convex tile, whose L1 perimeter is twice the box's width plus height,
// and whose coordinates relative to a vertex are at most the box's larger side).
inline bool ThinnerThanRounding(double tileArea, const Box2& box)
{
  const double width = box.XMax - box.XMin;
  const double height = box.YMax - box.YMin;
  return tileArea <=
    32.0 * std::numeric_limits<double>::epsilon() * std::max(width, height) * (width + height);
}

} // namespace tessera
