#include "meridian_cut.h"

namespace tessera
{
namespace
{

/// Where edge a-b crosses x = at, computed from its lower end whichever way it runs.
Point2 Crossing(const Point2& a, const Point2& b, double at)
{
  const bool aFirst = ComesFirst(a, b);
  const Point2& p = aFirst ? a : b;
  const Point2& q = aFirst ? b : a;
  return { at, p.y + (at - p.x) / (q.x - p.x) * (q.y - p.y) };
}

/// Sutherland-Hodgman against one side of x = at (side -1: x <= at, +1: x >= at).
void AppendSide(const Point2* ring, std::size_t count, double at, double side, ClippedRings& out)
{
  const std::size_t start = out.Vertices.size();
  for (std::size_t i = 0; i < count; ++i)
  {
    const Point2& a = ring[i];
    const Point2& b = ring[i + 1 < count ? i + 1 : 0];
    const double da = side * (a.x - at), db = side * (b.x - at);
    if (da >= 0.0)
    {
      out.Vertices.push_back(a);
    }
    if ((da < 0.0 && db > 0.0) || (da > 0.0 && db < 0.0))
    {
      out.Vertices.push_back(Crossing(a, b, at));
    }
  }
  if (out.Vertices.size() - start < 3)
  {
    out.Vertices.resize(start);
    return;
  }
  out.RingOffsets.push_back(out.Vertices.size());
}

} // namespace

std::array<ClippedRings, 2> CutAtMeridian(const ClippedRings& pieces,
  std::size_t first,
  std::size_t last,
  double at)
{
  std::array<ClippedRings, 2> sides;
  for (std::size_t r = first; r < last; ++r)
  {
    const std::size_t begin = pieces.RingOffsets[r];
    const std::size_t count = pieces.RingOffsets[r + 1] - begin;
    AppendSide(&pieces.Vertices[begin], count, at, -1.0, sides[0]);
    AppendSide(&pieces.Vertices[begin], count, at, 1.0, sides[1]);
  }
  return sides;
}

} // namespace tessera
