#include "fp_contract_off.h" // first: the double-double sums below rely on separate roundings

// The area of a convex tile & the catchment from where the catchment's boundary crosses the
// tile's, for the areas-only calls (ClipInto without rings). The clipping's cost grows with the
// segments inside a tile (each goes through every tile edge); this grows with those near its
// boundary.
//
// With every ring oriented so that the catchment lies on its left, the catchment's indicator w is
// the sum of the rings' winding numbers, and by Green's theorem
//
//   2 area(T & catchment) = sum over the rings' pieces inside T of  sum cross(p_k, p_k+1)
//                         + sum over stretches of T's boundary of   w(stretch) cross(s, t)
//
//            exit: w + 1 after it, going anticlockwise round T
//         +-------x---------------+
//         |      /  piece         |      A piece runs from an entry to the next exit along its
//         |     /                 |      ring; its middle vertices' terms are prefix sums over
//         |    (    catchment     |      the ring (O(1) per piece), its ends are partial segments.
//         |     \   (w = 1)       |      w along T's boundary starts at T's first vertex (a ray's
//         |      \                |      crossings, exact) and steps by 1 at each crossing.
//         +-------x---------------+
//            entry: w - 1 after it
//
// Rings that do not cross T add their whole area when inside it and nothing otherwise; those
// winding round T are in w. So a tile costs its crossings, the segments listed in the grid cells
// along its boundary, a ray along one grid row, and the rings.
//
// Every decision is exact, on the input coordinates (orient2d): which segments cross which hull
// edge, entries and exits, and w at the first vertex. In general position the crossings are
// isolated points where a segment passes from one side of a hull edge to the other. Anything else
// (a catchment vertex on T's boundary, a segment through a hull vertex, crossings that do not
// alternate) returns false and the clipping decides, as it does a result within a billionth of the
// tile of 0 or of the whole tile (where its rounding rules say what is empty), catchments with more
// than 64 rings, hulls of more than 64 vertices, and coordinates so far from their extent that the
// double-double sums could err by more than an ulp of the tile's area.
//
// Crossing points and partial segments are computed relative to the hull's first vertex, as the
// clipping's are; the prefix sums, on the input coordinates, are moved there exactly by
// sum cross(p_k - o, p_k+1 - o) = sum cross(p_k, p_k+1) + cross(o, p_first) - cross(o, p_last).

#include "clip.h"
#include "clip_primitives.h"
#include "expansion_arithmetic.h"
#include "predicates_inline.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

