#include "nested_rings.h"

#include "polygon_validation.h"
#include "predicates.h"

#include <algorithm>
#include <cmath>

namespace tessera
{
namespace
{

struct RingView
{
  const Point2* Vertices = nullptr;
  std::size_t Count = 0;
  Box2 Box;
  double Area = 0.0; // signed: positive anticlockwise
};

double SignedArea(const Point2* ring, std::size_t count)
{
  double twice = 0.0;
  for (std::size_t k = 0; k < count; ++k)
  {
    const Point2& a = ring[k];
    const Point2& b = ring[(k + 1) % count];
    twice += a.x * b.y - b.x * a.y;
  }
  return 0.5 * twice;
}

bool Usable(const Point2* ring, std::size_t count)
{
  return count >= 3 &&
    std::all_of(
      ring, ring + count, [](const Point2& p) { return std::isfinite(p.x) && std::isfinite(p.y); });
}

bool BoxHolds(const Box2& outer, const Box2& inner)
{
  return outer.XMin <= inner.XMin && inner.XMax <= outer.XMax && outer.YMin <= inner.YMin &&
    inner.YMax <= outer.YMax;
}

// Whether the convex ring outer holds inner: every vertex of inner on the inner side of every
// edge of outer, or on it; and inner is not outer again (one of its vertices strictly inside, or
// its area smaller beyond rounding: a copy starting at another vertex sums its area in another
// order).
bool ConvexRingHolds(const RingView& outer, const RingView& inner)
{
  const int inside = outer.Area > 0.0 ? 1 : -1;
  std::vector<char> strictly(inner.Count, 1);
  for (std::size_t k = 0; k < outer.Count; ++k)
  {
    const Point2& a = outer.Vertices[k];
    const Point2& b = outer.Vertices[(k + 1) % outer.Count];
    for (std::size_t j = 0; j < inner.Count; ++j)
    {
      const int side = orient2d(a, b, inner.Vertices[j]);
      if (side == -inside)
      {
        return false;
      }
      strictly[j] = strictly[j] && side == inside;
    }
  }
  const bool smaller = std::fabs(inner.Area) < (1.0 - 1e-12) * std::fabs(outer.Area);
  return smaller || std::find(strictly.begin(), strictly.end(), 1) != strictly.end();
}

// A grid of about one cell per ring over the rings' box; each ring listed in the cells its box
// meets.
class BoxGrid
{
public:
  explicit BoxGrid(const std::vector<RingView>& rings)
  {
    Box2 all = rings.front().Box;
    for (const RingView& ring : rings)
    {
      all.Extend(ring.Box);
    }
    this->Bounds = all;
    // About one cell a ring, the cells about square (rings stacked in a column would otherwise
    // each span every column).
    const double cells = double(rings.size());
    const double width = all.XMax - all.XMin, height = all.YMax - all.YMin;
    const double aspect = width > 0.0 && height > 0.0 ? width / height : 1.0;
    const double columns = std::clamp(std::round(std::sqrt(cells * aspect)), 1.0, cells);
    this->Columns = std::size_t(columns);
    this->Rows = std::size_t(std::clamp(std::round(cells / columns), 1.0, cells));
    this->Cells.resize(this->Columns * this->Rows);
    for (std::size_t r = 0; r < rings.size(); ++r)
    {
      const Box2& box = rings[r].Box;
      const std::size_t i0 = this->Column(box.XMin), i1 = this->Column(box.XMax);
      const std::size_t j0 = this->Row(box.YMin), j1 = this->Row(box.YMax);
      for (std::size_t j = j0; j <= j1; ++j)
      {
        for (std::size_t i = i0; i <= i1; ++i)
        {
          this->Cells[j * this->Columns + i].push_back(r);
        }
      }
    }
  }

  const std::vector<std::size_t>& RingsAt(const Point2& p) const
  {
    return this->Cells[this->Row(p.y) * this->Columns + this->Column(p.x)];
  }

private:
  static std::size_t Index(double value, double low, double high, std::size_t count)
  {
    const double t = high > low ? (value - low) / (high - low) : 0.0;
    const double cell = std::floor(t * double(count));
    return std::size_t(std::clamp(cell, 0.0, double(count - 1)));
  }
  std::size_t Column(double x) const
  {
    return Index(x, this->Bounds.XMin, this->Bounds.XMax, this->Columns);
  }
  std::size_t Row(double y) const
  {
    return Index(y, this->Bounds.YMin, this->Bounds.YMax, this->Rows);
  }

  Box2 Bounds;
  std::size_t Columns = 1;
  std::size_t Rows = 1;
  std::vector<std::vector<std::size_t>> Cells;
};

} // namespace

std::optional<std::pair<std::size_t, std::size_t>> FindRingInsideAnother(
  const std::vector<std::size_t>& offsets,
  const std::vector<Point2>& vertices)
{
  CheckRingOffsets(offsets, vertices.size());
  std::vector<RingView> rings;
  std::vector<std::size_t> numbers; // the caller's number of each ring kept
  for (std::size_t r = 0; r + 1 < offsets.size(); ++r)
  {
    const Point2* ring = vertices.data() + offsets[r];
    const std::size_t count = offsets[r + 1] - offsets[r];
    if (!Usable(ring, count))
    {
      continue;
    }
    const double area = SignedArea(ring, count);
    if (area != 0.0 && std::isfinite(area))
    {
      rings.push_back({ ring, count, BoundsOf(ring, count), area });
      numbers.push_back(r);
    }
  }
  if (rings.size() < 2)
  {
    return std::nullopt;
  }
  const BoxGrid grid(rings);
  for (std::size_t b = 0; b < rings.size(); ++b)
  {
    const RingView& inner = rings[b];
    for (const std::size_t a : grid.RingsAt(inner.Vertices[0]))
    {
      const RingView& outer = rings[a];
      if (a != b && std::fabs(inner.Area) <= std::fabs(outer.Area) &&
        BoxHolds(outer.Box, inner.Box) && ConvexRingHolds(outer, inner))
      {
        return std::make_pair(numbers[a], numbers[b]);
      }
    }
  }
  return std::nullopt;
}

} // namespace tessera
