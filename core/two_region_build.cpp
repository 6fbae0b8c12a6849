// Two-region batch insertion: the Delaunay triangulation of a large batch built on two cores.
//
// 1. A random sample, the first 1/32 of the BRIO order (its early rounds are random subsets), is
//    inserted serially, with the batch's hull vertices swapped into it first where the batch is
//    small (MoveHullToFront). The seam is the median x of the first four samples' worth of the
//    order; the points in a narrow strip around it follow, serially too.
// 2. Two regions insert the rest at once, each the points on its side of the seam in BRIO order.
//    A region owns the triangles whose vertices all lie on its side (a ghost vertex counts for
//    neither side). It defers a point whose walk or split would touch another triangle and skips
//    a Lawson flip across an edge into another triangle; once it has deferred most of the points
//    it tried, it defers the rest without walking (GivesUp). The triangles that straddle the seam
//    belong to neither region: nobody changes them while both run, so both may read them; the
//    twin link of such a triangle's edge whose ends are on one side is written by that side alone.
//
//             lower region      seam      upper region
//        +---------+---------+----:----+---------+
//        |  owned  | /  straddling :    \  owned  |     changed by the upper thread only
//        |  lower  |/ (frozen while both run)\  upper  |
//        +---------+---------+----:----+---------+
//
// 3. The triangulation is then Delaunay except possibly at edges of straddling triangles (the
//    skipped flips): Lawson's flip algorithm, which reaches the Delaunay triangulation from any
//    triangulation, is run from those edges.
// 4. The deferred points are inserted serially, along a Hilbert curve; preallocated triangles
//    left unused (by points that turned out to be duplicates) are compacted away.
//
// Each region reads only what it owns and what nobody writes, so the result depends on the input
// alone, never on timing or on the number of threads: with one core the regions run in turn.

#include "dirichlet_tessellation.h"

