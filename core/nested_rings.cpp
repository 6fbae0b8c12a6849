#include "nested_rings.h"

#include "polygon_area.h"
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

bool Usable(const Point2* ring, std::size_t count)
{
  return count >= 3 &&
    std::all_of(
      ring, ring + count, [](const Point2& p) { return std::isfinite(p.x) && std::isfinite(p.y); });
}

// Whether the convex ring outer holds inner: every vertex of inner on the inner side of every
// edge of outer, or on it; and inner is not outer again (one of its vertices strictly inside, or
// its area smaller beyond rounding; a copy listed from another vertex has the same area to the
// bit, summed from its lowest vertex by CompensatedPolygonArea).
bool ConvexRingHolds(const RingView& outer, const RingView& inner)
{
  const int inside = outer.Area > 0.0 ? 1 : -1;
  bool someStrictlyInside = false;
  for (std::size_t j = 0; j < inner.Count; ++j)
  {
    bool strictly = true;
    for (std::size_t k = 0; k < outer.Count; ++k)
    {
      const int side =
        orient2d(outer.Vertices[k], outer.Vertices[(k + 1) % outer.Count], inner.Vertices[j]);
      if (side == -inside)
      {
        return false;
      }
      strictly = strictly && side == inside;
    }
    someStrictlyInside = someStrictlyInside || strictly;
  }
  return someStrictlyInside || std::fabs(inner.Area) < (1.0 - 1e-12) * std::fabs(outer.Area);
}

// About one cell a ring, the cells' sides at quantiles of the rings' centres (as many rings
// between any two cuts): a ring far from the rest squeezed all others into one cell of an even
// grid, and every ring then met every other (9.3 s for 90,000 squares and one 10^6 away); cut by
// comparisons alone, no coordinate overflows (boxes wider than the doubles crashed). Each ring is
// listed in the cells its box meets.
class BoxGrid
{
public:
  explicit BoxGrid(const std::vector<RingView>& rings)
  {
    // As many rows as leave about one ring a cell with the columns the x cuts gave (rings in one
    // column, their x cuts all one, take n / 2 rows, not sqrt(n)).
    const double n = double(rings.size());
    const std::size_t side = std::max<std::size_t>(1, std::size_t(std::ceil(std::sqrt(n))));
    this->XCuts = QuantileCuts(rings, side, [](const Box2& b) { return b.XMin / 2 + b.XMax / 2; });
    const std::size_t rows =
      std::max<std::size_t>(1, std::size_t(std::ceil(n / double(this->XCuts.size() + 1))));
    this->YCuts = QuantileCuts(rings, rows, [](const Box2& b) { return b.YMin / 2 + b.YMax / 2; });
    this->Columns = this->XCuts.size() + 1;
    this->Cells.resize(this->Columns * (this->YCuts.size() + 1));
    for (std::size_t r = 0; r < rings.size(); ++r)
    {
      const Box2& box = rings[r].Box;
      const std::size_t i0 = Slot(this->XCuts, box.XMin), i1 = Slot(this->XCuts, box.XMax);
      const std::size_t j0 = Slot(this->YCuts, box.YMin), j1 = Slot(this->YCuts, box.YMax);
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
    return this->Cells[Slot(this->YCuts, p.y) * this->Columns + Slot(this->XCuts, p.x)];
  }

private:
  // The distinct values of centre(box) at the quantiles k / side, k = 1 .. side - 1.
  template<typename Centre>
  static std::vector<double> QuantileCuts(const std::vector<RingView>& rings,
    std::size_t side,
    Centre centre)
  {
    std::vector<double> centres(rings.size());
    std::transform(rings.begin(),
      rings.end(),
      centres.begin(),
      [&](const RingView& ring) { return centre(ring.Box); });
    std::sort(centres.begin(), centres.end());
    std::vector<double> cuts;
    for (std::size_t k = 1; k < side; ++k)
    {
      cuts.push_back(centres[k * centres.size() / side]);
    }
    cuts.erase(std::unique(cuts.begin(), cuts.end()), cuts.end());
    return cuts;
  }

  // The slot of value between the cuts: monotone in value.
  static std::size_t Slot(const std::vector<double>& cuts, double value)
  {
    return std::size_t(std::upper_bound(cuts.begin(), cuts.end(), value) - cuts.begin());
  }

  std::vector<double> XCuts, YCuts;
  std::size_t Columns = 1;
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
    // (summed from a vertex: a small ring far from the origin keeps its area)
    const double area = CompensatedPolygonArea(ring, count);
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
      if (a != b && std::fabs(inner.Area) <= std::fabs(outer.Area) && outer.Box.Holds(inner.Box) &&
        ConvexRingHolds(outer, inner))
      {
        return std::make_pair(numbers[a], numbers[b]);
      }
    }
  }
  return std::nullopt;
}

} // namespace tessera
