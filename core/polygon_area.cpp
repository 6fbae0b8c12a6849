#include "polygon_area.h"

#include <cmath>
#include <initializer_list>

namespace tessera
{

double CompensatedPolygonArea(const Point2* v, std::size_t n)
{
  double sum = 0.0, compensation = 0.0;
  for (std::size_t k = 1; k + 1 < n; ++k)
  {
    const double ax = v[k].x - v[0].x, ay = v[k].y - v[0].y;
    const double bx = v[k + 1].x - v[0].x, by = v[k + 1].y - v[0].y;
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