#include "convex_hull.h"
#include "large_pages.h"
#include "parallel_chunks.h"
#include "spatial_order.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace tessera
{
namespace
{

// Below this many points a serial build is about as fast as starting a thread and sewing the
// seam. Medians of 5 runs, serial against two regions: 4.1-4.8 against 3.8-4.3 ms at 10^4
// uniform points, 41-44 against 29-32 ms at 10^5.
constexpr std::int32_t TwoRegionMinimum = 10000;

// Below this many points the batch's hull vertices go into the sample (MoveHullToFront). A
// sample of m points leaves about (8/3) ln(m) / m of a square's area outside its hull (Renyi and
// Sulanke): 5% of 10^4 uniform points, 0.7% of 10^5, each deferred to the serial end. At 10^4 the
// deferred points went from 698 to 107 and their serial insertion from 0.32 to 0.10 ms, for
// 0.05 ms spent finding the hull; at 10^5 the hull took 0.45-0.70 ms and saved as much.
constexpr std::int32_t HullIntoSampleBelow = 100000;

// The seam is the median x of this many samples' worth of the order's first points (its early
// rounds are random subsets), not of the sample alone: at 10^4 points the sample's 312 put 53-57%
// of the points on one side for five seeds of eight, and the two regions finished up to 0.3 ms
// apart (at most 52% with four samples' worth; the seam's step took no longer). At most
// SeamMedianPoints of them, unless the sample has more: beyond, the median's error is some 0.2% of
// the points, and a larger serial selection buys nothing (4 samples' worth at 10^7 points: 1.25
// million).
constexpr std::int32_t SeamSamples = 4;
constexpr std::int32_t SeamMedianPoints = 1 << 16;

// The share of the batch inserted serially first: larger makes the straddling band thinner (fewer
// deferred points), smaller leaves more to the two regions.
constexpr std::int32_t SampleDivisor = 32;

// The points within a narrow strip around the seam, about 2 sqrt(N) of them (one spacing on either
// side for uniform points), are inserted serially after the sample too. The band of triangles
// that straddle the seam is then as narrow as the strip instead of as wide as the sample's
// triangles, and fewer points meet it: at 10^4 uniform points 256 strip points left 698 deferred
// instead of 1567, and the serial work took 0.40 ms instead of 0.63.
constexpr double SeamStripPointsPerRootN = 2.0;

// The strip's half-width: the distance to the seam within which the sample has its share of the
// strip's points. 0 (no strip) when the sample cannot tell.
double SeamStripHalfWidth(const Point2* pts, std::int32_t first, std::int32_t end, double seam)
{
  const double share = SeamStripPointsPerRootN * std::sqrt(double(end)) * first / end;
  const std::size_t k = std::size_t(share);
  if (k == 0 || k >= std::size_t(first))
  {
    return 0.0;
  }
  std::vector<double> gaps(static_cast<std::size_t>(first));
  for (std::int32_t j = 0; j < first; ++j)
  {
    gaps[j] = std::fabs(pts[j].x - seam);
  }
  std::nth_element(gaps.begin(), gaps.begin() + k, gaps.end());
  return gaps[k];
}

// Where a region's walk restarts when the straight walk from its last triangle runs into a
// triangle it does not own. The points of one side, taken in Hilbert order, leave the side and
// come back wherever the curve crosses the seam, and the straight walk between two such points
// may pass through the straddling band. A walk that failed there also left the region's last
// triangle where it was, so the points after it failed too: with 1M uniform points from one
// generator 7% were deferred, against 1.3% from another. Now the walk is tried once more from the
// triangle the region last made in the point's cell of a coarse grid (seeded with its sample
// triangles): a short walk that meets the band only near the seam. About 0.9% are deferred with
// either input. (A point the walk found, on an edge the region may not split, is deferred without
// a second walk, and the region's last triangle moves to where it was found: see InsertSide.)
//
// A slot the region has written holds a triangle it owns until both regions finish (it alone
// changes such triangles, and its splits and flips keep their vertices on its side), and so does
// an owned sample triangle: the restart reads nothing the other region writes. Each region has
// its own grid.
class RestartGrid
{
public:
  RestartGrid(const Box2& box, std::int32_t cellsPerSide)
    : Box(box)
    , Cells(cellsPerSide)
    , ScaleX(cellsPerSide / std::max(box.XMax - box.XMin, std::numeric_limits<double>::min()))
    , ScaleY(cellsPerSide / std::max(box.YMax - box.YMin, std::numeric_limits<double>::min()))
    , Triangles(std::size_t(cellsPerSide) * std::size_t(cellsPerSide), -1)
  {
  }

  /// The cell's triangle (-1: none yet) of a point in the box the grid was made for.
  std::int32_t& At(const Point2& p)
  {
    const std::int32_t i = this->Cell((p.x - this->Box.XMin) * this->ScaleX);
    const std::int32_t j = this->Cell((p.y - this->Box.YMin) * this->ScaleY);
    return this->Triangles[std::size_t(j) * std::size_t(this->Cells) + std::size_t(i)];
  }

private:
  // A side of the box far below 1 (subnormal widths) or beyond the largest double makes the
  // scale infinite or zero: any cell will do then (GridCell).
  std::int32_t Cell(double scaled) const
  {
    return std::int32_t(GridCell(scaled, std::uint32_t(this->Cells)));
  }

  Box2 Box;
  std::int32_t Cells;
  double ScaleX;
  double ScaleY;
  std::vector<std::int32_t> Triangles;
};

// About this many sample points per cell of a restart grid: a restart walk then crosses a few
// triangles.
constexpr std::int32_t SamplePointsPerCell = 4;

// A region that has deferred more than half of the points it tried, once it has tried this many,
// defers the rest without walking to them. Points in convex position (on a parabola, a circle)
// all lie outside the sample's hull, where a region may not insert, and each walk failed only
// after a long detour through the thin triangles across the curve: 10^6 points on a parabola
// spent 0.08 s failing for some seeds and 5.3 s for others, then 0.5 s in the serial insertion
// (CGAL: 0.56 to 0.86 s). On five lines of inexact slope most first tries of 10^6 points fail
// too (before, a third of all failed, after 1.8 s of walks; 40000 points defer a quarter). Copies
// of earlier points count as deferred: at 90% copies a region gives up, and the copies are met
// along the curve instead. Uniform points defer about 1% and never give up. The waste before giving
// up is at most 256 walks of MaxWalk steps; half keeps a region that still inserts most of its
// points on its core. The choice depends on the region's own points alone, so the result still does
// not depend on timing.
constexpr std::size_t TriesBeforeGivingUp = 256;

bool GivesUp(std::size_t tried, std::size_t deferred)
{
  return tried >= TriesBeforeGivingUp && 2 * deferred > tried;
}

} // namespace

// Inserts vertices [0, count) (BuildFrom's local numbering; order[k] is vertex k's input id) in
// order, on two regions when the batch is large.
void DirichletTessellation::InsertInOrder(std::vector<std::int32_t>& order, const Box2& box)
{
  const std::int32_t count = std::int32_t(order.size());
  const std::int32_t sample = count >= TwoRegionMinimum ? count / SampleDivisor : count;
  if (sample < count && count < HullIntoSampleBelow)
  {
    // The batch's hull vertices become the sample's first vertices (coordinates and input ids
    // alike), so that no point of the batch lies outside the sample's hull and waits for the
    // serial end: a region never grows the hull. The rest keeps its place in the order (the few
    // displaced sample points are inserted where the hull vertices were). Up to an eighth of the
    // points may be candidates, and the hull may fill half the sample. A disc has some 10% of its
    // points outside its octagon: at 10^4 points the hull took 0.16 ms there (0.05 for a square),
    // the points deferred went from about 700 to 245 (107), and the build took 1% less time (11%).
    MoveHullToFront(this->Coordinates, order, count / 8, sample / 2);
  }
  for (std::int32_t k = 0; k < sample; ++k)
  {
    this->InsertAcceptedPoint(k);
  }
  if (sample < count && !this->InsertInTwoRegions(sample, count, box))
  {
    for (std::int32_t k = sample; k < count; ++k)
    {
      this->InsertAcceptedPoint(k);
    }
  }
}

// The two-region build of vertices [First, End) after the sample [0, First): its steps, and the
// state they pass on.
struct DirichletTessellation::TwoRegionBuild
{
  TwoRegionBuild(DirichletTessellation& tess, std::int32_t first, std::int32_t end, const Box2& box)
    : T(tess)
    , Pts(tess.Coordinates.data())
    , First(first)
    , End(end)
    , Bounds(box)
  {
  }

  void SplitAtSeam();
  void FindTriangleOwners();
  void AllotSlots();
  void InsertSides();
  void InsertSide(std::size_t side);
  void Join();
  void InsertAlongCurve(std::vector<std::int32_t>& ids);
  bool OwnedBy(const Region& region, std::int32_t t) const;

  DirichletTessellation& T;
  const Point2* const Pts;
  const std::int32_t First, End;
  const Box2 Bounds;
  Region Regions[2];
  std::vector<std::int32_t> Sides[2]; // each region's points, in BRIO order
  std::int32_t SampleTriangles = 0;   // the triangles before the regions' slots
  std::vector<std::int8_t> OwnerOf;   // per sample triangle: its region's side, or NoOwner
  std::vector<std::int32_t> SeamEdges;
  std::vector<RestartGrid> Restarts;
  static constexpr std::int8_t NoOwner = -1;  // straddles the seam, or free
  static constexpr std::int32_t NoStart = -1; // a region's LastTriangle when it owns none
};

// Steps 2 to 4 for vertices [first, end). Returns false, having inserted nothing, when the
// sample is not yet two-dimensional.
bool DirichletTessellation::InsertInTwoRegions(std::int32_t first,
  std::int32_t end,
  const Box2& box)
{
  if (!this->IsTwoDimensional())
  {
    return false;
  }
  TwoRegionBuild build(*this, first, end, box);
  build.SplitAtSeam();
  build.FindTriangleOwners();
  build.AllotSlots();
  build.InsertSides();
  build.Join();
  return true;
}

// The seam at the median x of the order's first SeamSamples samples' worth of points; the points
// near it (the strip) inserted serially now, the others shared out to the two sides.
void DirichletTessellation::TwoRegionBuild::SplitAtSeam()
{
  const std::int32_t seamSample = std::min(
    this->End, std::max(this->First, std::min(SeamSamples * this->First, SeamMedianPoints)));
  std::vector<double> firstX(static_cast<std::size_t>(seamSample));
  for (std::int32_t k = 0; k < seamSample; ++k)
  {
    firstX[k] = this->Pts[k].x;
  }
  std::nth_element(firstX.begin(), firstX.begin() + seamSample / 2, firstX.end());
  for (int side = 0; side < 2; ++side)
  {
    this->Regions[side].SeamX = firstX[seamSample / 2];
    this->Regions[side].Upper = side == 1;
    this->Regions[side].MaxWalk = std::int64_t(8 * std::sqrt(double(this->End))) + 1024;
  }
  for (std::vector<std::int32_t>& side : this->Sides)
  {
    // Either may get them all; only what is used is touched.
    ReserveOnLargePages(side, std::size_t(this->End - this->First));
  }
  const double seam = this->Regions[0].SeamX;
  const double halfWidth = SeamStripHalfWidth(this->Pts, this->First, this->End, seam);
  std::vector<std::int32_t> strip;
  for (std::int32_t k = this->First; k < this->End; ++k)
  {
    if (std::fabs(this->Pts[k].x - seam) < halfWidth)
    {
      strip.push_back(k);
    }
    else
    {
      this->Sides[this->Regions[1].Owns(this->Pts[k]) ? 1 : 0].push_back(k);
    }
  }
  this->InsertAlongCurve(strip);
}

// Serial insertions of scattered points, each walking from the last: along the curve.
void DirichletTessellation::TwoRegionBuild::InsertAlongCurve(std::vector<std::int32_t>& ids)
{
  SortAlongHilbertCurve(this->Pts, this->Bounds, ids);
  for (const std::int32_t id : ids)
  {
    this->T.InsertAcceptedPoint(id);
  }
}

// Whether every real vertex of triangle t lies on the region's side.
bool DirichletTessellation::TwoRegionBuild::OwnedBy(const Region& region, std::int32_t t) const
{
  for (std::int32_t k = 0; k < 3; ++k)
  {
    const std::int32_t v = this->T.Origins[3 * t + k];
    if (v != Ghost && !region.Owns(this->Pts[v]))
    {
      return false;
    }
  }
  return true;
}

// Which region owns each sample triangle, and which triangles straddle the seam, before anything
// else changes: their edges are legalized after the regions (Join). (A point is on one side
// only, so a triangle has one owner at most.)
void DirichletTessellation::TwoRegionBuild::FindTriangleOwners()
{
  this->SampleTriangles = std::int32_t(this->T.Origins.size() / 3);
  this->OwnerOf.assign(std::size_t(this->SampleTriangles), NoOwner);
  for (std::int32_t t = 0; t < this->SampleTriangles; ++t)
  {
    if (this->T.IsFreeTriangle(t))
    {
      continue;
    }
    for (std::int8_t side = 0; side < 2; ++side)
    {
      if (this->OwnedBy(this->Regions[side], t))
      {
        this->OwnerOf[t] = side;
        break;
      }
    }
    if (this->OwnerOf[t] == NoOwner)
    {
      this->SeamEdges.insert(this->SeamEdges.end(), { 3 * t, 3 * t + 1, 3 * t + 2 });
    }
  }
}

// Each region gets 2 triangles per point: exactly what inserting all of them takes. Its restart
// grid starts with its owned sample triangles, and its first walk starts from the grid's triangle
// for its first point (from any owned triangle if that cell has none). A region that owns no real
// triangle (its side's points all on a line, beside a seam on another line) has nowhere to start:
// NoStart, and InsertSide defers its points. (It started in the serial insertion's last triangle,
// which the other region may own and be changing while this one reads it.)
void DirichletTessellation::TwoRegionBuild::AllotSlots()
{
  const std::int32_t cellsPerSide =
    std::max(1, std::int32_t(std::sqrt(double(this->First) / SamplePointsPerCell)));
  this->Restarts.assign(2, RestartGrid(this->Bounds, cellsPerSide));
  std::int32_t slot = this->SampleTriangles;
  for (int side = 0; side < 2; ++side)
  {
    Region& region = this->Regions[side];
    RestartGrid& restarts = this->Restarts[side];
    const std::vector<std::int32_t>& ids = this->Sides[side];
    region.NextSlot = slot;
    slot += 2 * std::int32_t(ids.size());
    region.EndSlot = slot;
    region.LastTriangle = NoStart;
    for (std::int32_t t = 0; t < this->SampleTriangles; ++t)
    {
      if (this->OwnerOf[t] == side && !this->T.IsGhostTriangle(t))
      {
        restarts.At(this->Pts[this->T.Origins[3 * t]]) = t;
        region.LastTriangle = t;
      }
    }
    if (!ids.empty() && restarts.At(this->Pts[ids.front()]) >= 0)
    {
      region.LastTriangle = restarts.At(this->Pts[ids.front()]);
    }
  }
  // Not written here: each region writes the triangles it makes, the rest are freed in Join.
  this->T.Origins.resize(3 * std::size_t(slot));
  this->T.Twins.resize(3 * std::size_t(slot));
}

// The two sides may run at once: InsertSide(side) touches only Regions[side], Restarts[side] and
// what that region owns.
void DirichletTessellation::TwoRegionBuild::InsertSides()
{
  if (parallel::ThreadLimit() > 1)
  {
    parallel::RunChunks(2, [this](std::size_t side) { this->InsertSide(side); });
  }
  else
  {
    this->InsertSide(0);
    this->InsertSide(1);
  }
}

// One region's points, in order, each inserted or deferred.
void DirichletTessellation::TwoRegionBuild::InsertSide(std::size_t side)
{
  Region& region = this->Regions[side];
  const std::vector<std::int32_t>& ids = this->Sides[side];
  if (region.LastTriangle == NoStart)
  {
    region.Deferred = ids; // (each walk would have ended Foreign at once)
    return;
  }
  for (std::size_t tried = 0; tried < ids.size(); ++tried)
  {
    if (GivesUp(tried, region.Deferred.size()))
    {
      region.Deferred.insert(region.Deferred.end(), ids.begin() + tried, ids.end());
      break;
    }
    const std::int32_t id = ids[tried];
    std::int32_t edge = -1;
    std::int32_t& restart = this->Restarts[side].At(this->Pts[id]);
    Location location = this->T.InsertInRegion(region, id, edge);
    if (location == Location::Foreign && edge >= 0)
    {
      // Found, on an edge whose far triangle the region may not change (a hull edge: points on
      // the hull's lines, as on two parallel lines, all are): deferred at once, and the next walk
      // starts here. Retried from the cell's restart triangle, each such point walked there and
      // back (two lines of 10^6 points: 170 million steps, 3.5 s against 0.3).
      region.LastTriangle = edge / 3;
    }
    else if (location == Location::Foreign && restart >= 0 && restart != region.LastTriangle)
    {
      region.LastTriangle = restart;
      location = this->T.InsertInRegion(region, id, edge);
    }
    if (location == Location::Foreign || location == Location::OnVertex)
    {
      region.Deferred.push_back(id);
    }
    else
    {
      restart = region.LastTriangle;
    }
  }
}

// The regions' unused slots freed, the seam legalized, and the deferred points inserted.
void DirichletTessellation::TwoRegionBuild::Join()
{
  DirichletTessellation& tess = this->T;
  for (Region& region : this->Regions)
  {
    tess.Accepted += region.Inserted;
    for (std::int32_t k = region.EndSlot - 1; k >= region.NextSlot; --k)
    {
      tess.FreeTriangle(k);
    }
  }
  // The seam is legalized whatever the regions saw (no short-circuit here).
  const bool seamCocircular = tess.LegalizeEdges(this->SeamEdges);
  tess.Serial.SawCocircular |=
    seamCocircular || this->Regions[0].SawCocircular || this->Regions[1].SawCocircular;
  for (const Region& region : this->Regions)
  {
    if (region.LastTriangle != NoStart)
    {
      tess.Serial.LastTriangle = region.LastTriangle;
      break;
    }
  }
  // The deferred points, along the curve: they lie near the seam and (from 10^5 points, where the
  // hull is not moved into the sample) outside the sample's hull, all around the batch, or anywhere
  // on a side given up, and walking to them in their rounds' order took 13 steps each at 1M
  // uniform points (5 along the curve), 10.6 ms against 5.3.
  std::vector<std::int32_t> deferred = std::move(this->Regions[0].Deferred);
  deferred.insert(
    deferred.end(), this->Regions[1].Deferred.begin(), this->Regions[1].Deferred.end());
  this->InsertAlongCurve(deferred);
  tess.CompactFreeTriangles();
}

// Lawson's flip algorithm from the given half-edges: flips every edge whose far apex lies strictly
// inside the circle of its triangle, and checks the four edges around each flip, until none is
// left. Ghost triangles take part through the same EdgeTest as RestoreDelaunay, so flips also make
// the hull convex again. Returns whether a test found two adjacent triangles exactly co-circular.
bool DirichletTessellation::LegalizeEdges(std::vector<std::int32_t>& edges)
{
  bool cocircular = false;
  const std::int32_t* const org = this->Origins.data();
  while (!edges.empty())
  {
    const std::int32_t e = edges.back();
    edges.pop_back();
    const std::int32_t f = this->Twins[e];
    const std::int32_t a = org[e], b = org[Next(e)], c = org[Prev(e)], d = org[Prev(f)];
    const int test = this->EdgeTest(a, b, c, d);
    cocircular |= test == 0;
    if (test > 0)
    {
      this->FlipEdge(e);
      // After the flip e is a -> d, Prev(e) c -> a, f d -> b and Next(f) b -> c.
      edges.insert(edges.end(), { e, Prev(e), f, Next(f) });
    }
  }
  return cocircular;
}

// Replaces the diagonal a - b of the quadrilateral a, d, b, c by c - d, keeping both triangles'
// slots and the positions of e and its twin f in them.
//
//          c                        c
//         / \                      /|\ .
//        a-e->b         ->        a | b
//         \ /                      \|/
//          d                        d
void DirichletTessellation::FlipEdge(std::int32_t e)
{
  std::int32_t* const org = this->Origins.data();
  std::int32_t* const twin = this->Twins.data();
  const std::int32_t f = twin[e];
  const std::int32_t e1 = Next(e), e2 = Prev(e), f1 = Next(f), f2 = Prev(f);
  const std::int32_t b = org[e1], c = org[e2], d = org[f2];
  const std::int32_t outerBC = twin[e1], outerAD = twin[f1], outerDB = twin[f2];
  // (a, d, c): e = a -> d, e1 = d -> c, e2 = c -> a keeps its twin.
  org[e1] = d;
  twin[e] = outerAD;
  twin[outerAD] = e;
  twin[e1] = f2;
  // (d, b, c): f = d -> b, f1 = b -> c, f2 = c -> d.
  org[f] = d;
  org[f1] = b;
  org[f2] = c;
  twin[f] = outerDB;
  twin[outerDB] = f;
  twin[f1] = outerBC;
  twin[outerBC] = f1;
  twin[f2] = e1;
}

// Moves the triangles at the end into the free slots below, so that the arrays hold exactly the
// triangulation (2n - 2 triangles) as a serial build would.
void DirichletTessellation::CompactFreeTriangles()
{
  this->ForgetWalkStarts(); // (its triangles are renumbered)
  std::vector<std::int32_t>& holes = this->FreeTriangles;
  std::sort(holes.begin(), holes.end());
  const std::int32_t count = std::int32_t(this->Origins.size() / 3);
  const std::int32_t kept = count - std::int32_t(holes.size());
  std::int32_t* const org = this->Origins.data();
  std::int32_t* const twin = this->Twins.data();
  std::int32_t from = count;
  for (const std::int32_t hole : holes)
  {
    if (hole >= kept)
    {
      break;
    }
    do
    {
      --from;
    } while (this->IsFreeTriangle(from));
    for (std::int32_t k = 0; k < 3; ++k)
    {
      const std::int32_t e = 3 * hole + k;
      org[e] = org[3 * from + k];
      twin[e] = twin[3 * from + k];
      twin[twin[e]] = e;
    }
  }
  std::vector<std::int32_t>().swap(holes); // the structure keeps no spare capacity
  this->Origins.resize(3 * std::size_t(kept));
  this->Twins.resize(3 * std::size_t(kept));
  if (this->Serial.LastTriangle >= kept)
  {
    this->Serial.LastTriangle = 0;
  }
}

} // namespace tessera
