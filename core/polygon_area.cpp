#include "polygon_area.h"

#include <cmath>
#include <initializer_list>

namespace tessera
{

double CompensatedPolygonArea(const Point2* v, std::size_t n)
{
  // From the lowest vertex, so that a polygon listed from another vertex (a tile of the same
  // points numbered otherwise) gets the same bits.
  const std::size_t o = LowestVertex(v, n);
  const auto at = [v, n, o](std::size_t k) -> const Point2&
  { return v[o + k < n ? o + k : o + k - n]; };
  double sum = 0.0, compensation = 0.0;
  for (std::size_t k = 1; k + 1 < n; ++k)
  {
    const Point2& p = at(k);
    const Point2& q = at(k + 1);
    const double ax = p.x - v[o].x, ay = p.y - v[o].y;
    const double bx = q.x - v[o].x, by = q.y - v[o].y;
    // Neumaier: each addition's exact rounding error goes to the compensation. Found by Knuth's
    // TwoSum, which needs no comparison of |sum| and |term| (a branch mispredicted about once per
    // tile) and gives the same exact error as the compare-and-subtract form.
    for (const double term : { ax * by, -(ay * bx) })
    {
      const double t = sum + term;
      const double z = t - sum;
      compensation += (sum - (t - z)) + (term - z);
      sum = t;
    }
  }
  return 0.5 * (sum + compensation);
}

} // namespace tessera
