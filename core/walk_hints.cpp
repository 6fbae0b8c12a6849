#include "walk_hints.h"

#include "spatial_order.h"

#include <algorithm>
#include <cmath>

namespace tessera
{
namespace
{
constexpr int Levels = 16;
constexpr std::uint32_t Cells = 1U << Levels; // a side
} // namespace

void WalkHints::Build(const std::int32_t* origins,
  std::size_t halfEdges,
  const std::vector<Point2>& points,
  std::size_t changes)
{
  const std::size_t triangles = halfEdges / 3;
  this->Built = triangles;
  this->ChangesAtBuild = changes;
  this->Entries.clear();
  // Each real triangle's first real vertex: the triangle's entry, and the box it is keyed over.
  std::vector<Entry> firsts;
  firsts.reserve(triangles);
  for (std::size_t t = 0; t < triangles; ++t)
  {
    const std::int32_t* v = origins + 3 * t;
    const std::int32_t first = v[0] >= 0 ? v[0] : v[1] >= 0 ? v[1] : v[2];
    if (first >= 0)
    {
      firsts.emplace_back(std::uint32_t(first), std::int32_t(t));
    }
  }
  if (firsts.empty())
  {
    return;
  }
  this->Box = BoundsOf(&points[firsts[0].first], 1);
  for (const Entry& e : firsts)
  {
    this->Box.Extend(points[e.first]);
  }
  // (one scale for both axes, as the batch's curve; a side that overflows, or one so small that
  // the scale does, gives no index: 0 * inf at the box's edge made a NaN cell)
  const double side = this->Box.LargerSide();
  const double scale = double(Cells) / side;
  this->Scale = side > 0.0 && std::isfinite(side) && std::isfinite(scale) ? scale : 0.0;
  if (this->Scale == 0.0)
  {
    return;
  }
  for (Entry& e : firsts)
  {
    e.first = this->Key(points[e.first]);
  }
  std::sort(firsts.begin(), firsts.end());
  this->Entries.swap(firsts);
}

std::uint32_t WalkHints::Key(const Point2& p) const
{
  // (a point outside the box takes the cell at its edge: GridCell)
  return HilbertIndex(GridCell((p.x - this->Box.XMin) * this->Scale, Cells),
    GridCell((p.y - this->Box.YMin) * this->Scale, Cells),
    Levels);
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
