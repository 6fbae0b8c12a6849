#include "walk_hints.h"

#include "spatial_order.h"

#include <algorithm>
#include <cmath>

namespace tessera
{
namespace
{
constexpr int Levels = 16;
constexpr double Cells = 65536.0; // 2^Levels a side
} // namespace

void WalkHints::Build(const std::int32_t* origins,
  std::size_t halfEdges,
  const std::vector<Point2>& points)
{
  const std::size_t triangles = halfEdges / 3;
  this->Built = triangles;
  this->Entries.clear();
  bool first = true;
  for (std::size_t t = 0; t < triangles; ++t)
  {
    for (std::size_t k = 0; k < 3; ++k)
    {
      if (origins[3 * t + k] >= 0)
      {
        const Point2& p = points[std::size_t(origins[3 * t + k])];
        this->Box = first ? Box2{ p.x, p.x, p.y, p.y } : this->Box;
        this->Box.Extend(p);
        first = false;
      }
    }
  }
  const double side = std::max(this->Box.XMax - this->Box.XMin, this->Box.YMax - this->Box.YMin);
  // (one scale for both axes, as the batch's curve; a side that overflows, or one so small that
  // the scale does, gives no index: 0 * inf at the box's edge made a NaN cell)
  const double scale = Cells / side;
  this->Scale = side > 0.0 && std::isfinite(side) && std::isfinite(scale) ? scale : 0.0;
  if (first || this->Scale == 0.0)
  {
    return;
  }
  this->Entries.reserve(triangles);
  for (std::size_t t = 0; t < triangles; ++t)
  {
    for (std::size_t k = 0; k < 3; ++k)
    {
      if (origins[3 * t + k] >= 0)
      {
        this->Entries.emplace_back(
          this->Key(points[std::size_t(origins[3 * t + k])]), std::int32_t(t));
        break;
      }
    }
  }
  std::sort(this->Entries.begin(), this->Entries.end());
}

std::uint32_t WalkHints::Key(const Point2& p) const
{
  // (NaN-free: Insert refuses points that are not finite; a point outside the box takes the cell
  // at its edge)
  const double x = std::clamp((p.x - this->Box.XMin) * this->Scale, 0.0, Cells - 1.0);
  const double y = std::clamp((p.y - this->Box.YMin) * this->Scale, 0.0, Cells - 1.0);
  return HilbertIndex(std::uint32_t(x), std::uint32_t(y), Levels);
}

int WalkHints::Near(const Point2& p, std::int32_t near[3]) const
{
  if (this->Entries.empty())
  {
    return 0;
  }
  const std::size_t at = std::size_t(
    std::lower_bound(this->Entries.begin(), this->Entries.end(), Entry(this->Key(p), INT32_MIN)) -
    this->Entries.begin());
  int count = 0;
  for (std::size_t k = at > 0 ? at - 1 : 0; k < this->Entries.size() && k <= at + 1; ++k)
  {
    near[count++] = this->Entries[k].second;
  }
  return count;
}

} // namespace tessera