namespace tessera
{
namespace
{

constexpr std::size_t MostRings = 64;
constexpr std::size_t MostHullVertices = 64;

// a + b + carry as a double-double: a + b exactly (TwoSum), its error and the carry added in one
// rounding (some eps^2 of the operands), the pair renormalised exactly.
DoubleDouble Sum(double a, double b, double carry)
{
  double sum = 0.0, error = 0.0;
  expansion::two_sum(a, b, sum, error);
  DoubleDouble result;
  expansion::two_sum(sum, error + carry, result.Hi, result.Lo);
  return result;
}

DoubleDouble Plus(const DoubleDouble& a, const DoubleDouble& b)
{
  return Sum(a.Hi, b.Hi, a.Lo + b.Lo);
}

DoubleDouble Minus(const DoubleDouble& a, const DoubleDouble& b)
{
  return Sum(a.Hi, -b.Hi, a.Lo - b.Lo);
}

// cross(a, b) = a.x b.y - a.y b.x from exact products (fma), rounded once to a double-double.
DoubleDouble Cross(const Point2& a, const Point2& b)
{
  double p = 0.0, pError = 0.0, q = 0.0, qError = 0.0;
  expansion::two_product_fma(a.x, b.y, p, pError);
  expansion::two_product_fma(a.y, b.x, q, qError);
  return Sum(p, -q, pError - qError);
}

Point2 Shifted(const Point2& p, const Point2& origin)
{
  return { p.x - origin.x, p.y - origin.y };
}

void AddCross(CompensatedSum& twice, const Point2& a, const Point2& b)
{
  twice.AddProduct(a.x, b.y);
  twice.AddProduct(-a.y, b.x);
}

// Where along edge a->b (0 to 1) a point on it lies, by its larger coordinate difference.
double AlongEdge(const Point2& p, const Point2& a, const Point2& b)
{
  const double dx = b.x - a.x, dy = b.y - a.y;
  return std::fabs(dx) >= std::fabs(dy) ? (p.x - a.x) / dx : (p.y - a.y) / dy;
}

} // namespace

// Below some 64 grid cells in the tile's box, listing the box's segments costs the clipping less
// than the hull and the cells along its edges cost this (bench_clip's 376 Colorado tiles over 2000
// outline vertices: 12% slower from 16 cells on, as fast from 64).
bool Catchment::CrossingsWorthIt(const Box2& box) const
{
  const std::size_t cells = (this->CellX(box.XMax) - this->CellX(box.XMin) + 1) *
    (this->CellY(box.YMax) - this->CellY(box.YMin) + 1);
  return cells >= 64 && this->RingCount() <= MostRings;
}

bool Catchment::AreaByCrossings(const Point2* tile,
  std::size_t count,
  double tileArea,
  const Box2& box,
  Workspace& work,
  double& area) const
{
  work.Hull.assign(tile, tile + count);
  ConvexHull(work.Hull, work.ClipB);
  const std::vector<Point2>& hull = work.Hull;
  if (hull.size() < 3 || hull.size() > MostHullVertices)
  {
    return false;
  }
  const Box2 hullBox = BoundsOf(hull.data(), hull.size());
  if (!this->FindCrossings(hull, work) ||
    this->SumsTooCoarse(hull[0], hullBox, tileArea, work.BoundaryCrossings.size() / 2 + 1))
  {
    return false;
  }
  CompensatedSum twice;
  if (!this->AddInsidePieces(hull[0], work, twice))
  {
    return false;
  }
  this->AddBoundaryStretches(hull, work, twice);
  const bool ringsWithin = this->AddRingsWithin(hull, hullBox, work, twice);
  if (work.BoundaryCrossings.empty() && !ringsWithin)
  {
    // All in or all out (as the clipping's empty cells say), but for a tile thinner than rounding.
    if (ThinnerThanRounding(tileArea, box))
    {
      return false;
    }
    area = twice.Value() > 0.0 ? tileArea : 0.0;
    ++work.AreasByCrossings;
    return true;
  }
  area = 0.5 * twice.Value();
  const double margin = 1e-9 * tileArea;
  if (!(area > margin && area < tileArea - margin))
  {
    return false; // near empty or whole: the clipping's rounding rules decide
  }
  ++work.AreasByCrossings;
  return true;
}

// Each of a tile's sweeps (a piece's, or a ring's within it) errs by PrefixError (the rings'
// prefix sums) and eps^2 of the products that move it to the origin: where the sweeps could err by
// more than an ulp of the tile's area (a tile under 4 sqrt(eps), some 2^-24, of its coordinates'
// size, or larger on outlines of millions of vertices far from the origin, or crossed many times),
// the clipping measures it instead.
bool Catchment::SumsTooCoarse(const Point2& origin,
  const Box2& hullBox,
  double tileArea,
  std::size_t sweeps) const
{
  const double eps = std::numeric_limits<double>::epsilon();
  const double magnitude = std::max({ this->Box.LargestMagnitude(),
    hullBox.LargestMagnitude(),
    std::fabs(origin.x),
    std::fabs(origin.y) });
  const double error = static_cast<double>(sweeps) *
    (4.0 * this->PrefixError + 16.0 * eps * eps * magnitude * magnitude);
  return !(error <= eps * tileArea);
}

// Every crossing of the hull's boundary by a catchment segment, into work.BoundaryCrossings: edge
// by edge, the segments listed in the grid cells the edge passes through (each once per edge, by
// work.SegmentStamp), which are all that can meet it: a segment's cells are those its box meets,
// so it shares one with any point of it. False where a segment touches the boundary other than
// by crossing an open edge (AddEdgeCrossing).
bool Catchment::FindCrossings(const std::vector<Point2>& hull, Workspace& work) const
{
  work.BoundaryCrossings.clear();
  if (work.SegmentStamp.size() < this->Points.size())
  {
    work.SegmentStamp.resize(this->Points.size(), 0);
  }
  for (std::size_t e = 0; e < hull.size(); ++e)
  {
    if (++work.Stamp == 0) // wrapped round: no segment may look seen
    {
      std::fill(work.SegmentStamp.begin(), work.SegmentStamp.end(), 0);
      work.Stamp = 1;
    }
    const Point2& p = hull[e];
    const Point2& q = hull[e + 1 == hull.size() ? 0 : e + 1];
    bool touching = false;
    this->ForEachCellAlong(p,
      q,
      [&](std::size_t cell)
      {
        for (std::uint32_t k = this->CellStart[cell]; k < this->CellStart[cell + 1] && !touching;
             ++k)
        {
          const std::uint32_t v = this->CellEdges[k];
          if (work.SegmentStamp[v] != work.Stamp)
          {
            work.SegmentStamp[v] = work.Stamp;
            touching = !this->AddEdgeCrossing(v, p, q, e, hull[0], work.BoundaryCrossings);
          }
        }
      });
    if (touching)
    {
      return false;
    }
  }
  return true;
}

// The grid cells that segment p-q passes through, and some beside them. Row by row, its x range
// over the row, widened by a sixteenth of a row and of a column for rounding (and by ulps of the
// coordinates where cells are only some ulps wide), gives its cells.
template<typename Visit>
void Catchment::ForEachCellAlong(const Point2& p, const Point2& q, Visit&& visit) const
{
  const double rowHeight = 1.0 / this->CellScaleY;
  const double ulps = 8.0 * std::numeric_limits<double>::epsilon() * this->Box.LargestMagnitude();
  const double rowMargin = std::max(0.0625 * rowHeight, ulps);
  const double margin = std::max(0.0625 / this->CellScaleX, ulps);
  const double yLow = std::min(p.y, q.y), yHigh = std::max(p.y, q.y);
  const double xLow = std::min(p.x, q.x), xHigh = std::max(p.x, q.x);
  const auto xAt = [&](double y, double level)
  { return p.y == q.y ? level : p.x + (y - p.y) * (q.x - p.x) / (q.y - p.y); };
  for (std::size_t j = this->CellY(yLow); j <= this->CellY(yHigh); ++j)
  {
    const double rowLow = this->Box.YMin + static_cast<double>(j) * rowHeight - rowMargin;
    const double rowHigh = this->Box.YMin + static_cast<double>(j + 1) * rowHeight + rowMargin;
    const double x0 = xAt(std::max(rowLow, yLow), xLow);
    const double x1 = xAt(std::min(rowHigh, yHigh), xHigh);
    const std::size_t i0 = this->CellX(std::max(std::min(x0, x1) - margin, xLow));
    const std::size_t i1 = this->CellX(std::min(std::max(x0, x1) + margin, xHigh));
    for (std::size_t i = i0; i <= i1; ++i)
    {
      visit(i + j * this->GridX);
    }
  }
}

// Segment v's crossing of hull edge e (from p to q), appended if there is one: false when the
// segment touches the edge otherwise, an end on the closed edge or the segment through p or q.
// (A segment along the edge's line through a hull vertex crosses the next edge's line there.)
//
//        a (outside: side < 0)               the segment crosses the edge when its ends lie
//         \                                  strictly on opposite sides of the edge's line and
//   p -----x--------- q   (inside above)     the edge's ends strictly on opposite sides of its
//           \                                own; entering when a is the outside end
//            b
bool Catchment::AddEdgeCrossing(std::uint32_t v,
  const Point2& p,
  const Point2& q,
  std::size_t e,
  const Point2& origin,
  std::vector<Crossing>& crossings) const
{
  const Point2& a = this->Points[v];
  const Point2& b = this->Points[this->NextVertex(v)];
  if (std::max(a.x, b.x) < std::min(p.x, q.x) || std::min(a.x, b.x) > std::max(p.x, q.x) ||
    std::max(a.y, b.y) < std::min(p.y, q.y) || std::min(a.y, b.y) > std::max(p.y, q.y))
  {
    return true;
  }
  const int sa = orient2d_fast(p, q, a);
  const int sb = orient2d_fast(p, q, b);
  if ((sa == 0 && OnSegment(p, q, a)) || (sb == 0 && OnSegment(p, q, b)))
  {
    return false;
  }
  if (sa * sb >= 0)
  {
    return true;
  }
  const int sp = orient2d_fast(a, b, p), sq = orient2d_fast(a, b, q);
  if (sp == 0 || sq == 0)
  {
    return false; // through a hull vertex
  }
  if (sp != sq)
  {
    Crossing c;
    c.Segment = v;
    c.Edge = static_cast<std::uint32_t>(e);
    c.Entry = sa < 0;
    const Point2 ps = Shifted(p, origin), qs = Shifted(q, origin);
    c.At = LineCrossing(Shifted(a, origin), Shifted(b, origin), ps, qs);
    c.Along = AlongEdge(c.At, ps, qs);
    c.Order = c.Entry ? 0 : 1; // a convex tile: a segment entering and leaving enters first
    crossings.push_back(c);
  }
  return true;
}

// Each ring's pieces inside the tile, from each entry to the next exit along the ring (crossings
// in ring order alternate, or this returns false). work.RingCrossed: 1 for rings crossed.
bool Catchment::AddInsidePieces(const Point2& origin, Workspace& work, CompensatedSum& twice) const
{
  std::vector<Crossing>& crossings = work.BoundaryCrossings;
  std::sort(crossings.begin(),
    crossings.end(),
    [](const Crossing& x, const Crossing& y)
    { return x.Segment != y.Segment ? x.Segment < y.Segment : x.Order < y.Order; });
  work.RingCrossed.assign(this->RingCount(), 0);
  for (std::size_t first = 0; first < crossings.size();)
  {
    const std::uint32_t ring = this->EdgeRing[crossings[first].Segment];
    std::size_t last = first;
    while (last < crossings.size() && this->EdgeRing[crossings[last].Segment] == ring)
    {
      ++last;
    }
    work.RingCrossed[ring] = 1;
    for (std::size_t k = first; k < last; ++k)
    {
      const Crossing& next = crossings[k + 1 == last ? first : k + 1];
      if (crossings[k].Entry == next.Entry)
      {
        return false;
      }
      if (crossings[k].Entry)
      {
        this->AddPiece(crossings[k], next, origin, twice);
      }
    }
    first = last;
  }
  return true;
}

// A piece from `in` to `out`: the rest of in's segment, the whole segments between (a sweep), the
// start of out's segment; or the part of one segment between the two.
void Catchment::AddPiece(const Crossing& in,
  const Crossing& out,
  const Point2& origin,
  CompensatedSum& twice) const
{
  if (in.Segment == out.Segment && in.Order < out.Order)
  {
    AddCross(twice, in.At, out.At);
    return;
  }
  const std::size_t first = this->NextVertex(in.Segment);
  AddCross(twice, in.At, Shifted(this->Points[first], origin));
  this->AddSweep(first, out.Segment, origin, twice);
  AddCross(twice, Shifted(this->Points[out.Segment], origin), out.At);
}

// sum cross(p_k - o, p_k+1 - o) over the segments from vertex p to vertex q of one ring (round its
// end when q comes before p; none when q is p).
void Catchment::AddSweep(std::size_t p,
  std::size_t q,
  const Point2& origin,
  CompensatedSum& twice) const
{
  const std::uint32_t ring = this->EdgeRing[p];
  DoubleDouble sweep = p <= q
    ? Minus(this->Prefix[q], this->Prefix[p])
    : Plus(Minus(this->RingSweep[ring], this->Prefix[p]), this->Prefix[q]);
  sweep = Minus(Plus(sweep, Cross(origin, this->Points[p])), Cross(origin, this->Points[q]));
  twice.Add(sweep.Hi);
  twice.Add(sweep.Lo);
}

// The tile's boundary, anticlockwise from the hull's first vertex, each stretch between crossings
// weighted by the catchment's indicator there: exact at the first vertex (no crossing is there),
// then up by one after an exit and down by one after an entry.
void Catchment::AddBoundaryStretches(const std::vector<Point2>& hull,
  Workspace& work,
  CompensatedSum& twice) const
{
  const std::vector<Crossing>& crossings = work.BoundaryCrossings;
  std::vector<std::uint32_t>& order = work.AlongBoundary;
  order.resize(crossings.size());
  for (std::size_t k = 0; k < order.size(); ++k)
  {
    order[k] = static_cast<std::uint32_t>(k);
  }
  std::sort(order.begin(),
    order.end(),
    [&](std::uint32_t x, std::uint32_t y)
    {
      const Crossing& cx = crossings[x];
      const Crossing& cy = crossings[y];
      return cx.Edge != cy.Edge ? cx.Edge < cy.Edge : cx.Along < cy.Along;
    });
  int w = this->IndicatorAtVertex(hull[0], work);
  Point2 from{ 0.0, 0.0 };
  std::size_t k = 0;
  for (std::size_t e = 0; e < hull.size(); ++e)
  {
    const Point2 to = Shifted(hull[e + 1 == hull.size() ? 0 : e + 1], hull[0]);
    for (; k < order.size() && crossings[order[k]].Edge == e; ++k)
    {
      const Crossing& c = crossings[order[k]];
      AddCross(twice, { w * from.x, w * from.y }, c.At);
      from = c.At;
      w += c.Entry ? -1 : 1;
    }
    AddCross(twice, { w * from.x, w * from.y }, to);
    from = to;
  }
}

// The catchment's indicator at a hull vertex, which lies on no segment: 0 outside the catchment's
// box, its cell's when no segment is listed there (ClassifyEmptyCells), else the winding counted
// along its row.
int Catchment::IndicatorAtVertex(const Point2& h, Workspace& work) const
{
  if (!(h.x >= this->Box.XMin && h.x <= this->Box.XMax && h.y >= this->Box.YMin &&
        h.y <= this->Box.YMax))
  {
    return 0;
  }
  const signed char empty =
    this->EmptyCellInside[this->CellX(h.x) + this->CellY(h.y) * this->GridX];
  return empty >= 0 ? empty : this->WindingAt(h, work);
}

// Rings that do not cross the tile's boundary and lie inside it: their whole area. (Their segments
// may lie in cells the boundary passes through, or not.) Whether there were any.
bool Catchment::AddRingsWithin(const std::vector<Point2>& hull,
  const Box2& hullBox,
  const Workspace& work,
  CompensatedSum& twice) const
{
  bool any = false;
  for (std::size_t r = 0; r < this->RingCount(); ++r)
  {
    if (work.RingCrossed[r] == 0 && hullBox.Holds(this->RingBoxes[r]) &&
      TileHoldsPoint(hull.data(), hull.size(), this->Points[this->Offsets[r]], true))
    {
      twice.Add(this->RingSweep[r].Hi);
      twice.Add(this->RingSweep[r].Lo);
      any = true;
    }
  }
  return any;
}

// The rings' prefix sums (Prefix, RingSweep), their boxes, and a bound on the sums' error: each
// double-double addition errs by a few eps^2 of its operands, each at most the sum of the terms'
// sizes (loose: n times that sum, which grows with n, so a tile's own area must too).
void Catchment::BuildPrefixSums()
{
  this->Prefix.resize(this->Points.size());
  this->RingSweep.resize(this->RingCount());
  this->RingBoxes.resize(this->RingCount());
  double sizes = 0.0;
  for (std::size_t r = 0; r < this->RingCount(); ++r)
  {
    DoubleDouble sum;
    for (std::size_t v = this->Offsets[r]; v < this->Offsets[r + 1]; ++v)
    {
      this->Prefix[v] = sum;
      const DoubleDouble term = Cross(this->Points[v], this->Points[this->NextVertex(v)]);
      sum = Plus(sum, term);
      sizes += std::fabs(term.Hi);
    }
    this->RingSweep[r] = sum;
    this->RingBoxes[r] =
      BoundsOf(&this->Points[this->Offsets[r]], this->Offsets[r + 1] - this->Offsets[r]);
  }
  const double eps = std::numeric_limits<double>::epsilon();
  this->PrefixError = 4.0 * eps * eps * static_cast<double>(this->Points.size() + 1) * sizes;
}

} // namespace tessera
