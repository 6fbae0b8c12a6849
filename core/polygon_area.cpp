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
  double magnitude = 0.0; // the sum of the products' sizes, which their roundings scale with
  for (std::size_t k = 1; k + 1 < n; ++k)
  {
    const Point2& p = at(k);
    const Point2& q = at(k + 1);
    const double ax = p.x - v[o].x, ay = p.y - v[o].y;
    const double bx = q.x - v[o].x, by = q.y - v[o].y;
    area.Add(ax * by);
    area.Add(-(ay * bx));
    magnitude += std::fabs(ax * by) + std::fabs(ay * bx);
  }
  const double twice = area.Value();
  // The products' roundings (and the translation's) are parts in 2^53 of `magnitude`: for a tile
  // of ordinary shape a few times its area, for a long thin one (a strip between points on a
  // line, 1 long and 1e-6 wide) a million times: such strips of 10^6 collinear points summed to
  // 3e-12 off the window's area. Those are summed again from the coordinates themselves, each
  // product exact (fma), so that only the final sum is rounded.
  if (magnitude <= 64.0 * std::fabs(twice))
  {
    return 0.5 * twice;
  }
  CompensatedSum exact;
  for (std::size_t k = 0; k < n; ++k)
  {
    const Point2& p = at(k);
    const Point2& q = at(k + 1 < n ? k + 1 : 0);
    exact.AddProduct(p.x, q.y);
    exact.AddProduct(-q.x, p.y);
  }
  return 0.5 * exact.Value();
}

} // namespace tessera
