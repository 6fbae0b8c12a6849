#include "polygon_area.h"

#include "compensated_sum.h"

#include <cmath>

namespace tessera
{

double CompensatedPolygonArea(const Point2* v, std::size_t n)
{
  // From the lowest vertex, so that a polygon listed from another vertex (a tile of the same
  // points numbered otherwise) gets the same bits.
  const std::size_t o = LowestVertex(v, n);
  const auto at = [v, n, o](std::size_t k) -> const Point2&
  { return v[o + k < n ? o + k : o + k - n]; };
  // Neumaier's compensation with Knuth's TwoSum (compensated_sum.h), which needs no comparison of
  // |sum| and |term| (a branch mispredicted about once per tile).
  CompensatedSum area;
  for (std::size_t k = 1; k + 1 < n; ++k)
  {
    const Point2& p = at(k);
    const Point2& q = at(k + 1);
    const double ax = p.x - v[o].x, ay = p.y - v[o].y;
    const double bx = q.x - v[o].x, by = q.y - v[o].y;
    area.Add(ax * by);
    area.Add(-(ay * bx));
  }
  return 0.5 * area.Value();
}

} // namespace tessera
