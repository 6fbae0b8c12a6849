// Catchment clipping, checked against independent computations: rectangle overlaps by hand, an
// exact rational (GMP) Sutherland-Hodgman over whole rings with nesting found by a rational
// even-odd test, exact rational catchment areas, and tilings whose pieces must add up.

#include "clip.h"
#include "dirichlet_tessellation.h"
#include "errors.h"
#include "geo.h"
#include "polygon_validation.h"
#include "predicates.h"
#include "tiles.h"
#include "window.h"

#include <array>
#include <gmpxx.h>
#include "exact_support.h"
#include "test_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <string>
#include <vector>

using tessera::Catchment;
using tessera::InputError;
using tessera::Point2;

namespace
{

const std::string SelfContactHint =
  " (a ring may touch other rings at points, not itself; a ring that touches itself to enclose a "
  "lake, as some ArcGIS files have, is made an outer ring and a hole by GDAL's ogr2ogr -makevalid "
  "or QGIS's Fix Geometries)";

// ---- Exact rational reference ------------------------------------------------------------------

using tessera_test::ErrorOf;
using tessera_test::ExactArea;
using tessera_test::QPoint;
using tessera_test::Rectangle;
using tessera_test::Rings;

QPoint ToExact(const Point2& p)
{
  return { mpq_class(p.x), mpq_class(p.y) };
}

std::vector<QPoint> ToExact(const std::vector<Point2>& points)
{
  std::vector<QPoint> exact;
  for (const Point2& p : points)
  {
    exact.push_back(ToExact(p));
  }
  return exact;
}

mpq_class Cross(const QPoint& a, const QPoint& b, const QPoint& c)
{
  return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
}

// Textbook Sutherland-Hodgman in exact arithmetic, inside = closed left side of each edge.
std::vector<QPoint> ExactClip(std::vector<QPoint> subject, const std::vector<QPoint>& window)
{
  for (std::size_t e = 0; e < window.size() && !subject.empty(); ++e)
  {
    const QPoint& a = window[e];
    const QPoint& b = window[(e + 1) % window.size()];
    std::vector<QPoint> out;
    for (std::size_t i = 0; i < subject.size(); ++i)
    {
      const QPoint& p = subject[(i + subject.size() - 1) % subject.size()];
      const QPoint& q = subject[i];
      const mpq_class dp = Cross(a, b, p);
      const mpq_class dq = Cross(a, b, q);
      const bool pIn = sgn(dp) >= 0;
      const bool qIn = sgn(dq) >= 0;
      if (pIn != qIn)
      {
        const mpq_class t = dp / (dp - dq);
        out.push_back({ p.x + t * (q.x - p.x), p.y + t * (q.y - p.y) });
      }
      if (qIn)
      {
        out.push_back(q);
      }
    }
    subject = std::move(out);
  }
  return subject;
}

// Even-odd membership by the crossing x of each straddling edge, in rationals.
bool ExactInsideRing(const QPoint& p, const std::vector<QPoint>& ring)
{
  bool inside = false;
  for (std::size_t i = 0; i < ring.size(); ++i)
  {
    const QPoint& a = ring[i];
    const QPoint& b = ring[(i + 1) % ring.size()];
    if ((a.y > p.y) != (b.y > p.y))
    {
      const mpq_class x = a.x + (p.y - a.y) * (b.x - a.x) / (b.y - a.y);
      if (p.x < x)
      {
        inside = !inside;
      }
    }
  }
  return inside;
}

bool ExactInsideRegion(const QPoint& p, const Rings& rings)
{
  bool inside = false;
  for (std::size_t r = 0; r < rings.Count(); ++r)
  {
    inside ^= ExactInsideRing(p, ToExact(rings.Ring(r)));
  }
  return inside;
}

bool ExactOnRing(const QPoint& p, const std::vector<QPoint>& ring)
{
  for (std::size_t i = 0; i < ring.size(); ++i)
  {
    const QPoint& a = ring[i];
    const QPoint& b = ring[(i + 1) % ring.size()];
    if (sgn(Cross(a, b, p)) == 0 && std::min(a.x, b.x) <= p.x && p.x <= std::max(a.x, b.x) &&
      std::min(a.y, b.y) <= p.y && p.y <= std::max(a.y, b.y))
    {
      return true;
    }
  }
  return false;
}

// How many other rings enclose ring r, each tested at a point of ring r not on it (rings may touch
// at points, so a given vertex can lie on another ring): its vertices, then its edges' midpoints.
int ExactDepth(const Rings& rings, std::size_t r)
{
  std::vector<QPoint> ring = ToExact(rings.Ring(r));
  for (std::size_t i = 0, n = ring.size(); i < n; ++i)
  {
    const QPoint& a = ring[i];
    const QPoint& b = ring[(i + 1) % n];
    ring.push_back({ (a.x + b.x) / 2, (a.y + b.y) / 2 });
  }
  int depth = 0;
  for (std::size_t s = 0; s < rings.Count(); ++s)
  {
    if (s == r)
    {
      continue;
    }
    const std::vector<QPoint> other = ToExact(rings.Ring(s));
    const auto off = std::find_if(
      ring.begin(), ring.end(), [&](const QPoint& p) { return !ExactOnRing(p, other); });
    EXPECT_NE(off, ring.end()) << "ring " << r << " lies on ring " << s;
    depth += off != ring.end() && ExactInsideRing(*off, other);
  }
  return depth;
}

// Area of (even-odd region of the rings) & tile: each ring made anticlockwise and clipped whole,
// with the sign given by how many other rings enclose it.
mpq_class ExactClippedArea(const Rings& rings, const std::vector<Point2>& tile)
{
  const std::vector<QPoint> window = ToExact(tile);
  mpq_class total = 0;
  for (std::size_t r = 0; r < rings.Count(); ++r)
  {
    std::vector<QPoint> ring = ToExact(rings.Ring(r));
    if (sgn(ExactArea(ring)) < 0)
    {
      std::reverse(ring.begin(), ring.end());
    }
    const int depth = ExactDepth(rings, r);
    const mpq_class piece = ExactArea(ExactClip(ring, window));
    total += depth % 2 == 0 ? piece : mpq_class(-piece);
  }
  return total;
}

// The same for any polygon tile, not only a convex one: the fan of triangles from vertex 0, each
// clipped with its vertices made anticlockwise and counted with its orientation's sign, adds up the
// tile's winding number, so folds and reflex vertices count as the polygon has them.
mpq_class ExactPolygonClippedArea(const Rings& rings, const std::vector<Point2>& tile)
{
  mpq_class total = 0;
  for (std::size_t i = 1; i + 1 < tile.size(); ++i)
  {
    std::vector<Point2> triangle{ tile[0], tile[i], tile[i + 1] };
    const int sign = sgn(Cross(ToExact(tile[0]), ToExact(tile[i]), ToExact(tile[i + 1])));
    if (sign < 0)
    {
      std::swap(triangle[1], triangle[2]);
    }
    if (sign != 0)
    {
      total += sign * ExactClippedArea(rings, triangle);
    }
  }
  return total;
}

mpq_class ExactRegionArea(const Rings& rings)
{
  mpq_class total = 0;
  for (std::size_t r = 0; r < rings.Count(); ++r)
  {
    const std::vector<QPoint> ring = ToExact(rings.Ring(r));
    const int depth = ExactDepth(rings, r);
    const mpq_class area = abs(ExactArea(ring));
    total += depth % 2 == 0 ? area : mpq_class(-area);
  }
  return total;
}

// ---- Shapes ------------------------------------------------------------------------------------

double Overlap1D(double a0, double a1, double b0, double b1)
{
  return std::max(0.0, std::min(a1, b1) - std::max(a0, b0));
}

// Star-shaped about a centre: vertices in angular order, radii in [rMin, rMax], coordinates
// rounded to multiples of `step` (dyadic, so exact in binary).
std::vector<Point2> Star(std::mt19937& random,
  Point2 centre,
  int count,
  double rMin,
  double rMax,
  double step)
{
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<double> angles;
  for (int i = 0; i < count; ++i)
  {
    angles.push_back(2.0 * M_PI * (i + 0.1 + 0.8 * unit(random)) / count);
  }
  std::vector<Point2> star;
  for (double angle : angles)
  {
    const double radius = rMin + (rMax - rMin) * unit(random);
    star.push_back({ centre.x + std::round(radius * std::cos(angle) / step) * step,
      centre.y + std::round(radius * std::sin(angle) / step) * step });
  }
  return star;
}

// Anticlockwise convex hull (monotone chain, exact turns), collinear points dropped.
std::vector<Point2> ConvexHull(std::vector<Point2> points)
{
  std::sort(points.begin(),
    points.end(),
    [](const Point2& a, const Point2& b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
  points.erase(std::unique(points.begin(), points.end()), points.end());
  std::vector<Point2> hull(2 * points.size());
  std::size_t k = 0;
  const auto turnsLeft = [&](const Point2& a, const Point2& b, const Point2& c)
  { return sgn(Cross(ToExact(a), ToExact(b), ToExact(c))) > 0; };
  for (std::size_t i = 0; i < points.size(); ++i)
  {
    while (k >= 2 && !turnsLeft(hull[k - 2], hull[k - 1], points[i]))
    {
      --k;
    }
    hull[k++] = points[i];
  }
  for (std::size_t i = points.size() - 1, lower = k + 1; i-- > 0;)
  {
    while (k >= lower && !turnsLeft(hull[k - 2], hull[k - 1], points[i]))
    {
      --k;
    }
    hull[k++] = points[i];
  }
  hull.resize(k - 1);
  return hull;
}

std::vector<Point2> RandomConvex(std::mt19937& random,
  double x0,
  double x1,
  double y0,
  double y1,
  int count,
  double step)
{
  std::uniform_real_distribution<double> x(x0, x1);
  std::uniform_real_distribution<double> y(y0, y1);
  for (;;)
  {
    std::vector<Point2> points;
    for (int i = 0; i < count; ++i)
    {
      points.push_back(
        { std::round(x(random) / step) * step, std::round(y(random) / step) * step });
    }
    std::vector<Point2> hull = ConvexHull(points);
    if (hull.size() >= 3)
    {
      return hull;
    }
  }
}

// An outer star, a hole in it, an island in the hole, and a second outer star beside it; rings
// in a mixed order and orientation.
Rings NestedStars(std::mt19937& random, double step, double offset)
{
  Rings rings;
  const Point2 c{ offset, offset };
  std::vector<Point2> island = Star(random, c, 9, 3.0, 8.0, step);
  rings.Add(island);
  std::vector<Point2> outer = Star(random, c, 40, 30.0, 50.0, step);
  std::reverse(outer.begin(), outer.end());
  rings.Add(outer);
  rings.Add(Star(random, { offset + 120.0, offset + 10.0 }, 25, 10.0, 60.0, step));
  std::vector<Point2> hole = Star(random, c, 20, 12.0, 25.0, step);
  rings.Add(hole);
  return rings;
}

double Tolerance(const mpq_class& exact, double tileArea)
{
  return 1e-12 * std::max(std::fabs(exact.get_d()), 1e-3 * tileArea);
}

// Checks the returned rings against the region they claim: their signed areas add up to the
// area, and the even-odd rule over them matches exact membership at random points.
void CheckRings(const tessera::ClippedRings& out,
  double area,
  const Rings& catchment,
  const std::vector<Point2>& tile,
  std::mt19937& random)
{
  Rings pieces;
  double signedSum = 0.0;
  for (std::size_t r = 0; r + 1 < out.RingOffsets.size(); ++r)
  {
    pieces.Add({ out.Vertices.begin() + static_cast<std::ptrdiff_t>(out.RingOffsets[r]),
      out.Vertices.begin() + static_cast<std::ptrdiff_t>(out.RingOffsets[r + 1]) });
    signedSum += tessera_test::ShoelaceArea(pieces.Ring(r));
  }
  EXPECT_NEAR(signedSum, area, 1e-9 * std::max(1.0, area));
  double x0 = tile[0].x, x1 = tile[0].x, y0 = tile[0].y, y1 = tile[0].y;
  for (const Point2& p : tile)
  {
    x0 = std::min(x0, p.x);
    x1 = std::max(x1, p.x);
    y0 = std::min(y0, p.y);
    y1 = std::max(y1, p.y);
  }
  std::uniform_real_distribution<double> x(x0, x1);
  std::uniform_real_distribution<double> y(y0, y1);
  const std::vector<QPoint> window = ToExact(tile);
  for (int i = 0; i < 50; ++i)
  {
    const QPoint p = ToExact(Point2{ x(random), y(random) });
    bool inTile = true;
    for (std::size_t e = 0; e < window.size(); ++e)
    {
      inTile = inTile && sgn(Cross(window[e], window[(e + 1) % window.size()], p)) > 0;
    }
    const bool expected = inTile && ExactInsideRegion(p, catchment);
    EXPECT_EQ(ExactInsideRegion(p, pieces), expected)
      << "at (" << p.x.get_d() << ", " << p.y.get_d() << ")";
  }
}

} // namespace

// ---- Known pieces
// --------------------------------------------------------------------------------

TEST(Clip, SquareCatchmentGivesRectangleOverlaps)
{
  Rings square;
  square.Add(Rectangle(0, 0, 4, 4));
  const Catchment catchment(square.Offsets, square.Vertices);
  EXPECT_EQ(catchment.Area(), 16.0);
  std::mt19937 random(1);
  std::uniform_int_distribution<int> coordinate(-3, 7);
  for (int i = 0; i < 300; ++i)
  {
    int x0 = coordinate(random), x1 = coordinate(random), y0 = coordinate(random),
        y1 = coordinate(random);
    if (x0 == x1 || y0 == y1)
    {
      continue;
    }
    const std::vector<Point2> tile =
      Rectangle(std::min(x0, x1), std::min(y0, y1), std::max(x0, x1), std::max(y0, y1));
    const double expected = Overlap1D(std::min(x0, x1), std::max(x0, x1), 0, 4) *
      Overlap1D(std::min(y0, y1), std::max(y0, y1), 0, 4);
    const tessera::ClippedTile clipped = catchment.Clip(tile);
    EXPECT_EQ(clipped.Area, expected) << "tile " << x0 << " " << x1 << " " << y0 << " " << y1;
    EXPECT_EQ(catchment.ClipArea(tile), clipped.Area);
    CheckRings(clipped.Rings, clipped.Area, square, tile, random);
  }
}

TEST(Clip, HoleWithIslandFollowsEvenOdd)
{
  // Island first, hole clockwise, outer anticlockwise: order and orientation must not matter.
  Rings rings;
  rings.Add(Rectangle(4, 4, 6, 6));
  std::vector<Point2> hole = Rectangle(2, 2, 8, 8);
  std::reverse(hole.begin(), hole.end());
  rings.Add(hole);
  rings.Add(Rectangle(0, 0, 10, 10));
  const Catchment catchment(rings.Offsets, rings.Vertices);
  EXPECT_EQ(catchment.Area(), 100.0 - 36.0 + 4.0);
  EXPECT_EQ(catchment.RingDepths(), (std::vector<int>{ 2, 1, 0 }));
  EXPECT_TRUE(catchment.Contains({ 1, 1 }));
  EXPECT_FALSE(catchment.Contains({ 3, 3 }));
  EXPECT_TRUE(catchment.Contains({ 5, 5 }));
  EXPECT_FALSE(catchment.Contains({ 11, 5 }));
  std::mt19937 random(2);
  std::uniform_real_distribution<double> coordinate(-2.0, 12.0);
  for (int i = 0; i < 300; ++i)
  {
    const double ax = std::round(4 * coordinate(random)) / 4,
                 bx = std::round(4 * coordinate(random)) / 4;
    const double ay = std::round(4 * coordinate(random)) / 4,
                 by = std::round(4 * coordinate(random)) / 4;
    if (ax == bx || ay == by)
    {
      continue;
    }
    const double x0 = std::min(ax, bx), x1 = std::max(ax, bx), y0 = std::min(ay, by),
                 y1 = std::max(ay, by);
    const double expected = Overlap1D(x0, x1, 0, 10) * Overlap1D(y0, y1, 0, 10) -
      Overlap1D(x0, x1, 2, 8) * Overlap1D(y0, y1, 2, 8) +
      Overlap1D(x0, x1, 4, 6) * Overlap1D(y0, y1, 4, 6);
    const std::vector<Point2> tile = Rectangle(x0, y0, x1, y1);
    const tessera::ClippedTile clipped = catchment.Clip(tile);
    EXPECT_EQ(clipped.Area, expected) << x0 << " " << x1 << " " << y0 << " " << y1;
    CheckRings(clipped.Rings, clipped.Area, rings, tile, random);
  }
}

TEST(Clip, TilesInsideOutsideAndStraddling)
{
  std::mt19937 random(3);
  Rings rings;
  rings.Add(Star(random, { 0, 0 }, 400, 80.0, 100.0, 1.0 / 64));
  const Catchment catchment(rings.Offsets, rings.Vertices);
  const std::vector<Point2> inside = RandomConvex(random, -30, 30, -30, 30, 12, 1.0 / 8);
  const std::vector<Point2> outside = RandomConvex(random, 150, 200, -30, 30, 12, 1.0 / 8);
  const std::vector<Point2> around = RandomConvex(random, 70, 110, -20, 20, 12, 1.0 / 8);
  const std::vector<Point2> covering = Rectangle(-200, -200, 200, 200);

  const tessera::ClippedTile in = catchment.Clip(inside);
  EXPECT_EQ(in.Area, tessera_test::ShoelaceArea(inside));
  ASSERT_EQ(in.Rings.RingOffsets.size(), 2u);
  EXPECT_EQ(in.Rings.Vertices, inside);

  const tessera::ClippedTile out = catchment.Clip(outside);
  EXPECT_EQ(out.Area, 0.0);
  EXPECT_EQ(out.Rings.Vertices.size(), 0u);

  for (const auto& tile : { around, covering })
  {
    const tessera::ClippedTile clipped = catchment.Clip(tile);
    const mpq_class exact = ExactClippedArea(rings, tile);
    EXPECT_GT(exact, 0);
    EXPECT_NEAR(clipped.Area, exact.get_d(), Tolerance(exact, tessera_test::ShoelaceArea(tile)));
    CheckRings(clipped.Rings, clipped.Area, rings, tile, random);
  }
  EXPECT_NEAR(catchment.ClipArea(covering), catchment.Area(), 1e-12 * catchment.Area());
}

// ---- Against the exact reference ---------------------------------------------------------------

void CompareRandomTiles(const Rings& rings, double offset, unsigned seed, int tiles)
{
  const Catchment catchment(rings.Offsets, rings.Vertices);
  const mpq_class exactArea = ExactRegionArea(rings);
  EXPECT_NEAR(catchment.Area(), exactArea.get_d(), 1e-14 * exactArea.get_d());
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> size(1.0, 60.0);
  int partial = 0;
  for (int i = 0; i < tiles; ++i)
  {
    std::uniform_real_distribution<double> corner(offset - 80.0, offset + 180.0);
    const double x = corner(random), y = corner(random) - 50.0, s = size(random);
    const std::vector<Point2> tile = RandomConvex(random, x, x + s, y, y + s, 8, 1.0 / 16);
    const mpq_class exact = ExactClippedArea(rings, tile);
    const double tileArea = tessera_test::ShoelaceArea(tile);
    const tessera::ClippedTile clipped = catchment.Clip(tile);
    EXPECT_NEAR(clipped.Area, exact.get_d(), Tolerance(exact, tileArea)) << "tile " << i;
    partial += exact > 0 && exact.get_d() < tileArea;
    if (i % 10 == 0)
    {
      CheckRings(clipped.Rings, clipped.Area, rings, tile, random);
    }
  }
  EXPECT_GT(partial, tiles / 10); // the comparison must exercise real clipping
}

/// The exact area of tile & rings, once the catchment's ClipArea of tile i is checked against it.
mpq_class ExpectExactArea(const Catchment& catchment,
  const Rings& rings,
  const std::vector<Point2>& tile,
  double tileArea,
  int i)
{
  const mpq_class exact = ExactClippedArea(rings, tile);
  EXPECT_NEAR(catchment.ClipArea(tile), exact.get_d(), Tolerance(exact, tileArea)) << "tile " << i;
  return exact;
}

TEST(Clip, RandomConvexTilesMatchExactRationalClipping)
{
  for (unsigned seed = 10; seed < 16; ++seed)
  {
    std::mt19937 random(seed);
    CompareRandomTiles(NestedStars(random, 1.0, 0.0), 0.0, seed, 150);
  }
}

// Detailed outlines: a tile then has thousands of candidate segments, sorted by a radix sort from
// 1024 on (SortSegmentIds). Star rings of 6000 and 3000 vertices (a hole in the first), tiles of
// up to half their width.
TEST(Clip, TilesOnDetailedOutlinesMatchExactRationalClipping)
{
  std::mt19937 random(21);
  Rings rings;
  rings.Add(Star(random, { 0.0, 0.0 }, 6000, 60.0, 100.0, 1.0 / 64));
  rings.Add(Star(random, { 0.0, 0.0 }, 3000, 20.0, 40.0, 1.0 / 64));
  const Catchment catchment(rings.Offsets, rings.Vertices);
  std::uniform_real_distribution<double> corner(-110.0, 30.0), size(40.0, 100.0);
  int partial = 0;
  for (int i = 0; i < 12; ++i)
  {
    const double x = corner(random), y = corner(random), side = size(random);
    const std::vector<Point2> tile = RandomConvex(random, x, x + side, y, y + side, 8, 1.0 / 16);
    const double tileArea = tessera_test::ShoelaceArea(tile);
    const mpq_class exact = ExpectExactArea(catchment, rings, tile, tileArea, i);
    partial += exact > 0 && exact.get_d() < tileArea;
  }
  EXPECT_GT(partial, 6);
}

/// Counts the tiles whose areas alone the crossings measured, each checked against the exact.
struct CrossingsCheck
{
  explicit CrossingsCheck(const Rings& checked)
    : rings(checked)
  {
  }
  const Rings& rings;
  const Catchment catchment{ rings.Offsets, rings.Vertices };
  Catchment::Workspace work;
  int tiles = 0;
  /// Whether the tile lies partly in the catchment, once its area is checked.
  bool Expect(const std::vector<Point2>& tile)
  {
    const mpq_class exact = ExactClippedArea(rings, tile);
    const double tileArea = tessera_test::ShoelaceArea(tile);
    EXPECT_NEAR(catchment.ClipInto(tile.data(), tile.size(), 0, work, nullptr),
      exact.get_d(),
      Tolerance(exact, tileArea))
      << "tile " << tiles;
    ++tiles;
    return exact > 0 && exact.get_d() < tileArea;
  }
};

// Areas alone (no rings asked for) come from where the catchment's boundary crosses the tile's,
// with prefix sums along the rings (AreaByCrossings), where the tile's box spans enough grid
// cells; where a catchment vertex lies on a tile's boundary, or a segment passes through a tile
// vertex, the clipping measures the tile instead. Both must match the exact rational clipping:
// random tiles across a detailed outer ring, its hole and an island in the hole; tiles holding the
// island whole; and tiles whose edges run through catchment vertices.
TEST(Clip, AreasFromCrossingsMatchExactRationalClipping)
{
  std::mt19937 random(41);
  Rings rings;
  const Point2 c{ 0.0, 0.0 };
  rings.Add(Star(random, c, 1500, 60.0, 100.0, 1.0 / 64));
  rings.Add(Star(random, c, 750, 20.0, 40.0, 1.0 / 64));
  const std::vector<Point2> island = Star(random, c, 40, 3.0, 8.0, 1.0 / 64);
  rings.Add(island);
  CrossingsCheck check(rings);
  const Catchment& catchment = check.catchment;
  Catchment::Workspace& work = check.work;
  std::uniform_real_distribution<double> corner(-120.0, 60.0), size(5.0, 80.0);
  int partial = 0;
  for (int i = 0; i < 120; ++i)
  {
    const double x = corner(random), y = corner(random), side = size(random);
    partial += check.Expect(RandomConvex(random, x, x + side, y, y + side, 8, 1.0 / 16));
  }
  EXPECT_GT(partial, 36);
  EXPECT_GT(work.AreasByCrossings, 60u); // the crossings measured over half of them

  // Tiles inside the hole holding the island whole: its area, from its ring's sums.
  const std::size_t before = work.AreasByCrossings;
  for (int i = 0; i < 10; ++i)
  {
    const double half = 12.0 + 0.2 * i;
    const std::vector<Point2> square{
      { -half, -half }, { half, -half }, { half, half }, { -half, half }
    };
    EXPECT_DOUBLE_EQ(
      catchment.ClipInto(square.data(), 4, 0, work, nullptr), tessera_test::ShoelaceArea(island));
    check.Expect(square);
  }
  EXPECT_EQ(work.AreasByCrossings, before + 20);

  // Triangles whose first edge runs between two vertices of the outer ring (moved by off).
  const auto triangle = [&](int i, double off)
  {
    const Point2 p = rings.Vertices[static_cast<std::size_t>(37 * i)];
    const Point2 q = rings.Vertices[static_cast<std::size_t>(37 * i + 150)];
    const Point2 apex{ 0.5 * (p.x + q.x) - 0.5 * (q.y - p.y),
      0.5 * (p.y + q.y) + 0.5 * (q.x - p.x) };
    return std::vector<Point2>{
      { p.x + off, p.y + off }, { q.x + off, q.y + off }, { apex.x + off, apex.y + off }
    };
  };
  // Through the vertices: the clipping's.
  const std::size_t crossed = work.AreasByCrossings;
  for (int i = 0; i < 20; ++i)
  {
    check.Expect(triangle(i, 0.0));
  }
  EXPECT_EQ(work.AreasByCrossings, crossed);
  // Moved off the vertices, by a 1/3 that no dyadic coordinate has: measured by the crossings (the
  // clipping took the ones above for their vertices, not their size).
  for (int i = 0; i < 20; ++i)
  {
    check.Expect(triangle(i, 1.0 / 3.0));
  }
  EXPECT_GT(work.AreasByCrossings, crossed + 15);
}

// A polygon's edges cut into n equal parts each (dyadic for the shapes below).
std::vector<Point2> Subdivided(const std::vector<Point2>& polygon, int n)
{
  std::vector<Point2> out;
  for (std::size_t i = 0; i < polygon.size(); ++i)
  {
    const Point2 a = polygon[i], b = polygon[(i + 1) % polygon.size()];
    for (int k = 0; k < n; ++k)
    {
      out.push_back({ a.x + (b.x - a.x) * k / n, a.y + (b.y - a.y) * k / n });
    }
  }
  return out;
}

// Where rings meet, two rings' segments cross a tile's edge at one point, in opposite directions:
// two parts sharing a side, a lake on the outline, a hole touching the outer ring at a vertex, a
// third part on top of the first. Random tiles, and triangles across the shared side, the touching
// vertex and the lake's shore.
TEST(Clip, AreasFromCrossingsMatchExactWhereRingsMeet)
{
  Rings rings;
  rings.Add(Subdivided(Rectangle(0, 0, 64, 64), 64));
  rings.Add(Subdivided(Rectangle(64, 0, 128, 64), 64));
  rings.Add(Subdivided(Rectangle(16, 0, 48, 32), 32));
  rings.Add(Subdivided({ { 96, 32 }, { 112, 48 }, { 96, 64 }, { 80, 48 } }, 16));
  rings.Add(Subdivided({ { 0, 64 }, { 64, 64 }, { 32, 96 } }, 32));
  CrossingsCheck check{ rings };
  std::mt19937 random(11);
  std::uniform_real_distribution<double> corner(-20.0, 120.0), size(5.0, 60.0);
  for (int i = 0; i < 120; ++i)
  {
    const double x = corner(random), y = corner(random), side = size(random);
    check.Expect(RandomConvex(random, x, x + side, y, y + side, 6, i % 2 ? 1.0 / 4 : 1.0 / 1024));
  }
  EXPECT_GT(check.work.AreasByCrossings, 30u);
  const std::size_t byRandomTiles = check.work.AreasByCrossings;
  for (int i = 0; i < 20; ++i)
  {
    const double t = 1.0 + i * 0.37;
    check.Expect({ { 64 - t, 10 }, { 64 + 2 * t, 12 }, { 64.5, 70 } });
    check.Expect({ { 90 - t, 40 }, { 100 + t, 41 }, { 96.125, 80 } });
    check.Expect({ { 10 - t, -5 }, { 50 + t, -4 }, { 30.0625, 20 + t } });
  }
  EXPECT_GT(check.work.AreasByCrossings, byRandomTiles + 40); // (of 60 across shared boundaries)
}

// Up to 64 rings (an outer ring and holes) the crossings measure areas alone, with rings inside a
// tile added whole; beyond, and for tiles whose sums would be too coarse for their size
// (coordinates near 2^30 against tiles 40 to 90 wide, where only those above some 64 wide take
// the crossings), the clipping measures them. Either way they match the exact areas, at offsets
// of 0, 10^7 and 2^30.
TEST(Clip, AreasFromCrossingsMatchExactWithManyRingsAndAtOffsets)
{
  for (const int holes : { 63, 64 })
  {
    std::mt19937 random(13);
    Rings rings;
    rings.Add(Star(random, { 0, 0 }, 500, 80.0, 100.0, 1.0 / 64));
    for (int k = 0; k < holes; ++k)
    {
      rings.Add(
        Star(random, { -50 + 12.5 * (k % 8), -50 + 12.5 * (k / 8) }, 12, 2.0, 5.0, 1.0 / 64));
    }
    CrossingsCheck check{ rings };
    std::uniform_real_distribution<double> corner(-80.0, 40.0), size(30.0, 70.0);
    for (int i = 0; i < 25; ++i)
    {
      const double x = corner(random), y = corner(random), side = size(random);
      check.Expect(RandomConvex(random, x, x + side, y, y + side, 8, 1.0 / 1024));
    }
    EXPECT_EQ(check.work.AreasByCrossings > 15, holes == 63) << holes << " holes";
  }
  for (const double offset : { 0.0, 1e7, 1073741824.0 })
  {
    std::mt19937 random(41);
    Rings rings;
    rings.Add(Star(random, { offset, offset }, 600, 60.0, 100.0, 1.0 / 64));
    rings.Add(Star(random, { offset, offset }, 300, 20.0, 40.0, 1.0 / 64));
    CrossingsCheck check{ rings };
    std::uniform_real_distribution<double> corner(offset - 120.0, offset + 60.0), size(40.0, 90.0);
    for (int i = 0; i < 40; ++i)
    {
      const double x = corner(random), y = corner(random), side = size(random);
      check.Expect(RandomConvex(random, x, x + side, y, y + side, 8, 1.0 / 1024));
    }
    EXPECT_EQ(check.work.AreasByCrossings > 20, offset < 1e9) << "offset " << offset;
  }
}

// A catchment of few long slanted edges has a coarse grid (3 x 3 cells here), so a small tile's
// cells list segments that pass it by: those whose boxes miss the tile's, and those whose boxes
// meet it while their lines leave all four corners on one side. Such a tile takes the path of an
// empty cell; tiles across an edge, and those just clear of one, must match the exact clipping.
TEST(Clip, SmallTilesBesideLongSlantedEdgesMatchExactClipping)
{
  std::mt19937 random(31);
  const std::vector<Point2> triangle{ { 0.0, 0.0 }, { 100.0, 3.0 }, { 40.0, 90.0 } };
  const std::vector<Point2> hole{ { 30.0, 20.0 }, { 45.0, 50.0 }, { 60.0, 22.0 } };
  const Rings rings({ triangle, hole });
  const Catchment catchment(rings.Offsets, rings.Vertices);
  std::uniform_real_distribution<double> along(0.0, 1.0), offset(-4.0, 4.0), size(0.25, 3.0);
  int partial = 0, inside = 0, outside = 0;
  for (int i = 0; i < 600; ++i)
  {
    const std::vector<Point2>& ring = i % 3 == 0 ? hole : triangle;
    const std::size_t e = static_cast<std::size_t>(i / 3) % ring.size();
    const Point2& a = ring[e];
    const Point2& b = ring[(e + 1) % ring.size()];
    const double t = along(random), s = size(random);
    const double x = a.x + t * (b.x - a.x) + offset(random);
    const double y = a.y + t * (b.y - a.y) + offset(random);
    const std::vector<Point2> tile = RandomConvex(random, x, x + s, y, y + s, 6, 1.0 / 64);
    const double tileArea = tessera_test::ShoelaceArea(tile);
    const mpq_class exact = ExpectExactArea(catchment, rings, tile, tileArea, i);
    partial += exact > 0 && exact.get_d() < tileArea;
    inside += exact.get_d() == tileArea;
    outside += exact == 0;
  }
  // Each kind must be well represented for the comparison to mean something.
  EXPECT_GT(partial, 60);
  EXPECT_GT(inside, 100);
  EXPECT_GT(outside, 100);
}

// A sliver (a triangle 1e-13 high, some ulps at 50) is as thin as the clipping's rounding: it has
// no area to clip wherever it lies, whether a catchment segment's cell holds it or not (in an
// empty cell its area was kept).
// A tile that holds the whole catchment gives the catchment, its area and rings, however much
// larger it is: clipped relative to its first vertex, a unit catchment in a tile of 1e14 measured
// less than the rounding bound of that shift and was dropped as empty. A tile that large holding
// part of the catchment may still measure nothing (the shift's rounding is larger than the part),
// and HoldsPartOf then says that it holds some (a catchment vertex strictly inside it, or a
// segment through it), so that it is reported, not lost; tiles beside the catchment do not.
TEST(Clip, HugeTilesHoldingTheCatchmentGiveItOrAreReported)
{
  Rings rings;
  rings.Add(Rectangle(0, 0, 1, 1));
  rings.Add(Rectangle(0.25, 0.25, 0.5, 0.75)); // a hole
  const Catchment catchment(rings.Offsets, rings.Vertices);
  for (const double s : { 1e3, 1e10, 1e14, 1e15, 1e16, 1e100 })
  {
    const std::vector<Point2> holding{ { -s, -s }, { s, -s }, { 0.5, s } };
    const tessera::ClippedTile clipped = catchment.Clip(holding);
    EXPECT_EQ(mpq_class(clipped.Area), ExactClippedArea(rings, holding)) << s;
    EXPECT_EQ(clipped.Area, 0.875) << s;
    EXPECT_EQ(clipped.Rings.RingOffsets, catchment.RingOffsets()) << s;
    EXPECT_EQ(clipped.Rings.Vertices, catchment.Vertices()) << s;

    // A tile over the left of the catchment (holding some of its vertices), and a strip through
    // its middle (holding none: only segments cross it).
    const std::vector<Point2> leftHalf{ { -s, -s }, { 0.75, -s }, { 0.75, s } };
    const std::vector<Point2> strip{ { 0.4, -s }, { 0.6, -s }, { 0.5, s } };
    for (const auto& part : { leftHalf, strip })
    {
      const double area = catchment.ClipArea(part);
      const mpq_class exact = ExactClippedArea(rings, part);
      ASSERT_GT(exact, 0) << s;
      if (area == 0.0)
      {
        EXPECT_TRUE(catchment.HoldsPartOf(part.data(), part.size())) << s;
      }
      else
      {
        // The clip's rounding: ulps of the tile's size (RoundingAreaBound) over a perimeter of 4.
        EXPECT_NEAR(area, exact.get_d(), 128 * std::numeric_limits<double>::epsilon() * s) << s;
      }
    }
    const std::vector<Point2> beside{ { -s, -s }, { -0.5, -s }, { -0.5, s } };
    EXPECT_EQ(catchment.ClipArea(beside), 0.0) << s;
    EXPECT_FALSE(catchment.HoldsPartOf(beside.data(), beside.size())) << s;
  }
}

TEST(Clip, SliverTilesHaveNoAreaWhateverTheirCell)
{
  const Rings rings({ { { 0.0, 0.0 }, { 100.0, 0.0 }, { 100.0, 100.0 }, { 0.0, 100.0 } } });
  const Catchment catchment(rings.Offsets, rings.Vertices);
  // The square's grid is 3 x 3, its middle cell empty: slivers across the cells of the edges,
  // beside an edge, and in the empty cell.
  for (const auto& [x0, x1, y] : { std::array<double, 3>{ 10.0, 90.0, 1.0 },
         std::array<double, 3>{ 10.0, 90.0, 50.0 },
         std::array<double, 3>{ 40.0, 60.0, 50.0 } })
  {
    const std::vector<Point2> sliver{ { x0, y }, { x1, y }, { x1, y + 1e-13 } };
    ASSERT_GT(tessera_test::ShoelaceArea(sliver), 0.0);
    EXPECT_EQ(catchment.ClipArea(sliver), 0.0) << "from x = " << x0 << " at y = " << y;
  }
  const std::vector<Point2> thin{ { 10.0, 50.0 }, { 90.0, 50.0 }, { 90.0, 50.0 + 1e-9 } };
  const double height = (50.0 + 1e-9) - 50.0; // exact: 1e-9 as rounded at 50
  EXPECT_NEAR(catchment.ClipArea(thin), 40.0 * height, 1e-22)
    << "a thin tile above rounding keeps its area";
}

TEST(Clip, DyadicCoordinatesAwayFromOriginMatchExactClipping)
{
  for (unsigned seed = 20; seed < 24; ++seed)
  {
    std::mt19937 random(seed);
    CompareRandomTiles(NestedStars(random, 1.0 / 64, 1024.0), 1024.0, seed, 150);
  }
}

TEST(Clip, AreasFarFromTheOriginAreExact)
{
  // Tiles inside the catchment (measured whole, not clipped) and the catchment itself, at 2^30
  // and 2^40 plus a non-dyadic fraction: the shoelace's terms are some 2^80 there, and without the
  // shift to the first vertex a unit tile's area came out 2.6e-8 off.
  std::mt19937 random(5);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (const int exponent : { 30, 40 })
  {
    const double at = std::ldexp(1.0, exponent) + 0.123456789;
    Rings rings;
    rings.Add({ { at - 100, at - 90 },
      { at + 110, at - 100 },
      { at + 95, at + 105 },
      { at - 90, at + 100 } });
    const Catchment catchment(rings.Offsets, rings.Vertices);
    std::vector<QPoint> exactRing;
    for (const Point2& p : rings.Vertices)
    {
      exactRing.push_back({ p.x, p.y });
    }
    const double catchmentArea = ExactArea(exactRing).get_d();
    EXPECT_LE(std::abs(catchment.Area() - catchmentArea), 1e-15 * catchmentArea) << exponent;
    for (int k = 0; k < 200; ++k)
    {
      const double cx = at + u(random), cy = at + u(random);
      std::vector<Point2> tile;
      std::vector<QPoint> exactTile;
      for (int j = 0; j < 6; ++j)
      {
        const double angle = 2.0 * M_PI * j / 6 + 0.1 * u(random);
        tile.push_back({ cx + std::cos(angle), cy + std::sin(angle) });
        exactTile.push_back({ tile.back().x, tile.back().y });
      }
      const double exact = ExactArea(exactTile).get_d();
      ASSERT_LE(std::abs(catchment.ClipArea(tile) - exact), 1e-15 * exact)
        << "2^" << exponent << " tile " << k;
    }
  }
}

TEST(Clip, SliverTilesWhoseBoxIsAnUlpWideMatchExactClipping)
{
  // A fuzzer's case: coordinates near 2^39, a tile whose box is one ulp wide in x, so that the
  // box's computed centre lies on its side. The winding counted there once added the whole tile.
  // The same case shifted by dyadic offsets (exact) must agree with the exact area too.
  const std::vector<Point2> ring{ { 549755813892.0, -412316860426.0 },
    { 549755813889.0, -412316860425.0 },
    { 549755813884.0, -412316860420.0 },
    { 549755813881.0, -412316860412.0 },
    { 549755813881.0, -412316860411.5 },
    { 549755813896.0, -412316860415.0 },
    { 549755813898.0, -412316860416.0 } };
  const std::vector<Point2> tile{ { 549755813889.9999, -412316860426.0 },
    { 549755813890.0, -412316860426.00006 },
    { 549755813890.0, -412316860425.99994 } };
  for (const double shift : { 0.0, 3.0, -1024.0, 0.5 })
  {
    Rings rings;
    std::vector<Point2> shifted = ring;
    for (Point2& p : shifted)
    {
      p.x += shift;
    }
    rings.Add(shifted);
    std::vector<Point2> t = tile;
    for (Point2& p : t)
    {
      p.x += shift;
    }
    const Catchment catchment(rings.Offsets, rings.Vertices);
    EXPECT_EQ(catchment.ClipArea(t), ExactClippedArea(rings, t).get_d()) << "shift " << shift;
  }
}

TEST(Clip, FoldedTilesAreErrorsOrEmptyAsAsked)
{
  // A tile given by a user with clockwise vertices, or fewer than 3, is an error naming it; a
  // tessellation's tile that came out folded or collapsed (thinner than its vertices' rounding)
  // counts as empty when the caller says so (FoldedTile::IsEmpty), and a sound tile is clipped
  // the same either way.
  Rings rings;
  rings.Add({ { 0, 0 }, { 4, 0 }, { 4, 4 }, { 0, 4 } });
  const Catchment catchment(rings.Offsets, rings.Vertices);
  Catchment::Workspace work;
  const std::vector<Point2> clockwise{ { 1, 1 }, { 1, 2 }, { 2, 2 }, { 2, 1 } };
  const std::vector<Point2> two{ { 1, 1 }, { 2, 2 } };
  const std::vector<Point2> sound{ { 3, 3 }, { 5, 3 }, { 5, 5 }, { 3, 5 } };
  EXPECT_THROW(catchment.ClipInto(clockwise.data(), 4, 7, work, nullptr), InputError);
  EXPECT_THROW(catchment.ClipInto(two.data(), 2, 7, work, nullptr), InputError);
  const auto empty = Catchment::FoldedTile::IsEmpty;
  EXPECT_EQ(catchment.ClipInto(clockwise.data(), 4, 7, work, nullptr, empty), 0.0);
  EXPECT_EQ(catchment.ClipInto(two.data(), 2, 7, work, nullptr, empty), 0.0);
  EXPECT_EQ(catchment.ClipInto(sound.data(), 4, 7, work, nullptr, empty), 1.0);
  EXPECT_EQ(catchment.ClipInto(sound.data(), 4, 7, work, nullptr), 1.0);
}

// Random convex quad w (anticlockwise) with sloped edges, at one of several scales and offsets.
double SlopedQuadScale(int w)
{
  return std::pow(10.0, static_cast<double>(w % 4) * 2.0 - 2.0);
}

double SlopedQuadOffset(int w)
{
  return (w % 3) * 1000.0 * SlopedQuadScale(w) + 0.3;
}

std::vector<Point2> SlopedQuad(int w,
  std::mt19937& random,
  std::uniform_real_distribution<double>& u)
{
  const double scale = SlopedQuadScale(w), offset = SlopedQuadOffset(w);
  std::vector<Point2> quad(4);
  for (int k = 0; k < 4; ++k)
  {
    const double angle = 2.0 * M_PI * (k + 0.15 + 0.7 * u(random)) / 4.0;
    const double radius = scale * (0.6 + 0.4 * u(random));
    quad[static_cast<std::size_t>(k)] = { offset + radius * std::cos(angle),
      offset + radius * std::sin(angle) };
  }
  return ConvexHull(quad);
}

// 600 random triangles near the edges of the anticlockwise convex ring (sizes from a tenth of
// `size` down to 1e-5 of it), each just outside an edge or straddling it (inside false), or just
// inside or straddling (inside true). Those strictly outside the ring (every vertex strictly
// right of one edge) or strictly inside it (strictly left of every edge), decided exactly by
// orient2d, must clip to nothing: no area, no ring. Returns (triangles checked, failures).
std::pair<int, int> ExpectStrictTrianglesClipToNothing(const Catchment& catchment,
  const std::vector<Point2>& ring,
  double size,
  bool inside,
  std::mt19937& random,
  std::uniform_real_distribution<double>& u,
  const std::string& what)
{
  const std::size_t n = ring.size();
  const double side = inside ? -1.0 : 1.0; // +1: towards the right of an edge (outside)
  int checked = 0, failed = 0;
  for (int t = 0; t < 600; ++t)
  {
    const std::size_t e = static_cast<std::size_t>(t) % n;
    const Point2& a = ring[e];
    const Point2& b = ring[(e + 1) % n];
    const double along = u(random), s = size * std::pow(10.0, -1.0 - 4.0 * u(random));
    const double ex = b.x - a.x, ey = b.y - a.y, length = std::hypot(ex, ey);
    const Point2 near{ a.x + along * ex + side * (ey / length * s * u(random)),
      a.y + along * ey - side * (ex / length * s * u(random)) };
    std::vector<Point2> tile;
    for (int k = 0; k < 3; ++k)
    {
      const double angle = 2.0 * M_PI * (k + u(random)) / 3.0;
      tile.push_back({ near.x + s * std::cos(angle), near.y + s * std::sin(angle) });
    }
    const int turn = tessera::orient2d(tile[0], tile[1], tile[2]);
    if (turn == 0)
    {
      continue;
    }
    if (turn < 0)
    {
      std::swap(tile[1], tile[2]);
    }
    // Per edge: every vertex strictly on the side looked at (right of it outside, left inside).
    bool beyondOne = false, beyondAll = true;
    for (std::size_t f = 0; f < n; ++f)
    {
      const bool beyond = std::all_of(tile.begin(),
        tile.end(),
        [&](const Point2& p)
        { return side * tessera::orient2d(ring[f], ring[(f + 1) % n], p) < 0; });
      beyondOne = beyondOne || beyond;
      beyondAll = beyondAll && beyond;
    }
    if (!(inside ? beyondAll : beyondOne))
    {
      continue;
    }
    ++checked;
    const tessera::ClippedTile clipped = catchment.Clip(tile);
    if (clipped.Area != 0.0 || !clipped.Rings.Vertices.empty())
    {
      ++failed;
      ADD_FAILURE() << what << " tile " << t << ": area " << clipped.Area << ", "
                    << clipped.Rings.RingOffsets.size() - 1 << " ring(s)";
    }
  }
  return { checked, failed };
}

// Tiles strictly outside a convex window with sloped edges: every vertex strictly outside one
// window edge, decided exactly by orient2d. The rounding of the window's vertices shifted to the
// tile's first vertex used to leave a degenerate ring with a residue area (1.2e-19 for the first
// case below, a ring a, c, a) instead of nothing.
TEST(Clip, TilesStrictlyOutsideASlopedWindowGiveNothing)
{
  const std::vector<Point2> reported{ { 0.4086610372306775, 0.8808966471121111 },
    { 0.32179489723071797, 0.907743781081812 },
    { 0.32449995774984586, 0.8634977563300995 } };
  const std::vector<Point2> quad{ { 0.1, 0.1 }, { 0.9, 0.15 }, { 0.85, 0.9 }, { 0.15, 0.8 } };
  {
    Rings rings;
    rings.Add(quad);
    const tessera::ClippedTile clipped = Catchment(rings.Offsets, rings.Vertices).Clip(reported);
    EXPECT_EQ(clipped.Area, 0.0);
    EXPECT_TRUE(clipped.Rings.Vertices.empty()) << clipped.Rings.Vertices.size() << " vertices";
  }
  std::mt19937 random(41);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  int outside = 0, failed = 0;
  // The quad as given, and random convex quads with sloped edges at several offsets and scales.
  for (int w = 0; w < 24; ++w)
  {
    const std::vector<Point2> window = w == 0 ? quad : SlopedQuad(w, random, u);
    Rings rings;
    rings.Add(window);
    const Catchment catchment(rings.Offsets, rings.Vertices);
    const double size = std::max(catchment.Bounds().XMax - catchment.Bounds().XMin,
      catchment.Bounds().YMax - catchment.Bounds().YMin);
    const auto [checked, failures] = ExpectStrictTrianglesClipToNothing(
      catchment, window, size, false, random, u, "window " + std::to_string(w));
    outside += checked;
    failed += failures;
  }
  EXPECT_GT(outside, 2500); // the check must see many tiles
  EXPECT_EQ(failed, 0) << "of " << outside << " tiles strictly outside";
}

// Tiles strictly inside a convex hole with sloped edges (every vertex strictly inside, exactly by
// orient2d): the outer ring gives the tile, the hole's ring clipped to it gives it back reversed,
// and the two areas, computed apart, used to leave a residue (1.2e-19) with the two rings.
TEST(Clip, TilesStrictlyInsideAHoleGiveNothing)
{
  std::mt19937 random(43);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  int inside = 0, failed = 0;
  for (int w = 0; w < 24; ++w)
  {
    const double scale = SlopedQuadScale(w), offset = SlopedQuadOffset(w);
    const std::vector<Point2> hole = SlopedQuad(w, random, u);
    Rings rings;
    rings.Add(
      Rectangle(offset - 3 * scale, offset - 3 * scale, offset + 3 * scale, offset + 3 * scale));
    rings.Add(hole);
    const Catchment catchment(rings.Offsets, rings.Vertices);
    const auto [checked, failures] = ExpectStrictTrianglesClipToNothing(
      catchment, hole, scale, true, random, u, "hole " + std::to_string(w));
    inside += checked;
    failed += failures;
  }
  EXPECT_GT(inside, 2500); // the check must see many tiles
  EXPECT_EQ(failed, 0) << "of " << inside << " tiles strictly inside the hole";
}

// ---- Tilings -----------------------------------------------------------------------------------

// A jittered grid over (and beyond) the catchment's box, each quad split into two triangles.
void TilingOf(const tessera::Box2& box,
  int cells,
  std::mt19937& random,
  std::vector<std::size_t>& offsets,
  std::vector<Point2>& vertices)
{
  const double x0 = box.XMin - 7.3, y0 = box.YMin - 5.1;
  const double dx = (box.XMax - box.XMin + 14.0) / cells, dy = (box.YMax - box.YMin + 11.0) / cells;
  tessera_test::JitteredTriangleTiling(x0, y0, dx, dy, cells, random, offsets, vertices);
}

// Areas alone of a tiling whose tiles span many grid cells come from the catchment's crossings
// with their boundaries, not from clipping (AreaByCrossings): a computation of their own, which
// must agree with the clipped rings' areas tile by tile, and sum to the catchment's area.
void ExpectAreasAloneAgree(const Catchment& catchment, const mpq_class& exactArea)
{
  std::mt19937 random(5);
  std::vector<std::size_t> offsets;
  std::vector<Point2> vertices;
  TilingOf(catchment.Bounds(), 6, random, offsets, vertices);
  const tessera::ClippedTiles clipped = catchment.ClipAll(offsets, vertices);
  Catchment::Workspace work;
  double areasAloneSum = 0.0;
  for (std::size_t t = 0; t + 1 < offsets.size(); ++t)
  {
    const std::size_t count = offsets[t + 1] - offsets[t];
    const double alone = catchment.ClipInto(&vertices[offsets[t]], count, t, work, nullptr);
    const double tileArea =
      tessera_test::ShoelaceArea({ vertices.begin() + static_cast<std::ptrdiff_t>(offsets[t]),
        vertices.begin() + static_cast<std::ptrdiff_t>(offsets[t + 1]) });
    EXPECT_NEAR(alone, clipped.Areas[t], 1e-13 * tileArea) << "tile " << t;
    areasAloneSum += alone;
  }
  EXPECT_GT(work.AreasByCrossings, 20u); // (of 72 tiles: the others lie clear of the outline)
  EXPECT_NEAR(areasAloneSum, exactArea.get_d(), 1e-12 * exactArea.get_d());
}

TEST(Clip, TilingAreasSumToCatchmentArea)
{
  for (unsigned seed = 30; seed < 34; ++seed)
  {
    std::mt19937 random(seed);
    Rings rings;
    const Point2 c{ 3.25, -1.5 };
    rings.Add(Star(random, c, 2000, 30.0, 50.0, 1e-9));
    rings.Add(Star(random, c, 300, 12.0, 25.0, 1e-9));
    rings.Add(Star(random, c, 50, 3.0, 8.0, 1e-9));
    const Catchment catchment(rings.Offsets, rings.Vertices);
    const mpq_class exactArea = ExactRegionArea(rings);
    EXPECT_NEAR(catchment.Area(), exactArea.get_d(), 1e-14 * exactArea.get_d());

    std::vector<std::size_t> offsets;
    std::vector<Point2> vertices;
    TilingOf(catchment.Bounds(), 37, random, offsets, vertices);
    const tessera::ClippedTiles clipped = catchment.ClipAll(offsets, vertices);
    ASSERT_EQ(clipped.Areas.size(), offsets.size() - 1);
    ASSERT_EQ(clipped.TileRingOffsets.size(), offsets.size());
    double sum = 0.0;
    int partial = 0;
    for (std::size_t t = 0; t < clipped.Areas.size(); ++t)
    {
      sum += clipped.Areas[t];
      const std::vector<Point2> tile(vertices.begin() + static_cast<std::ptrdiff_t>(offsets[t]),
        vertices.begin() + static_cast<std::ptrdiff_t>(offsets[t + 1]));
      partial += clipped.Areas[t] > 0 && clipped.Areas[t] < tessera_test::ShoelaceArea(tile);
      // The rings of each tile add up to its area.
      double ringSum = 0.0;
      for (std::size_t r = clipped.TileRingOffsets[t]; r < clipped.TileRingOffsets[t + 1]; ++r)
      {
        ringSum += tessera_test::ShoelaceArea({ clipped.Rings.Vertices.begin() +
            static_cast<std::ptrdiff_t>(clipped.Rings.RingOffsets[r]),
          clipped.Rings.Vertices.begin() +
            static_cast<std::ptrdiff_t>(clipped.Rings.RingOffsets[r + 1]) });
      }
      EXPECT_NEAR(ringSum, clipped.Areas[t], 1e-9 * tessera_test::ShoelaceArea(tile));
    }
    EXPECT_GT(partial, 100);
    EXPECT_EQ(clipped.CatchmentArea, catchment.Area());
    EXPECT_NEAR(sum, exactArea.get_d(), 1e-12 * exactArea.get_d());
    // Areas alone: the same areas (below 64 grid cells in a tile's box, by the same clipping).
    const tessera::ClippedTiles areasOnly = catchment.ClipAll(offsets, vertices, false);
    ASSERT_EQ(areasOnly.Areas.size(), clipped.Areas.size());
    for (std::size_t t = 0; t < clipped.Areas.size(); ++t)
    {
      EXPECT_NEAR(areasOnly.Areas[t], clipped.Areas[t], 1e-13 * catchment.Area()) << "tile " << t;
    }
    EXPECT_TRUE(areasOnly.Rings.Vertices.empty());
    ExpectAreasAloneAgree(catchment, exactArea);
  }
}

// Exactly degenerate tilings: an integer grid whose lines run along the catchment's edges and
// through its vertices.
TEST(Clip, GridAlignedWithCatchmentEdgesSumsExactly)
{
  Rings rings;
  rings.Add({ { 0, 0 }, { 6, 0 }, { 6, 2 }, { 3, 2 }, { 3, 4 }, { 6, 4 }, { 6, 6 }, { 0, 6 } });
  rings.Add({ { 1, 1 }, { 2, 3 }, { 1, 5 } });
  const Catchment catchment(rings.Offsets, rings.Vertices);
  std::vector<std::size_t> offsets{ 0 };
  std::vector<Point2> vertices;
  for (int j = -1; j < 7; ++j)
  {
    for (int i = -1; i < 7; ++i)
    {
      const std::vector<Point2> cell = Rectangle(i, j, i + 1, j + 1);
      vertices.insert(vertices.end(), cell.begin(), cell.end());
      offsets.push_back(vertices.size());
    }
  }
  const tessera::ClippedTiles clipped = catchment.ClipAll(offsets, vertices);
  double sum = 0.0;
  std::mt19937 random(5);
  for (std::size_t t = 0; t < clipped.Areas.size(); ++t)
  {
    const std::vector<Point2> tile(vertices.begin() + static_cast<std::ptrdiff_t>(offsets[t]),
      vertices.begin() + static_cast<std::ptrdiff_t>(offsets[t + 1]));
    EXPECT_EQ(clipped.Areas[t], ExactClippedArea(rings, tile).get_d()) << "cell " << t;
    sum += clipped.Areas[t];
  }
  EXPECT_EQ(sum, ExactRegionArea(rings).get_d());
  EXPECT_EQ(catchment.Area(), 36.0 - 6.0 - 2.0);
}

// A lattice cell as a tessellation may deliver it: a collinear vertex, a repeated corner, and a
// fold on the top side (a vertex a hair to the right of the one before while the side runs left).
// The polygon is still exactly the cell, but the fold's edge points right, and its half-plane
// (above the top side) holds nothing of the cell.
std::vector<Point2> RoughCell(double x0, double y0, double x1, double y1)
{
  const double xm = 0.5 * (x0 + x1);
  return { { x0, y0 },
    { xm, y0 },
    { x1, y0 },
    { x1, y0 },
    { x1, y1 },
    { xm, y1 },
    { std::nextafter(xm, x1), y1 },
    { x0, y1 } };
}

// Tiles of a lattice whose lines run through the catchment's vertices (densified sides, a slanted
// side through lattice points, a hole with lattice-point corners), each tile with collinear,
// repeated and folded vertices. The tiles cover the catchment, so their clipped areas add up to it;
// a tile's area does not depend on its start vertex nor on the extra vertices.
TEST(Clip, RoughLatticeTilesThroughCatchmentVerticesSumToCatchmentArea)
{
  const double o = 4096.0; // shifting to the tile's first vertex stays exact for these dyadics
  std::vector<Point2> outer;
  const auto side = [&](Point2 a, Point2 b, int pieces)
  {
    for (int k = 0; k < pieces; ++k)
    {
      const double t = static_cast<double>(k) / pieces;
      outer.push_back({ o + a.x + t * (b.x - a.x), o + a.y + t * (b.y - a.y) });
    }
  };
  side({ 1, 1 }, { 9, 1 }, 32);
  side({ 9, 1 }, { 9, 5 }, 16);
  side({ 9, 5 }, { 5, 7 }, 8); // through (7, 6) and half-lattice points
  side({ 5, 7 }, { 1, 7 }, 16);
  side({ 1, 7 }, { 1, 1 }, 24);
  Rings rings;
  rings.Add(outer);
  rings.Add({ { o + 3, o + 2 }, { o + 6, o + 3 }, { o + 3, o + 4 } });
  const Catchment catchment(rings.Offsets, rings.Vertices);
  const mpq_class exactArea = ExactRegionArea(rings);
  ASSERT_EQ(exactArea, mpq_class(8 * 4 + 4 * 2 + 4 * 2 / 2 - 3));

  std::vector<std::size_t> offsets{ 0 };
  std::vector<Point2> vertices;
  for (int j = 0; j < 8; ++j)
  {
    for (int i = 0; i < 10; ++i)
    {
      const std::vector<Point2> cell = RoughCell(o + i, o + j, o + i + 1, o + j + 1);
      vertices.insert(vertices.end(), cell.begin(), cell.end());
      offsets.push_back(vertices.size());
    }
  }
  const tessera::ClippedTiles clipped = catchment.ClipAll(offsets, vertices);
  double sum = 0.0;
  int partial = 0;
  for (std::size_t t = 0; t + 1 < offsets.size(); ++t)
  {
    std::vector<Point2> tile(vertices.begin() + static_cast<std::ptrdiff_t>(offsets[t]),
      vertices.begin() + static_cast<std::ptrdiff_t>(offsets[t + 1]));
    const double area = clipped.Areas[t];
    sum += area;
    partial += area > 0.0 && area < 1.0;
    const mpq_class exact = ExactPolygonClippedArea(rings, tile);
    EXPECT_NEAR(area, exact.get_d(), Tolerance(exact, 1.0)) << "tile " << t;
    const std::vector<Point2> clean = Rectangle(tile[0].x, tile[0].y, tile[4].x, tile[4].y);
    EXPECT_NEAR(catchment.ClipArea(clean), area, 1e-14) << "tile " << t;
    for (std::size_t start = 1; start < tile.size(); ++start)
    {
      std::rotate(tile.begin(), tile.begin() + 1, tile.end());
      EXPECT_NEAR(catchment.ClipArea(tile), area, 1e-14) << "tile " << t << " start " << start;
    }
  }
  EXPECT_GE(partial, 8); // the cells along the slanted sides
  EXPECT_NEAR(sum, exactArea.get_d(), 1e-12 * exactArea.get_d());
}

// Thiessen tiles of a lon/lat lattice of gauges, projected by the automatic Albers projection, and
// a densified, projected catchment: tile sides run through catchment vertices, and the tiles have
// vertices an ulp apart (rounded face centres that coincide exactly in the lattice), and
// near-collinear ones. Before the tile was clipped as its convex hull, an edge between two vertices
// an ulp apart could cut away the whole tile, depending on the start vertex.
TEST(Clip, ProjectedLatticeThiessenTilesSumToCatchmentArea)
{
  std::vector<Point2> gauges;
  for (int j = 0; j < 12; ++j)
  {
    for (int i = 0; i < 14; ++i)
    {
      gauges.push_back({ -109.0 + 0.3 * i, 37.0 + 0.16 * j });
    }
  }
  const std::vector<Point2> corners{
    { -108.0, 37.5 }, { -106.0, 37.5 }, { -106.0, 38.5 }, { -107.0, 38.8 }, { -108.0, 38.5 }
  };
  const tessera::GeographicProjection projection(tessera::AutomaticParameters(gauges));
  std::vector<Point2> sites;
  for (const Point2& g : gauges)
  {
    sites.push_back(projection.Forward(g));
  }
  Rings rings;
  {
    std::vector<Point2> ring;
    for (std::size_t k = 0; k < corners.size(); ++k)
    {
      const Point2 a = corners[k], b = corners[(k + 1) % corners.size()];
      const int pieces = tessera::DensifiedPieceCount(a, b, 0.01);
      for (int i = 0; i < pieces; ++i)
      {
        ring.push_back(
          projection.Forward(tessera::InterpolateLonLat(a, b, static_cast<double>(i) / pieces)));
      }
    }
    rings.Add(ring);
  }
  const Catchment catchment(rings.Offsets, rings.Vertices);
  const mpq_class exactArea = ExactRegionArea(rings);

  const tessera::Box2 box = tessera::BoundsOf(sites.data(), sites.size());
  const tessera::DirichletTessellation tessellation(
    tessera::Window::Rectangle(box.XMin - 2e5, box.XMax + 2e5, box.YMin - 2e5, box.YMax + 2e5),
    sites);
  const tessera::TileSet tiles = tessera::ComputeTiles(tessellation);
  std::vector<std::size_t> offsets(tiles.Offsets.begin(), tiles.Offsets.end());
  const tessera::ClippedTiles clipped = catchment.ClipAll(offsets, tiles.Vertices, false);
  double sum = 0.0;
  int partial = 0, rough = 0;
  for (std::size_t t = 0; t + 1 < offsets.size(); ++t)
  {
    std::vector<Point2> tile(tiles.Vertices.begin() + static_cast<std::ptrdiff_t>(offsets[t]),
      tiles.Vertices.begin() + static_cast<std::ptrdiff_t>(offsets[t + 1]));
    const double area = clipped.Areas[t];
    const double tileArea = tessera_test::ShoelaceArea(tile);
    sum += area;
    partial += area > 0.0 && area < 0.999 * tileArea;
    for (std::size_t i = 0; i < tile.size(); ++i)
    {
      const Point2 a = tile[i], b = tile[(i + 1) % tile.size()];
      rough += std::fabs(a.x - b.x) + std::fabs(a.y - b.y) < 1e-6;
    }
    // Every tile against the exact clip, those the clip left whole or empty included (a tile
    // wrongly dropped or wrongly kept whole must fail here, not only in the sum).
    const mpq_class exact = ExactPolygonClippedArea(rings, tile);
    EXPECT_NEAR(area, exact.get_d(), Tolerance(exact, tileArea)) << "tile " << t;
    if (exact == 0 || exact == ExactArea(ToExact(tile)))
    {
      continue; // the catchment misses the tile or holds it: rotations would not exercise a cut
    }
    for (std::size_t start = 1; start < tile.size(); ++start)
    {
      std::rotate(tile.begin(), tile.begin() + 1, tile.end());
      EXPECT_NEAR(catchment.ClipArea(tile), area, 1e-12 * tileArea)
        << "tile " << t << " start " << start;
    }
  }
  EXPECT_GT(partial, 20);
  EXPECT_GT(rough, 10); // the tiles do have vertices a hair apart
  EXPECT_NEAR(sum, exactArea.get_d(), 1e-12 * exactArea.get_d());
}

// ---- Rings that touch at points (OGC-valid polygons) --------------------------------------------

// A square with two holes and an island, touching at single points: hole 1's vertex on the middle
// of the square's left edge, hole 2 at hole 1's right vertex, the island at hole 1's bottom
// vertex. Each touching ring starts at its contact, so the first vertex is on another ring.
Rings TouchingRings()
{
  Rings rings;
  rings.Add(Rectangle(0, 0, 100, 100));
  rings.Add({ { 0, 50 }, { 30, 20 }, { 60, 50 }, { 30, 80 } });
  rings.Add({ { 60, 50 }, { 80, 30 }, { 90, 50 }, { 80, 70 } });
  rings.Add({ { 30, 20 }, { 40, 45 }, { 30, 60 }, { 20, 45 } });
  return rings;
}

TEST(Clip, RingsTouchingAtPointsFollowEvenOdd)
{
  const Rings rings = TouchingRings();
  const Catchment catchment(rings.Offsets, rings.Vertices);
  EXPECT_EQ(catchment.RingDepths(), (std::vector<int>{ 0, 1, 1, 2 }));
  // 100 * 100 less the two diamonds (60 x 60 / 2 and 30 x 40 / 2), plus the island (20 x 40 / 2).
  EXPECT_EQ(catchment.Area(), 10000.0 - 1800.0 - 600.0 + 400.0);
  EXPECT_EQ(mpq_class(catchment.Area()), ExactRegionArea(rings));
  EXPECT_TRUE(catchment.Contains({ 5, 10 }));
  EXPECT_FALSE(catchment.Contains({ 10, 50 }));
  EXPECT_FALSE(catchment.Contains({ 80, 50 }));
  EXPECT_TRUE(catchment.Contains({ 30, 40 }));
  for (unsigned seed = 40; seed < 43; ++seed)
  {
    CompareRandomTiles(rings, 0.0, seed, 150);
  }
  // Tiles with a contact point as a vertex, or on an edge.
  for (const std::vector<Point2>& tile : { Rectangle(0, 40, 10, 60),
         Rectangle(50, 40, 70, 60),
         Rectangle(25, 10, 35, 30),
         std::vector<Point2>{ { 55, 50 }, { 65, 50 }, { 60, 62 } } })
  {
    const mpq_class exact = ExactClippedArea(rings, tile);
    EXPECT_GT(exact, 0);
    EXPECT_NEAR(
      catchment.ClipArea(tile), exact.get_d(), Tolerance(exact, tessera_test::ShoelaceArea(tile)));
  }
}

// A ring may touch others at every one of its vertices: a hole inscribed in the outer ring.
TEST(Clip, AHoleTouchingAtEveryVertexIsAHole)
{
  Rings rings;
  rings.Add({ { 0, 5 }, { 5, 0 }, { 10, 5 } });
  rings.Add(Rectangle(0, 0, 10, 10));
  const Catchment catchment(rings.Offsets, rings.Vertices);
  EXPECT_EQ(catchment.RingDepths(), (std::vector<int>{ 1, 0 }));
  EXPECT_EQ(catchment.Area(), 75.0);
  EXPECT_EQ(mpq_class(catchment.Area()), ExactRegionArea(rings));
  EXPECT_FALSE(catchment.Contains({ 5, 2 }));
  EXPECT_TRUE(catchment.Contains({ 5, 7 }));
  EXPECT_TRUE(catchment.Contains({ 1, 1 }));
}

// Sub-catchments given as adjacent polygons (one meeting two others along parts of its edge), and
// a lake on the outline (a hole sharing a stretch of it: a bay): the even-odd region is their
// union, less the lake.
TEST(Clip, RingsSharingStretchesOfBoundaryFollowEvenOdd)
{
  Rings rings;
  rings.Add(Rectangle(0, 0, 50, 100));
  rings.Add(Rectangle(50, 0, 100, 40));
  rings.Add(Rectangle(50, 40, 100, 100));
  rings.Add({ { 70, 100 }, { 60, 80 }, { 90, 80 }, { 80, 100 } });
  const Catchment catchment(rings.Offsets, rings.Vertices);
  EXPECT_EQ(catchment.RingDepths(), (std::vector<int>{ 0, 0, 0, 1 }));
  EXPECT_EQ(catchment.Area(), 10000.0 - 400.0);
  EXPECT_EQ(mpq_class(catchment.Area()), ExactRegionArea(rings));
  EXPECT_TRUE(catchment.Contains({ 75, 60 }));
  EXPECT_FALSE(catchment.Contains({ 75, 90 }));
  for (unsigned seed = 45; seed < 48; ++seed)
  {
    CompareRandomTiles(rings, 0.0, seed, 150);
  }
}

// Sub-catchments tiling a basin (a 3 x 3 grid of squares: the middle one shares all its edges with
// others), and a hole in a corner of the basin's outline, sharing two edges with it.
TEST(Clip, RingsWhoseEdgesAreAllSharedAreNestedRightly)
{
  Rings grid;
  for (int i = 0; i < 3; ++i)
  {
    for (int j = 0; j < 3; ++j)
    {
      grid.Add(Rectangle(40.0 * i, 40.0 * j, 40.0 * i + 40, 40.0 * j + 40));
    }
  }
  const Catchment tiled(grid.Offsets, grid.Vertices);
  EXPECT_EQ(tiled.RingDepths(), std::vector<int>(9, 0));
  EXPECT_EQ(tiled.Area(), 14400.0);
  EXPECT_TRUE(tiled.Contains({ 60, 60 }));
  CompareRandomTiles(grid, 0.0, 48, 150);
  Rings corner;
  corner.Add(Rectangle(0, 0, 30, 30));
  corner.Add(Rectangle(0, 0, 10, 10));
  const Catchment cornered(corner.Offsets, corner.Vertices);
  EXPECT_EQ(cornered.RingDepths(), (std::vector<int>{ 0, 1 }));
  EXPECT_EQ(cornered.Area(), 800.0);
  EXPECT_FALSE(cornered.Contains({ 5, 5 }));
  EXPECT_TRUE(cornered.Contains({ 15, 5 }));
}

// Parts of a multipolygon meeting at corners (a checkerboard, whose inner squares touch others at
// all four corners), and the sum of a tiling.
TEST(Clip, PartsMeetingAtCornersSumToTheirArea)
{
  Rings rings;
  for (int i = 0; i < 4; ++i)
  {
    for (int j = 0; j < 4; ++j)
    {
      if ((i + j) % 2 == 0)
      {
        rings.Add(Rectangle(10.0 * i, 10.0 * j, 10.0 * i + 10, 10.0 * j + 10));
      }
    }
  }
  const Catchment catchment(rings.Offsets, rings.Vertices);
  EXPECT_EQ(catchment.Area(), 800.0);
  EXPECT_EQ(catchment.RingDepths(), std::vector<int>(8, 0));
  std::mt19937 random(44);
  std::vector<std::size_t> offsets;
  std::vector<Point2> vertices;
  TilingOf(catchment.Bounds(), 23, random, offsets, vertices);
  const tessera::ClippedTiles clipped = catchment.ClipAll(offsets, vertices);
  double sum = 0.0;
  for (std::size_t t = 0; t + 1 < offsets.size(); ++t)
  {
    const std::vector<Point2> tile(vertices.begin() + static_cast<std::ptrdiff_t>(offsets[t]),
      vertices.begin() + static_cast<std::ptrdiff_t>(offsets[t + 1]));
    const mpq_class exact = ExactClippedArea(rings, tile);
    EXPECT_NEAR(
      clipped.Areas[t], exact.get_d(), Tolerance(exact, tessera_test::ShoelaceArea(tile)));
    sum += clipped.Areas[t];
  }
  EXPECT_NEAR(sum, 800.0, 1e-12 * 800.0);
}

// ---- Bad input ---------------------------------------------------------------------------------

// ValidateRings, which other tests use to say the library's rings are simple, agrees with an
// exact test of every pair of edges (RingDefect) on random rings of 3 to 7 vertices on a 4 x 4
// lattice: most touch, cross or double back on themselves; some are simple.
TEST(Clip, ValidateRingsAgreesWithAnExactTestOfEveryPairOfEdges)
{
  std::mt19937 random(5);
  std::uniform_int_distribution<int> coordinate(0, 3), size(3, 7);
  int simple = 0, refused = 0;
  for (int trial = 0; trial < 20000; ++trial)
  {
    std::vector<Point2> ring(std::size_t(size(random)));
    for (Point2& p : ring)
    {
      p = { double(coordinate(random)), double(coordinate(random)) };
    }
    const std::string defect = tessera_test::RingDefect(ring);
    const std::string error = ErrorOf([&] { tessera::ValidateRings({ 0, ring.size() }, ring); });
    EXPECT_EQ(defect.empty(), error.empty())
      << "trial " << trial << ": exactly, " << (defect.empty() ? "simple" : defect)
      << "; ValidateRings: " << (error.empty() ? "accepted" : error);
    simple += defect.empty();
    refused += !defect.empty();
  }
  EXPECT_GT(simple, 1000);
  EXPECT_GT(refused, 1000);
}

TEST(Clip, RejectsBadCatchmentsNamingRingsAndSegments)
{
  const auto build = [](const Rings& rings)
  { return ErrorOf([&] { Catchment catchment(rings.Offsets, rings.Vertices); }); };
  Rings bowTie;
  bowTie.Add({ { 0, 0 }, { 2, 0 }, { 0, 2 }, { 2, 2 } });
  EXPECT_EQ(build(bowTie),
    "ring 0 is self-intersecting: segment 1 and segment 3 touch or cross" + SelfContactHint);

  Rings crossing;
  crossing.Add(Rectangle(0, 0, 4, 4));
  crossing.Add(Rectangle(3, 1, 5, 2));
  const std::string crossed = build(crossing);
  EXPECT_NE(crossed.find("ring 0 segment 1 and ring 1 segment"), std::string::npos) << crossed;
  // The error carries the rings' indices, for a caller to say where they came from.
  const auto ringsOf = [](const Rings& rings)
  {
    try
    {
      Catchment catchment(rings.Offsets, rings.Vertices);
    }
    catch (const tessera::RingError& error)
    {
      return error.Rings;
    }
    return std::vector<std::size_t>();
  };
  EXPECT_EQ(ringsOf(crossing), (std::vector<std::size_t>{ 0, 1 }));
  EXPECT_EQ(ringsOf(bowTie), (std::vector<std::size_t>{ 0 }));
  // and the segments it names ("ring:segment"), for a caller to say where they run.
  const auto segmentsOf = [](const Rings& rings)
  {
    std::string named;
    try
    {
      Catchment catchment(rings.Offsets, rings.Vertices);
    }
    catch (const tessera::RingError& error)
    {
      for (const tessera::RingError::Segment& s : error.Segments)
      {
        named +=
          (named.empty() ? "" : " ") + std::to_string(s.Ring) + ":" + std::to_string(s.Index);
      }
    }
    return named;
  };

  // Rings may touch and share stretches of boundary, not cross: ring 1's diagonal enters ring 0
  // at one corner and leaves at the other; ring 3 runs along ring 2's bottom edge and leaves it
  // below, then inside, and comes back along its top edge.
  Rings crossingAtCorners;
  crossingAtCorners.Add(Rectangle(0, 0, 10, 10));
  crossingAtCorners.Add({ { 0, 0 }, { 10, 10 }, { 20, -5 } });
  EXPECT_EQ(build(crossingAtCorners).rfind("ring 0 segment", 0), 0u) << build(crossingAtCorners);
  EXPECT_NE(build(crossingAtCorners).find("and ring 1 segment"), std::string::npos);
  EXPECT_NE(build(crossingAtCorners).find(" cross (rings may touch and share stretches"),
    std::string::npos);
  Rings crossingAlongStretches;
  crossingAlongStretches.Add(Rectangle(0, 0, 10, 10));
  crossingAlongStretches.Add(
    { { 2, 0 }, { 4, 0 }, { 4, 10 }, { 2, 10 }, { 2, 12 }, { -2, 12 }, { -2, -2 }, { 2, -2 } });
  EXPECT_EQ(build(crossingAlongStretches),
    "ring 0 and ring 1 cross along boundary they share, where ring 0 segment 0 meets ring 1 "
    "segment 0: ring 1 leaves ring 0 on its outside at one end and on its inside at the other "
    "(rings may touch and share stretches of boundary, but not cross; holes and islands are "
    "separate rings)");
  EXPECT_EQ(segmentsOf(crossingAlongStretches), "0:0 1:0");
  // Ring 1 touches ring 0 from inside at (0, 5), from outside at (2, 0), and crosses its right
  // edge at (10, 8) and (10, 9). The contacts, swept first, show both sides; the crossing named
  // is the first of the two where they cross, not a contact.
  //
  //          +-----------+ (10,10)
  //          |       .-----x----.  (9,9) to (12,9): crossing at (10,9)
  //          |   .---------x--. |  (9,8) to (11,8): crossing at (10,8), the one named
  //   (0,5)  +<            |  | |
  //          |             |  | |  ring 1 runs (0,5) (9,8) (11,8) (11,-2) (3,-2) (2,0) (1,-2)
  //   (0,0)  +--v----------+  | |  (1,-3) (12,-3) (12,9) (9,9); it touches ring 0 at (0,5)
  //           / \ ..........'  |  from inside, at (2,0) from outside
  //          '   '..............'
  Rings crossingBeyondContacts;
  crossingBeyondContacts.Add(Rectangle(0, 0, 10, 10));
  crossingBeyondContacts.Add({ { 0, 5 },
    { 9, 8 },
    { 11, 8 },
    { 11, -2 },
    { 3, -2 },
    { 2, 0 },
    { 1, -2 },
    { 1, -3 },
    { 12, -3 },
    { 12, 9 },
    { 9, 9 } });
  EXPECT_EQ(build(crossingBeyondContacts),
    "ring 0 segment 1 and ring 1 segment 1 cross (rings may touch and share stretches of "
    "boundary, but not cross; holes and islands are separate rings)");
  EXPECT_EQ(segmentsOf(crossingBeyondContacts), "0:1 1:1");
  EXPECT_EQ(segmentsOf(crossing), "0:1 1:0"); // (3, 1)-(5, 1) across x = 4
  EXPECT_EQ(segmentsOf(bowTie), "0:1 0:3");
  Rings twice;
  twice.Add(Rectangle(0, 0, 10, 10));
  twice.Add(Rectangle(0, 0, 10, 10));
  EXPECT_EQ(build(twice),
    "ring 0 and ring 1 run along each other all the way round: a ring given twice (give it once: "
    "by the even-odd rule the two copies cancel, taking its region away), or an island that fills "
    "a hole exactly (leave both out: they cancel)");
  Rings spike; // goes out and back along the same line
  spike.Add({ { 0, 0 }, { 4, 0 }, { 4, 4 }, { 4, 6 }, { 4, 5 }, { 0, 4 } });
  EXPECT_NE(build(spike).find("ring 0 is self-intersecting"), std::string::npos) << build(spike);

  Rings nan;
  nan.Add(Rectangle(0, 0, 1, 1));
  nan.Add({ { 5, 5 }, { 6, 5 }, { std::nan(""), 6 } });
  EXPECT_EQ(build(nan), "ring 1 vertex 2 has a NaN coordinate");

  Rings infinite;
  infinite.Add({ { 0, 0 }, { HUGE_VAL, 0 }, { 0, 1 } });
  EXPECT_EQ(build(infinite), "ring 0 vertex 1 has an infinite coordinate");

  Rings flat;
  flat.Add({ { 0, 0 }, { 1, 1 }, { 1, 1 }, { 0, 0 } });
  EXPECT_NE(build(flat).find("ring 0 has fewer than 3 distinct vertices"), std::string::npos);
  Rings point; // (a ring of one vertex: that vertex repeats itself, and none was left)
  point.Add({ { 0.5, 0.5 } });
  EXPECT_EQ(build(point), "ring 0 has 1 vertex (a polygon needs 3 or more)");
  Rings emptyAfterARectangle;
  emptyAfterARectangle.Add(Rectangle(0, 0, 1, 1));
  emptyAfterARectangle.Add({});
  EXPECT_EQ(build(emptyAfterARectangle), "ring 1 has 0 vertices (a polygon needs 3 or more)");

  Rings collinear;
  collinear.Add({ { 0, 0 }, { 1, 1 }, { 2, 2 } });
  EXPECT_EQ(build(collinear),
    "ring 0 has no area: its points lie on one line (segment 0 and segment 2 overlap)");
  Rings collinearAfterARectangle; // named by its own number, its points in any order
  collinearAfterARectangle.Add(Rectangle(0, 0, 10, 10));
  collinearAfterARectangle.Add({ { 20, 0 }, { 24, 2 }, { 22, 1 }, { 26, 3 } });
  EXPECT_NE(build(collinearAfterARectangle).find("ring 1 has no area: its points lie on one line"),
    std::string::npos)
    << build(collinearAfterARectangle);

  // A closing vertex equal to the first, and repeated vertices, are accepted.
  Rings closed;
  closed.Add({ { 0, 0 }, { 2, 0 }, { 2, 0 }, { 2, 2 }, { 0, 2 }, { 0, 0 } });
  EXPECT_EQ(build(closed), "");
  const Catchment catchment(closed.Offsets, closed.Vertices);
  EXPECT_EQ(catchment.Area(), 4.0);
  EXPECT_EQ(catchment.Vertices().size(), 4u);
}

TEST(Clip, RejectsBadTilesNamingThem)
{
  Rings square;
  square.Add(Rectangle(0, 0, 4, 4));
  const Catchment catchment(square.Offsets, square.Vertices);
  std::vector<Point2> clockwise = Rectangle(1, 1, 2, 2);
  std::reverse(clockwise.begin(), clockwise.end());
  EXPECT_NE(ErrorOf([&] { catchment.ClipArea(clockwise); }).find("tile 0 has clockwise"),
    std::string::npos);
  EXPECT_EQ(ErrorOf(
              [&] {
                catchment.ClipArea({ { 0, 0 }, { 1, 0 } });
              }),
    "tile 0 has 2 vertices; a tile needs at least 3");
  std::vector<Point2> vertices = Rectangle(1, 1, 2, 2);
  const std::vector<Point2> second = { { 0, 0 }, { 1, std::nan("") }, { 0, 1 } };
  vertices.insert(vertices.end(), second.begin(), second.end());
  EXPECT_EQ(ErrorOf(
              [&] {
                catchment.ClipAll({ 0, 4, 7 }, vertices);
              }),
    "tile 1 vertex 1 has a NaN coordinate");
  EXPECT_NE(ErrorOf(
              [&] {
                catchment.ClipAll({ 0, 4, 6 }, vertices);
              })
              .find("last tile offset"),
    std::string::npos);
  // A degenerate tile (zero area) is not an error.
  EXPECT_EQ(catchment.ClipArea({ { 1, 1 }, { 2, 2 }, { 3, 3 } }), 0.0);
}

TEST(Clip, NonConvexTilesAreErrorsAndRoundingFoldsAreNot)
{
  // A genuinely non-convex tile would be clipped as its convex hull: it is an error naming it,
  // whether it lies inside the catchment, straddles it or misses it. A tile whose reflex turn is
  // only as deep as the rounding of its coordinates (as in a tessellation far from the origin) is
  // clipped.
  Rings square;
  square.Add(Rectangle(0, 0, 4, 4));
  const Catchment catchment(square.Offsets, square.Vertices);
  const auto ell = [](double x, double y)
  {
    return std::vector<Point2>{
      { x, y }, { x + 2, y }, { x + 2, y + 1 }, { x + 1, y + 1 }, { x + 1, y + 2 }, { x, y + 2 }
    };
  };
  for (const Point2& at : { Point2{ 1, 1 }, Point2{ 3, 3 }, Point2{ 10, 10 } })
  {
    const std::string error = ErrorOf([&] { catchment.ClipArea(ell(at.x, at.y)); });
    EXPECT_NE(error.find("tile 0 is not convex: its area 3 differs from its convex hull's 3.5"),
      std::string::npos)
      << error;
  }
  std::vector<Point2> vertices = Rectangle(1, 1, 2, 2);
  const std::vector<Point2> second = ell(2, 2);
  vertices.insert(vertices.end(), second.begin(), second.end());
  EXPECT_NE(ErrorOf(
              [&] {
                catchment.ClipAll({ 0, 4, 10 }, vertices);
              })
              .find("tile 1 is not convex"),
    std::string::npos);
  // Tessellation tiles (FoldedTile::IsEmpty) are not checked: they are convex up to rounding.
  Catchment::Workspace work;
  const std::vector<Point2> inside = ell(1, 1);
  EXPECT_EQ(catchment.ClipInto(
              inside.data(), inside.size(), 0, work, nullptr, Catchment::FoldedTile::IsEmpty),
    3.0);

  // A unit square at 2^40 with a vertex on its bottom edge raised by one ulp (2^-12): a reflex
  // turn 1.2e-4 of its area deep, from rounding alone. A notch half the side deep is not.
  const double big = std::ldexp(1.0, 40), ulp = std::ldexp(1.0, -12);
  Rings far;
  far.Add(Rectangle(big - 8, big - 8, big + 0.5, big + 8));
  const Catchment farCatchment(far.Offsets, far.Vertices);
  const std::vector<Point2> folded{
    { big, big }, { big + 0.5, big + ulp }, { big + 1, big }, { big + 1, big + 1 }, { big, big + 1 }
  };
  const double area = farCatchment.ClipArea(folded);
  EXPECT_GE(area, 0.5 - ulp);
  EXPECT_LE(area, 0.5);
  const std::vector<Point2> notched{
    { big, big }, { big + 0.5, big + 0.5 }, { big + 1, big }, { big + 1, big + 1 }, { big, big + 1 }
  };
  EXPECT_NE(ErrorOf([&] { farCatchment.ClipArea(notched); }).find("tile 0 is not convex"),
    std::string::npos);

  // A square listed twice winds twice around its hull: twice the hull's area.
  std::vector<Point2> twice = Rectangle(1, 1, 2, 2);
  const std::vector<Point2> again = twice;
  twice.insert(twice.end(), again.begin(), again.end());
  EXPECT_NE(ErrorOf([&] { catchment.ClipArea(twice); }).find("tile 0 is not convex: its area 2"),
    std::string::npos);

  // Tiles that went through float (VTK points often do): a fold as deep as a float's rounding at
  // UTM-like coordinates is an error for double coordinates, and clips when the caller gives the
  // float epsilon.
  const double x0 = 500000.0, y0 = 4500000.0, floatUlp = std::ldexp(1.0, -1); // ulp of 4.5e6
  const std::vector<Point2> floatFolded{ { x0, y0 },
    { x0 + 300, y0 + floatUlp },
    { x0 + 600, y0 },
    { x0 + 600, y0 + 600 },
    { x0, y0 + 600 } };
  Rings utm;
  utm.Add(Rectangle(x0 - 1000, y0 - 1000, x0 + 300, y0 + 1000));
  const Catchment utmCatchment(utm.Offsets, utm.Vertices);
  EXPECT_NE(ErrorOf([&] { utmCatchment.ClipArea(floatFolded); }).find("tile 0 is not convex"),
    std::string::npos);
  const double floatArea = utmCatchment.ClipInto(floatFolded.data(),
    floatFolded.size(),
    0,
    work,
    nullptr,
    Catchment::FoldedTile::IsAnError,
    std::numeric_limits<float>::epsilon());
  EXPECT_NEAR(floatArea, 300.0 * 600.0, 300.0 * floatUlp);
}

TEST(Clip, SegmentsIntersectIsExact)
{
  // Near-degenerate: c is on segment ab only in exact arithmetic.
  const Point2 a{ 0.1, 0.1 }, b{ 0.7, 0.7 };
  EXPECT_TRUE(tessera::SegmentsIntersect(a, b, { 0.5, 0.5 }, { 1, 0 }));
  EXPECT_FALSE(tessera::SegmentsIntersect(a, b, { std::nextafter(0.5, 1.0), 0.5 }, { 1, 0 }));
  EXPECT_TRUE(tessera::SegmentsIntersect(a, b, { 0.7, 0.7 }, { 1, 0 }));
  EXPECT_FALSE(tessera::SegmentsIntersect(a, b, { 0.8, 0.8 }, { 1, 1 }));
  EXPECT_TRUE(tessera::SegmentsIntersect(a, b, { 0.6, 0.6 }, { 1, 1 }));
}

TEST(Clip, RejectsTheBowTieOfTheColoradoOutline)
{
  // Four consecutive vertices of the R maps Colorado outline (its vertices 19 to 22, at the
  // north-west corner), closed by a point to the south-east: segment 19->20 crosses 21->22.
  Rings corner;
  corner.Add({ { -107.922333, 41.018047 },
    { -109.056786, 40.989399 },
    { -109.051064, 40.995129 },
    { -109.056786, 40.657085 },
    { -107.9, 40.6 } });
  EXPECT_EQ(ErrorOf([&] { Catchment catchment(corner.Offsets, corner.Vertices); }),
    "ring 0 is self-intersecting: segment 0 and segment 2 touch or cross" + SelfContactHint);
  // Without vertex 21 (here 2) the ring is simple.
  Rings fixed;
  fixed.Add({ { -107.922333, 41.018047 },
    { -109.056786, 40.989399 },
    { -109.056786, 40.657085 },
    { -107.9, 40.6 } });
  EXPECT_EQ(ErrorOf([&] { Catchment catchment(fixed.Offsets, fixed.Vertices); }), "");
}

TEST(Clip, ContainsMatchesExactEvenOdd)
{
  std::mt19937 random(40);
  const Rings rings = NestedStars(random, 1.0 / 64, 0.0);
  const Catchment catchment(rings.Offsets, rings.Vertices);
  std::uniform_real_distribution<double> x(-70.0, 200.0);
  std::uniform_real_distribution<double> y(-80.0, 80.0);
  int inside = 0;
  for (int i = 0; i < 3000; ++i)
  {
    const Point2 p{ x(random), y(random) };
    const bool expected = ExactInsideRegion(ToExact(p), rings);
    EXPECT_EQ(catchment.Contains(p), expected) << p.x << " " << p.y;
    inside += expected;
  }
  EXPECT_GT(inside, 300);
  EXPECT_LT(inside, 2700);
}

// Densified edges (many collinear vertices, as a densified outline has) and tiles whose edges pass
// through those vertices.
TEST(Clip, DensifiedOutlineWithTilesThroughItsVertices)
{
  std::vector<Point2> outer;
  for (int k = 0; k < 16; ++k)
  {
    outer.push_back({ k * 0.5, 0.0 });
  }
  for (int k = 0; k < 16; ++k)
  {
    outer.push_back({ 8.0, k * 0.5 });
  }
  for (int k = 0; k < 16; ++k)
  {
    outer.push_back({ 8.0 - k * 0.5, 8.0 });
  }
  for (int k = 0; k < 16; ++k)
  {
    outer.push_back({ 0.0, 8.0 - k * 0.5 });
  }
  Rings rings;
  rings.Add(outer);
  rings.Add({ { 2, 2 }, { 2, 6 }, { 6, 6 }, { 6, 2 } });
  const Catchment catchment(rings.Offsets, rings.Vertices);
  EXPECT_EQ(catchment.Area(), 64.0 - 16.0);
  std::mt19937 random(41);
  std::uniform_int_distribution<int> coordinate(-2, 20);
  for (int i = 0; i < 200; ++i)
  {
    // Triangles with half-integer vertices: their edges often run along or through ring vertices.
    std::vector<Point2> tile = { { coordinate(random) * 0.5, coordinate(random) * 0.5 },
      { coordinate(random) * 0.5, coordinate(random) * 0.5 },
      { coordinate(random) * 0.5, coordinate(random) * 0.5 } };
    const double area = tessera_test::ShoelaceArea(tile);
    if (area == 0.0)
    {
      continue;
    }
    if (area < 0.0)
    {
      std::swap(tile[1], tile[2]);
    }
    const mpq_class exact = ExactClippedArea(rings, tile);
    const tessera::ClippedTile clipped = catchment.Clip(tile);
    EXPECT_NEAR(clipped.Area, exact.get_d(), Tolerance(exact, std::fabs(area)));
    CheckRings(clipped.Rings, clipped.Area, rings, tile, random);
  }
}

// A clockwise tile is named with its signed area as a number (%f printed -0.000000 for -5e-9).
TEST(Clip, AClockwiseTileIsNamedWithItsArea)
{
  const Rings rings({ { { 0.0, 0.0 }, { 1.0, 0.0 }, { 1.0, 1.0 }, { 0.0, 1.0 } } });
  const Catchment catchment(rings.Offsets, rings.Vertices);
  const std::vector<Point2> clockwise{ { 0.5, 0.5 }, { 0.5, 0.5001 }, { 0.5001, 0.5 } };
  try
  {
    catchment.ClipArea(clockwise);
    ADD_FAILURE() << "a clockwise tile was clipped";
  }
  catch (const tessera::InputError& e)
  {
    EXPECT_NE(std::string(e.what()).find("signed area -4.99999999999"), std::string::npos)
      << e.what();
  }
}

// AllOnOneLine against exact rational cross products of every triple, on small sets of grid
// points (many collinear, many repeated, the first often repeated).
TEST(PolygonValidation, AllOnOneLineMatchesExactTriples)
{
  std::mt19937 random(17);
  std::uniform_int_distribution<int> coordinate(0, 3), size(0, 6);
  int collinear = 0, notCollinear = 0;
  for (int trial = 0; trial < 2000; ++trial)
  {
    std::vector<Point2> points(static_cast<std::size_t>(size(random)));
    for (Point2& p : points)
    {
      // On the line y = 2x + 1 half the time (scaled by 0.1: not exact in binary), else anywhere.
      const int x = coordinate(random);
      p = trial % 2 ? Point2{ 0.1 * x, 0.1 * (2 * x + 1) }
                    : Point2{ 0.1 * x, 0.1 * coordinate(random) };
    }
    bool expected = true;
    for (const Point2& a : points)
      for (const Point2& b : points)
        for (const Point2& c : points)
        {
          expected = expected && Cross(ToExact(a), ToExact(b), ToExact(c)) == 0;
        }
    EXPECT_EQ(AllOnOneLine(points.data(), points.size()), expected) << "trial " << trial;
    ++(expected ? collinear : notCollinear);
  }
  EXPECT_GT(collinear, 500);
  EXPECT_GT(notCollinear, 500);
}
