// Properties of the derived results: tiles against an independent O(N^2) half-plane
// intersection, areas summing to the window area, the Euler count of section 2.3, the square
// lattice (square tiles, diagonals as half-neighbours, degenerate faces), Delaunay faces.

#include "circumcentre.h"
#include "clip.h"
#include "dirichlet_tessellation.h"
#include "polygon_area.h"
#include "predicates.h"
#include "thiessen_sweep.h"
#include "tiles.h"

#include <gmpxx.h>
#include "exact_support.h"
#include "test_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <functional>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <map>
#include <random>
#include <set>
#include <string>
#include <vector>

using namespace tessera;
using tessera_test::GraphPairs;
using tessera_test::Hexagon;
using tessera_test::PairKinds;
using tessera_test::ShoelaceArea;
using tessera_test::UniformPoints;

namespace
{

double NeumaierSum(const std::vector<double>& values)
{
  double sum = 0.0, compensation = 0.0;
  for (const double v : values)
  {
    const double t = sum + v;
    compensation += std::fabs(sum) >= std::fabs(v) ? (sum - t) + v : (v - t) + sum;
    sum = t;
  }
  return sum + compensation;
}

// Independent tile: the window polygon clipped by every bisector half-plane, one at a time.
std::vector<Point2> BruteForceTile(const Window& window,
  const std::vector<Point2>& points,
  std::size_t i)
{
  std::vector<Point2> polygon = window.Vertices();
  for (std::size_t j = 0; j < points.size(); ++j)
  {
    if (j == i)
    {
      continue;
    }
    // Keep x with |x - pi|^2 <= |x - pj|^2, i.e. g(x) = (pj - pi).x - (|pj|^2 - |pi|^2)/2 <= 0.
    const double nx = points[j].x - points[i].x, ny = points[j].y - points[i].y;
    const double mx = 0.5 * (points[i].x + points[j].x), my = 0.5 * (points[i].y + points[j].y);
    const auto g = [&](const Point2& p) { return nx * (p.x - mx) + ny * (p.y - my); };
    std::vector<Point2> clipped;
    for (std::size_t k = 0; k < polygon.size(); ++k)
    {
      const Point2& a = polygon[k];
      const Point2& b = polygon[(k + 1) % polygon.size()];
      const double ga = g(a), gb = g(b);
      if (ga <= 0)
      {
        clipped.push_back(a);
      }
      if ((ga < 0 && gb > 0) || (ga > 0 && gb < 0))
      {
        const double s = ga / (ga - gb);
        clipped.push_back({ a.x + s * (b.x - a.x), a.y + s * (b.y - a.y) });
      }
    }
    polygon = clipped;
  }
  return polygon;
}

// The exact area of point i's tile: the window polygon clipped by every bisector half-plane in
// rational arithmetic.
mpq_class ExactTileArea(const Window& window, const std::vector<Point2>& points, std::size_t i)
{
  using Q = tessera_test::QPoint;
  std::vector<Q> polygon;
  for (const Point2& v : window.Vertices())
  {
    polygon.push_back({ v.x, v.y });
  }
  const Q p{ points[i].x, points[i].y };
  for (std::size_t j = 0; j < points.size(); ++j)
  {
    const Q q{ points[j].x, points[j].y };
    if (j == i || (q.x == p.x && q.y == p.y))
    {
      continue;
    }
    // g(x) = (q - p).(x - (p + q) / 2) <= 0: nearer to p.
    const mpq_class mx = (p.x + q.x) / 2, my = (p.y + q.y) / 2;
    const auto g = [&](const Q& v) -> mpq_class
    { return (q.x - p.x) * (v.x - mx) + (q.y - p.y) * (v.y - my); };
    std::vector<Q> clipped;
    for (std::size_t k = 0; k < polygon.size(); ++k)
    {
      const Q& a = polygon[k];
      const Q& b = polygon[(k + 1) % polygon.size()];
      const mpq_class ga = g(a), gb = g(b);
      if (sgn(ga) <= 0)
      {
        clipped.push_back(a);
      }
      if ((sgn(ga) < 0 && sgn(gb) > 0) || (sgn(ga) > 0 && sgn(gb) < 0))
      {
        const mpq_class t = ga / (ga - gb);
        clipped.push_back({ a.x + t * (b.x - a.x), a.y + t * (b.y - a.y) });
      }
    }
    polygon = clipped;
  }
  return tessera_test::ExactArea(polygon);
}

bool Near(const Point2& a, const Point2& b, double tolerance)
{
  return std::fabs(a.x - b.x) <= tolerance && std::fabs(a.y - b.y) <= tolerance;
}

std::size_t KindCount(const ContiguityGraph& graph, int kind)
{
  return std::size_t(std::count(graph.Kinds.begin(), graph.Kinds.end(), std::uint8_t(kind)));
}

} // namespace

TEST(Tiles, AgreeWithBruteForceHalfPlaneIntersection)
{
  for (const bool hexagon : { false, true })
  {
    for (unsigned seed = 1; seed <= 6; ++seed)
    {
      const Window window = hexagon ? Hexagon() : Window::Rectangle(-0.1, 1.1, -0.2, 1.05);
      // Some points outside the window too: they must be ignored.
      const std::vector<Point2> points = UniformPoints(5 + 15 * seed, seed, -0.15, 1.15);
      DirichletTessellation t(window, points);
      std::vector<Point2> accepted;
      std::vector<std::int32_t> acceptedIds;
      for (std::int32_t id = 0; id < std::int32_t(points.size()); ++id)
      {
        if (t.Status(id) == PointStatus::Accepted)
        {
          accepted.push_back(points[id]);
          acceptedIds.push_back(id);
        }
      }
      const TileSet tiles = ComputeTiles(t);
      std::vector<std::int32_t> tileIds = tiles.PointIds;
      std::sort(tileIds.begin(), tileIds.end());
      ASSERT_EQ(tileIds, acceptedIds);
      for (std::size_t k = 0; k < accepted.size(); ++k)
      {
        const std::size_t index =
          std::size_t(std::find(acceptedIds.begin(), acceptedIds.end(), tiles.PointIds[k]) -
            acceptedIds.begin());
        const std::vector<Point2> expected = BruteForceTile(window, accepted, index);
        const std::vector<Point2> ours(
          tiles.Vertices.begin() + tiles.Offsets[k], tiles.Vertices.begin() + tiles.Offsets[k + 1]);
        EXPECT_NEAR(tiles.Areas[k], ShoelaceArea(expected), 1e-10) << "tile " << k;
        for (const Point2& v : ours)
        {
          EXPECT_TRUE(std::any_of(
            expected.begin(), expected.end(), [&](const Point2& w) { return Near(v, w, 1e-9); }))
            << "tile " << k << " vertex " << v.x << " " << v.y;
        }
        for (const Point2& w : expected)
        {
          EXPECT_TRUE(std::any_of(
            ours.begin(), ours.end(), [&](const Point2& v) { return Near(v, w, 1e-9); }))
            << "tile " << k << " misses " << w.x << " " << w.y;
        }
        // Anticlockwise.
        EXPECT_GT(tiles.Areas[k], 0.0);
      }
    }
  }
}

TEST(Tiles, AreasSumToTheWindowAreaAndEulerCountHolds)
{
  for (const bool hexagon : { false, true })
  {
    for (const std::size_t n : { 2u, 3u, 17u, 400u, 5000u })
    {
      const Window window = hexagon ? Hexagon() : Window::Rectangle(0.0, 1.0, 0.0, 1.0);
      const std::vector<Point2> points = UniformPoints(n, unsigned(n) + hexagon, 0.05, 0.95);
      DirichletTessellation t(window, points);
      TessellationDual dual(t);
      const TileSet tiles = dual.Tiles();
      const double total = NeumaierSum(tiles.Areas);
      EXPECT_NEAR(total, window.Area(), 1e-12 * window.Area()) << "n=" << n;
      ASSERT_EQ(dual.DegenerateFaceCount(), 0u);
      const ContiguityGraph graph = dual.Contiguities();
      EXPECT_EQ(KindCount(graph, 1), 0u);
      // Section 2.3: every contiguity counted from both sides; a point's NeighborCount counts its
      // point neighbours and its window sides, each constraint has two constraint neighbours.
      long sumNeighbors = 0;
      for (const std::int32_t c : tiles.NeighborCounts)
      {
        sumNeighbors += c;
      }
      const long pointPairs = long(KindCount(graph, 0));
      const long constraintSides = sumNeighbors - 2 * pointPairs;
      const long constraints = long(window.EffectiveConstraints().size());
      const long counted = 2 * pointPairs + 2 * constraintSides + 2 * constraints;
      EXPECT_EQ(counted, 4 * constraints + 6 * long(t.AcceptedCount()) - 6) << "n=" << n;
    }
  }
}

// The exact area of a polygon of doubles (GMP), as a double.
double ExactPolygonArea(const Point2* v, std::size_t n)
{
  std::vector<tessera_test::QPoint> ring;
  for (std::size_t k = 0; k < n; ++k)
  {
    ring.push_back({ v[k].x, v[k].y });
  }
  return tessera_test::ExactArea(ring).get_d();
}

TEST(Tiles, ThinTilesAreasAreWithinUlpsOfTheirPolygonsExactAreas)
{
  // Long thin polygons (1 long, 1e-6 or 1e-9 wide, at any slant): their products rounded, their
  // areas were a part in 1e10 off, and a million collinear points' strips summed to 3e-12 off the
  // window's area (beyond the 1e-12 the issue asks).
  std::mt19937_64 rng(41);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const double ulps = 4.0 * std::ldexp(1.0, -53);
  for (int trial = 0; trial < 2000; ++trial)
  {
    const double t = 6.283185307179586 * u(rng), w = trial % 2 ? 1e-6 : 1e-9;
    const Point2 p{ u(rng), u(rng) };
    const Point2 d{ std::cos(t), std::sin(t) }, m{ -w * std::sin(t), w * std::cos(t) };
    const Point2 quad[4] = {
      p, { p.x + d.x, p.y + d.y }, { p.x + d.x + m.x, p.y + d.y + m.y }, { p.x + m.x, p.y + m.y }
    };
    const double exact = ExactPolygonArea(quad, 4);
    ASSERT_GT(exact, 0.0);
    EXPECT_NEAR(CompensatedPolygonArea(quad, 4), exact, ulps * exact) << "trial " << trial;
  }
  // Points on a slanted line: strips across the window, each tile within ulps of its polygon's
  // exact area, and all of them summing to the window's.
  std::vector<Point2> line;
  for (int k = 0; k < 20000; ++k)
  {
    const double s = u(rng);
    line.push_back({ 0.1 + 0.8 * s, 0.2 + 0.6 * s });
  }
  const Window window = Window::Rectangle(0.0, 1.0, 0.0, 1.0);
  DirichletTessellation t(window, line);
  const TileSet tiles = TessellationDual(t).Tiles();
  for (std::size_t k = 0; k < tiles.PointIds.size(); ++k)
  {
    const std::size_t b = std::size_t(tiles.Offsets[k]), e = std::size_t(tiles.Offsets[k + 1]);
    const double exact = ExactPolygonArea(tiles.Vertices.data() + b, e - b);
    ASSERT_NEAR(tiles.Areas[k], exact, ulps * exact) << "tile of point " << tiles.PointIds[k];
  }
  EXPECT_NEAR(NeumaierSum(tiles.Areas), 1.0, 1e-14);
}

// A window given by constraints multiplied by a huge or tiny factor is the same window: the
// tiles (their points, sides and areas) must not change. Products of such coefficients used to
// overflow (factors from about 1e155) or underflow (about 1e-200), and tiles overlapped.
TEST(Tiles, ScalingTheWindowConstraintsLeavesTheTiles)
{
  const std::vector<HalfPlane> square{ { -1, 0, 0 }, { 1, 0, -1 }, { 0, -1, 0 }, { 0, 1, -1 } };
  const std::vector<HalfPlane> triangle{ { 0, -1, 0 }, { -1, 0, 0 }, { 1, 1, -1 } };
  for (const auto* shape : { &square, &triangle })
  {
    const std::vector<Point2> points =
      shape == &square ? UniformPoints(300, 77u, 0.01, 0.99) : UniformPoints(300, 78u, 0.01, 0.49);
    const Window plain(*shape);
    const DirichletTessellation reference(plain, points);
    const TileSet expected = TessellationDual(reference).Tiles();
    for (const double factor : { 1e155, 1e300, 1e-200, 1e-300, 3.0 })
    {
      std::vector<HalfPlane> scaled = *shape;
      for (HalfPlane& h : scaled)
      {
        h = { h.a * factor, h.b * factor, h.c * factor };
      }
      const Window window(scaled);
      const DirichletTessellation t(window, points);
      const TileSet tiles = TessellationDual(t).Tiles();
      const std::string where =
        std::string(shape == &square ? "square" : "triangle") + " times " + std::to_string(factor);
      EXPECT_NEAR(NeumaierSum(tiles.Areas), plain.Area(), 1e-12 * plain.Area()) << where;
      ASSERT_EQ(tiles.PointIds, expected.PointIds) << where;
      EXPECT_EQ(tiles.NeighborCounts, expected.NeighborCounts) << where;
      for (std::size_t k = 0; k < tiles.Areas.size(); ++k)
      {
        EXPECT_NEAR(tiles.Areas[k], expected.Areas[k], 1e-13) << where << ", tile " << k;
      }
    }
  }
}

// Where a tile edge leaves the window through an axis-aligned side (x = X or y = Y), its end has
// that coordinate exactly: the side's own value (a rectangle's bound, or -c/a correctly rounded
// for a constraint a*x + c < 0), so a user's test "on the side" (x == xmax) holds and tiles of a
// rectangle keep straight sides. The crossing used to be found along the bisector, m + t d, and
// landed up to some ulps off the side. Checked for both tile derivations (TileSet and TileMesh)
// against the side's value computed independently here.
TEST(Tiles, CrossingsWithAxisAlignedSidesLieExactlyOnTheSides)
{
  struct Case
  {
    std::vector<HalfPlane> constraints;
    std::vector<double> sideX, sideY; // the sides' exact coordinates
  };
  const double x0 = -3.3, x1 = 0.7, y0 = 0.1, y1 = 2.9;
  const std::vector<Case> cases{
    { { { -1, 0, x0 }, { 1, 0, -x1 }, { 0, -1, y0 }, { 0, 1, -y1 } }, { x0, x1 }, { y0, y1 } },
    // x < 2.1 / 3 and y > -1.7 / 7, with a slanted third side: -c/a of the normalized
    // constraint, which is -c/a of the given one (scaling by 2^k is exact).
    { { { 3, 0, -2.1 }, { 0, -7, -1.7 }, { -1, 1, -1 } }, { 2.1 / 3 }, { -1.7 / 7 } },
  };
  for (std::size_t c = 0; c < cases.size(); ++c)
  {
    const Window window(cases[c].constraints);
    const Box2 box = BoundsOf(window.Vertices().data(), window.Vertices().size());
    std::mt19937_64 random(100 + c);
    std::uniform_real_distribution<double> ux(box.XMin, box.XMax), uy(box.YMin, box.YMax);
    std::vector<Point2> points;
    while (points.size() < 3000)
    {
      const Point2 p{ ux(random), uy(random) };
      if (window.Contains(p))
      {
        points.push_back(p);
      }
    }
    DirichletTessellation t(window, points);
    const TileSet tiles = TessellationDual(t).Tiles();
    const TileMesh mesh = TessellationDual(t).TileMeshAndContiguities(false).Tiles;
    std::size_t onSides = 0;
    const auto check = [&](const Point2& v, const char* where)
    {
      for (const double x : cases[c].sideX)
      {
        if (std::fabs(v.x - x) <= 1e-9)
        {
          ++onSides;
          EXPECT_EQ(v.x, x) << where << " case " << c << ": a vertex " << v.x - x
                            << " off x = " << x;
        }
      }
      for (const double y : cases[c].sideY)
      {
        if (std::fabs(v.y - y) <= 1e-9)
        {
          ++onSides;
          EXPECT_EQ(v.y, y) << where << " case " << c << ": a vertex " << v.y - y
                            << " off y = " << y;
        }
      }
    };
    for (const Point2& v : tiles.Vertices)
    {
      check(v, "TileSet");
    }
    for (const Point2& v : mesh.Vertices)
    {
      check(v, "TileMesh");
    }
    EXPECT_GT(onSides, 100u) << "case " << c;
  }
}
TEST(Tiles, SquareLatticeHasSquareTilesAndDiagonalHalfNeighbours)
{
  const int side = 10;
  std::vector<Point2> points;
  for (int j = 0; j < side; ++j)
  {
    for (int i = 0; i < side; ++i)
    {
      points.push_back({ i + 0.5, j + 0.5 });
    }
  }
  DirichletTessellation t(Window::Rectangle(0.0, side, 0.0, side), points);
  TessellationDual dual(t);
  EXPECT_EQ(dual.DegenerateFaceCount(), std::size_t((side - 1) * (side - 1)));
  const TileSet tiles = dual.Tiles();
  ASSERT_EQ(tiles.PointIds.size(), points.size());
  for (std::size_t k = 0; k < points.size(); ++k)
  {
    const Point2& point = points[tiles.PointIds[k]];
    EXPECT_EQ(tiles.Offsets[k + 1] - tiles.Offsets[k], 4) << k;
    EXPECT_NEAR(tiles.Areas[k], 1.0, 1e-14);
    EXPECT_EQ(tiles.NeighborCounts[k], 4); // interior: 4 points; border: points + window sides
    for (std::int64_t v = tiles.Offsets[k]; v < tiles.Offsets[k + 1]; ++v)
    {
      EXPECT_NEAR(std::fabs(tiles.Vertices[v].x - point.x), 0.5, 1e-14);
      EXPECT_NEAR(std::fabs(tiles.Vertices[v].y - point.y), 0.5, 1e-14);
    }
  }
  const ContiguityGraph graph = dual.Contiguities();
  std::set<std::pair<int, int>> edges, diagonals;
  for (std::size_t k = 0; k < graph.Kinds.size(); ++k)
  {
    const int a = graph.Pairs[2 * k], b = graph.Pairs[2 * k + 1];
    const int dx = std::abs(a % side - b % side), dy = std::abs(a / side - b / side);
    if (graph.Kinds[k] == 0)
    {
      EXPECT_EQ(dx + dy, 1) << a << " " << b;
      edges.insert({ a, b });
    }
    else
    {
      EXPECT_EQ(dx, 1);
      EXPECT_EQ(dy, 1);
      diagonals.insert({ a, b });
    }
  }
  EXPECT_EQ(edges.size(), std::size_t(2 * side * (side - 1)));
  EXPECT_EQ(diagonals.size(), std::size_t(2 * (side - 1) * (side - 1)));

  const DelaunayFaces faces = dual.Faces(false);
  ASSERT_EQ(faces.Offsets.size(), std::size_t((side - 1) * (side - 1) + 1));
  for (std::size_t f = 0; f + 1 < faces.Offsets.size(); ++f)
  {
    EXPECT_EQ(faces.Offsets[f + 1] - faces.Offsets[f], 4);
    const std::int32_t first = faces.PointIds[faces.Offsets[f]];
    for (std::int64_t k = faces.Offsets[f]; k < faces.Offsets[f + 1]; ++k)
    {
      EXPECT_GE(faces.PointIds[k], first);
    }
  }
  const DelaunayFaces split = dual.Faces(true);
  ASSERT_EQ(split.Offsets.size(), std::size_t(2 * (side - 1) * (side - 1) + 1));
  for (std::size_t f = 0; f + 1 < split.Offsets.size(); ++f)
  {
    const std::int32_t* v = split.PointIds.data() + split.Offsets[f];
    EXPECT_GT(orient2d(points[v[0]], points[v[1]], points[v[2]]), 0);
  }
}

TEST(Tiles, DelaunayFacesAreEmptyCircleTriangles)
{
  for (unsigned seed = 1; seed <= 5; ++seed)
  {
    const std::vector<Point2> points = UniformPoints(60 * seed, seed, 0.0, 1.0);
    DirichletTessellation t(Window::Rectangle(-1, 2, -1, 2), points);
    const DelaunayFaces faces = ComputeDelaunayFaces(t, false);
    std::size_t hull = 0;
    for (std::int32_t tri = 0; tri < std::int32_t(t.Origin().size() / 3); ++tri)
    {
      hull += t.IsGhostTriangle(tri);
    }
    ASSERT_EQ(faces.Offsets.size() - 1, 2 * points.size() - 2 - hull);
    std::set<std::vector<std::int32_t>> seen;
    for (std::size_t f = 0; f + 1 < faces.Offsets.size(); ++f)
    {
      ASSERT_EQ(faces.Offsets[f + 1] - faces.Offsets[f], 3);
      const std::int32_t* v = faces.PointIds.data() + faces.Offsets[f];
      EXPECT_LT(v[0], v[1]);
      EXPECT_LT(v[0], v[2]);
      EXPECT_TRUE(seen.insert({ v[0], v[1], v[2] }).second);
      for (std::size_t q = 0; q < points.size(); ++q)
      {
        EXPECT_LE(incircle(points[v[0]], points[v[1]], points[v[2]], points[q]), 0);
      }
    }
  }
}

TEST(Tiles, EdgesOutsideTheWindowAreNotContiguities)
{
  // Two points near the bottom of a wide, flat window and one far above: the bisector of the two
  // bottom points crosses the window, but an obtuse configuration's edge can lie outside.
  const std::vector<Point2> points{ { 0.0, 0.0 }, { 2.0, 0.0 }, { 1.0, 0.05 } };
  DirichletTessellation t(Window::Rectangle(-1.0, 3.0, -0.1, 0.2), points);
  const ContiguityGraph graph = ComputeContiguityGraph(t);
  // The Voronoi edge between 0 and 1 runs from the circumcentre (1, about -9.975) downwards:
  // entirely below the window.
  std::set<std::pair<int, int>> pairs;
  for (std::size_t k = 0; k < graph.Kinds.size(); ++k)
  {
    pairs.insert({ graph.Pairs[2 * k], graph.Pairs[2 * k + 1] });
  }
  EXPECT_EQ(pairs, (std::set<std::pair<int, int>>{ { 0, 2 }, { 1, 2 } }));
  const TileSet tiles = ComputeTiles(t);
  EXPECT_NEAR(NeumaierSum(tiles.Areas), 4.0 * 0.3, 1e-14);
}

// ---------------------------------------------------------------------------------------------
// Exact window decisions: contiguities against an exact rational brute force, and the two
// engines against each other, on inputs whose Voronoi vertices and edges meet the window
// boundary exactly or nearly.

namespace
{

// For each pair of accepted points, the Voronoi edge on the bisector m + t d is cut by every
// other point's half-plane and the window's: each is alpha + beta t < 0 (open, for kind 0) or
// <= 0 (closed point constraints, for kind 1), all in exact rationals. Kind 0: the open interval
// is non-empty. Kind 1: the closed point constraints leave a single t, strictly inside the
// window. A double pass with a wide margin skips pairs that are far from either.
PairKinds BruteForcePairs(const Window& window,
  const std::vector<Point2>& points,
  const std::vector<std::int32_t>& ids)
{
  PairKinds pairs;
  const auto& constraints = window.EffectiveConstraints();
  for (std::size_t x = 0; x < ids.size(); ++x)
  {
    for (std::size_t y = x + 1; y < ids.size(); ++y)
    {
      const Point2 &pi = points[ids[x]], &pj = points[ids[y]];
      // Double pre-pass, relative to pi (translation-free): the closed interval of the point
      // constraints, skipped only when empty by a wide margin.
      {
        const double mx = 0.5 * (pj.x - pi.x), my = 0.5 * (pj.y - pi.y);
        const double dx = pi.y - pj.y, dy = pj.x - pi.x;
        double lo = -1e300, hi = 1e300;
        const auto cut = [&](double alpha, double beta)
        {
          if (beta > 0)
          {
            hi = std::min(hi, -alpha / beta);
          }
          else if (beta < 0)
          {
            lo = std::max(lo, -alpha / beta);
          }
          else if (alpha > 1e-9)
          {
            lo = 1e300;
          }
        };
        for (const std::int32_t k : ids)
        {
          if (k == ids[x] || k == ids[y])
          {
            continue;
          }
          const double ex = points[k].x - pi.x, ey = points[k].y - pi.y;
          cut(2 * (mx * ex + my * ey) - (ex * ex + ey * ey), 2 * (dx * ex + dy * ey));
        }
        for (const HalfPlane& h : constraints)
        {
          cut(h.a * mx + h.b * my + (h.a * pi.x + h.b * pi.y + h.c), h.a * dx + h.b * dy);
        }
        const double scale = 1.0 + std::fabs(lo < -1e299 ? 0 : lo) + std::fabs(hi > 1e299 ? 0 : hi);
        if (lo > hi + 1e-3 * scale)
        {
          continue;
        }
      }
      const mpq_class mx = (mpq_class(pi.x) + pj.x) / 2, my = (mpq_class(pi.y) + pj.y) / 2;
      const mpq_class dx = mpq_class(pi.y) - pj.y, dy = mpq_class(pj.x) - pi.x;
      bool haveLo = false, haveHi = false, empty = false;
      mpq_class lo, hi;         // open interval (points and window)
      bool closedEmpty = false; // closed point constraints only
      bool cHaveLo = false, cHaveHi = false;
      mpq_class clo, chi;
      const auto cut = [&](const mpq_class& alpha, const mpq_class& beta, bool point)
      {
        if (sgn(beta) == 0)
        {
          empty = empty || sgn(alpha) >= 0;
          closedEmpty = closedEmpty || (point && sgn(alpha) > 0);
          return;
        }
        const mpq_class t = -alpha / beta;
        if (sgn(beta) > 0)
        {
          if (!haveHi || t < hi)
          {
            hi = t;
            haveHi = true;
          }
          if (point && (!cHaveHi || t < chi))
          {
            chi = t;
            cHaveHi = true;
          }
        }
        else
        {
          if (!haveLo || t > lo)
          {
            lo = t;
            haveLo = true;
          }
          if (point && (!cHaveLo || t > clo))
          {
            clo = t;
            cHaveLo = true;
          }
        }
      };
      const mpq_class ni = mpq_class(pi.x) * pi.x + mpq_class(pi.y) * pi.y;
      for (const std::int32_t k : ids)
      {
        if (k == ids[x] || k == ids[y])
        {
          continue;
        }
        const Point2& pk = points[k];
        const mpq_class ex = mpq_class(pk.x) - pi.x, ey = mpq_class(pk.y) - pi.y;
        const mpq_class nk = mpq_class(pk.x) * pk.x + mpq_class(pk.y) * pk.y;
        cut(2 * (mx * ex + my * ey) + ni - nk, 2 * (dx * ex + dy * ey), true);
      }
      for (const HalfPlane& h : constraints)
      {
        cut(h.a * mx + h.b * my + mpq_class(h.c), h.a * dx + h.b * dy, false);
      }
      const std::pair<std::int32_t, std::int32_t> key(
        std::min(ids[x], ids[y]), std::max(ids[x], ids[y]));
      if (!empty && haveLo && haveHi && lo < hi)
      {
        pairs[key] = 0;
        continue;
      }
      if (closedEmpty || !cHaveLo || !cHaveHi || clo != chi)
      {
        continue;
      }
      const mpq_class vx = mx + clo * dx, vy = my + clo * dy;
      bool inside = true;
      for (const HalfPlane& h : constraints)
      {
        inside = inside && sgn(h.a * vx + h.b * vy + mpq_class(h.c)) < 0;
      }
      if (inside)
      {
        pairs[key] = 1;
      }
    }
  }
  return pairs;
}

void ExpectExactContiguities(const Window& window, const std::vector<Point2>& points, bool sweep)
{
  const DirichletTessellation t(window, points);
  const TessellationDual dual(t);
  const PairKinds ours = GraphPairs(dual.Contiguities());
  const PairKinds exact = BruteForcePairs(window, points, tessera_test::AcceptedIds(t));
  for (const auto& [pair, kind] : exact)
  {
    const auto found = ours.find(pair);
    EXPECT_TRUE(found != ours.end() && found->second == kind)
      << "missing pair (" << pair.first << ", " << pair.second << ") kind " << kind;
  }
  for (const auto& [pair, kind] : ours)
  {
    EXPECT_TRUE(exact.count(pair))
      << "spurious pair (" << pair.first << ", " << pair.second << ") kind " << kind;
  }
  // NeighborCount: contiguities with points plus window edges; the point part must match.
  const TileSet tiles = dual.Tiles();
  std::map<std::int32_t, std::int32_t> kind0;
  for (const auto& [pair, kind] : exact)
  {
    if (kind == 0)
    {
      ++kind0[pair.first];
      ++kind0[pair.second];
    }
  }
  for (std::size_t k = 0; k < tiles.PointIds.size(); ++k)
  {
    EXPECT_GE(tiles.NeighborCounts[k], kind0[tiles.PointIds[k]]);
    EXPECT_LE(tiles.NeighborCounts[k],
      kind0[tiles.PointIds[k]] + std::int32_t(window.EffectiveConstraints().size()));
  }
  if (!sweep)
  {
    return;
  }
  const ThiessenSweepResult other = ComputeThiessenSweep(window, points);
  EXPECT_EQ(GraphPairs(other.Contiguities), ours);
  std::map<std::int32_t, double> areas;
  for (std::size_t k = 0; k < tiles.PointIds.size(); ++k)
  {
    areas[tiles.PointIds[k]] = tiles.Areas[k];
  }
  ASSERT_EQ(other.Tiles.PointIds.size(), tiles.PointIds.size());
  for (std::size_t k = 0; k < other.Tiles.PointIds.size(); ++k)
  {
    EXPECT_NEAR(other.Tiles.Areas[k], areas[other.Tiles.PointIds[k]], 1e-12 * window.Area());
    EXPECT_EQ(other.Tiles.NeighborCounts[k],
      tiles.NeighborCounts[std::size_t(
        std::find(tiles.PointIds.begin(), tiles.PointIds.end(), other.Tiles.PointIds[k]) -
        tiles.PointIds.begin())])
      << "point " << other.Tiles.PointIds[k];
  }
}

} // namespace

TEST(TilesExactWindow, RotatedLattice)
{
  const double angle = 0.3, c = std::cos(angle), s = std::sin(angle);
  std::vector<Point2> points;
  for (int i = 0; i < 20; ++i)
  {
    for (int j = 0; j < 20; ++j)
    {
      const double x = i / 20.0 - 0.5, y = j / 20.0 - 0.5;
      points.push_back({ 0.5 + c * x - s * y, 0.5 + s * x + c * y });
    }
  }
  const Window window = Window::Rectangle(-0.5, 1.5, -0.5, 1.5);
  ExpectExactContiguities(window, points, true);
  // The pairs measured wrong in floating point, by index i * 20 + j.
  const PairKinds ours = GraphPairs(ComputeContiguityGraph(DirichletTessellation(window, points)));
  EXPECT_EQ(ours.count({ 0, 140 }), 0U);
  EXPECT_EQ(ours.count({ 6, 13 }), 0U);
  EXPECT_EQ(ours.count({ 0, 20 }), 1U);
  EXPECT_EQ(ours.count({ 12, 13 }), 1U);
}

// Subsets of the grid of odd multiples of 1/16 in the unit square: many exactly co-circular
// vertices, some exactly on the window's sides and corners (even multiples of 1/16).
TEST(TilesExactWindow, GridSubsetsTouchingTheBoundary)
{
  std::mt19937_64 rng(5);
  for (int trial = 0; trial < 40; ++trial)
  {
    std::vector<Point2> points;
    const double keep = 0.25 + 0.05 * (trial % 10);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    for (int i = 0; i < 8; ++i)
    {
      for (int j = 0; j < 8; ++j)
      {
        if (u(rng) < keep)
        {
          points.push_back({ (2 * i + 1) / 16.0, (2 * j + 1) / 16.0 });
        }
      }
    }
    if (points.size() < 3)
    {
      continue;
    }
    ExpectExactContiguities(Window::Rectangle(0, 1, 0, 1), points, true);
    // Windows whose sides are lattice lines inside the point set (points beyond are rejected).
    ExpectExactContiguities(Window::Rectangle(0.125, 0.875, 0, 0.75), points, true);
    // The same shifted by 2^30 (still exact): the filters see huge translations.
    if (trial % 4 == 0)
    {
      const double base = std::ldexp(1.0, 30);
      std::vector<Point2> shifted = points;
      for (Point2& p : shifted)
      {
        p = { p.x + base, p.y + base };
      }
      ExpectExactContiguities(
        Window::Rectangle(base + 0.125, base + 0.875, base, base + 0.75), shifted, true);
    }
  }
}

// Tiny perturbations of such sets (filters fail, the exact tier decides), and a window with
// oblique sides through grid points.
TEST(TilesExactWindow, NearDegenerateSetsAndObliqueWindow)
{
  std::mt19937_64 rng(9);
  const Window oblique(
    { { -1, 0, 0 }, { 0, -1, 0 }, { 1, 1, -1.5 }, { 1, 0, -1 }, { 0, 1, -1 }, { 1, -1, -0.625 } });
  for (int trial = 0; trial < 30; ++trial)
  {
    std::vector<Point2> points;
    std::uniform_real_distribution<double> u(0.0, 1.0);
    for (int i = 0; i < 8; ++i)
    {
      for (int j = 0; j < 8; ++j)
      {
        if (u(rng) < 0.4)
        {
          Point2 p{ (2 * i + 1) / 16.0, (2 * j + 1) / 16.0 };
          if (trial % 2 == 1 && u(rng) < 0.3)
          {
            p.x += std::ldexp(u(rng) < 0.5 ? -1.0 : 1.0, -45 - int(rng() % 8));
          }
          points.push_back(p);
        }
      }
    }
    if (points.size() < 3)
    {
      continue;
    }
    ExpectExactContiguities(Window::Rectangle(0, 1, 0, 1), points, true);
    ExpectExactContiguities(oblique, points, false);
  }
}

TEST(Tiles, FastDelaunayFacesEqualTheDualsFaces)
{
  // ComputeDelaunayFaces skips the dual when no two neighbouring triangles are co-circular: it
  // must list exactly what TessellationDual::Faces lists, also after removals left free
  // triangles, and fall back to the dual when a face is degenerate.
  std::mt19937_64 random(99);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int round = 0; round < 6; ++round)
  {
    std::vector<tessera::Point2> points(400);
    for (auto& p : points)
    {
      p = { u(random), u(random) };
    }
    if (round % 2 == 1)
    {
      for (int k = 0; k < 25; ++k) // a lattice patch: co-circular squares
      {
        points[k] = { 0.3 + 0.01 * (k % 5), 0.3 + 0.01 * (k / 5) };
      }
    }
    tessera::DirichletTessellation t(tessera::Window::Rectangle(-0.5, 1.5, -0.5, 1.5), points);
    if (round >= 2)
    {
      for (std::int32_t id = 100; id < 160; ++id)
      {
        t.Remove(id);
      }
    }
    for (bool split : { false, true })
    {
      const tessera::DelaunayFaces fast = tessera::ComputeDelaunayFaces(t, split);
      const tessera::DelaunayFaces dual = tessera::TessellationDual(t).Faces(split);
      EXPECT_EQ(fast.Offsets, dual.Offsets) << "round " << round;
      EXPECT_EQ(fast.PointIds, dual.PointIds) << "round " << round;
    }
    // The same fast path writing into the caller's arrays: all or nothing.
    const std::size_t capacity = tessera::DelaunayFaceCapacity(t);
    std::vector<std::int32_t> ids(3 * capacity, -7), offsets(capacity + 1, -7);
    const std::int64_t count = tessera::WriteTriangularDelaunayFaces(t, ids.data(), offsets.data());
    const tessera::TessellationDual dual(t);
    if (dual.DegenerateFaceCount() > 0)
    {
      EXPECT_EQ(count, -1) << "round " << round;
      continue;
    }
    const tessera::DelaunayFaces faces = dual.Faces(false);
    ASSERT_EQ(count + 1, std::int64_t(faces.Offsets.size())) << "round " << round;
    ids.resize(3 * std::size_t(count));
    offsets.resize(std::size_t(count) + 1);
    EXPECT_EQ(ids, faces.PointIds) << "round " << round;
    EXPECT_EQ(offsets, faces.Offsets) << "round " << round;
  }
}

// Inputs for the derivation tests: uniform points, a lattice (degenerate faces, half-neighbours),
// uniform points with a lattice patch and the first 100 ids removed, collinear points, and the
// extra ones given. Each is tessellated in a rectangle and in an oblique triangle that clips many
// tiles, points removed, and handed to check(tessellation, name).
struct DerivationInput
{
  std::string Name;
  std::vector<Point2> Points;
  std::int32_t RemoveBelow = 0; ///< ids below this ...
  std::int32_t RemoveEvery = 1; ///< ... and multiples of this are removed after the build
};

template<class Check>
void ForEachDerivationInput(std::vector<DerivationInput> inputs, const Check& check)
{
  std::vector<Point2> mixed = UniformPoints(800, 6);
  const std::vector<Point2> patch = tessera_test::SquareLattice(6, 50.0);
  mixed.insert(mixed.end(), patch.begin(), patch.end());
  inputs.insert(inputs.begin(),
    { { "uniform", UniformPoints(3000, 5) },
      { "lattice", tessera_test::SquareLattice(30, 30.0) },
      { "mixed, 100 removed", mixed, 100 },
      { "collinear", { { 0.1, 0.1 }, { 0.3, 0.3 }, { 0.5, 0.5 }, { 0.9, 0.9 } } } });
  const Window oblique({ { 1.0, 1.0, -1.6 }, { -1.0, 0.2, -0.3 }, { 0.1, -1.0, -0.2 } });
  for (const DerivationInput& input : inputs)
  {
    for (const Window& window : { Window::Rectangle(-0.1, 1.1, -0.1, 1.1), oblique })
    {
      DirichletTessellation t(window, input.Points);
      for (std::int32_t id = 0; id < input.RemoveBelow; id += input.RemoveEvery)
      {
        if (t.Status(id) == PointStatus::Accepted)
        {
          t.Remove(id);
        }
      }
      check(t, input.Name);
    }
  }
}

// A TileMesh column (an UninitializedVector) as a std::vector, to compare with a TileSet's.
template<class T>
std::vector<T> Plain(const tessera::UninitializedVector<T>& column)
{
  return { column.begin(), column.end() };
}

// TilesAndContiguities walks each ring once for both results, sharing one chunk's scratch
// buffers, and lists an interior tile's contiguities straight from its ring (Contiguities() alone
// checks every ring edge's faces): it must give exactly what the two separate passes give. (Whether
// the results themselves are right is what the exact tests above check: all three share Derive.)
TEST(Tiles, TilesAndContiguitiesEqualTheSeparatePasses)
{
  ForEachDerivationInput({},
    [](const DirichletTessellation& t, const std::string& set)
    {
      const TessellationDual dual(t);
      const TilesAndGraph both = dual.TilesAndContiguities();
      const TileSet tiles = dual.Tiles();
      const ContiguityGraph graph = dual.Contiguities();
      EXPECT_EQ(both.Tiles.PointIds, tiles.PointIds) << "set " << set;
      EXPECT_EQ(both.Tiles.Offsets, tiles.Offsets) << "set " << set;
      EXPECT_TRUE(both.Tiles.Vertices == tiles.Vertices) << "set " << set;
      EXPECT_EQ(both.Tiles.Areas, tiles.Areas) << "set " << set;
      EXPECT_EQ(both.Tiles.NeighborCounts, tiles.NeighborCounts) << "set " << set;
      EXPECT_EQ(both.Graph.Pairs, graph.Pairs) << "set " << set;
      EXPECT_EQ(both.Graph.Kinds, graph.Kinds) << "set " << set;
      EXPECT_GT(graph.Pairs.size(), 0u) << "set " << set;
    });
}

TEST(Tiles, DroppingRepeatedVerticesAlsoDropsSpikes)
{
  // Vertices by letter; tags are the positions in the given ring. A spike X, Y, X keeps one X
  // (the tags of the two X merged) and drops Y; anywhere in the ring, also across its end.
  const std::map<char, Point2> at = { { 'A', { 0, 0 } },
    { 'B', { 1e-16, 0 } },
    { 'C', { 1, 0 } },
    { 'D', { 1, 1 } },
    { 'E', { 0, 1 } } };
  struct Case
  {
    const char* Given;
    const char* Kept;
    std::vector<std::pair<int, int>> Merged;
  };
  for (const Case& c : { Case{ "ABACDE", "ACDE", { { 0, 2 } } },
         Case{ "CDEABA", "CDEA", { { 3, 5 } } },
         Case{ "BACDEA", "ACDE", { { 1, 5 } } }, // A (5), B (0), A (1): across the end
         Case{ "ACDEAB", "ACDE", { { 0, 4 } } }, // A (4), B (5), A (0): across the end
         Case{ "AABAACD", "ACD", { { 0, 1 }, { 0, 3 }, { 0, 4 } } },
         Case{ "ACDE", "ACDE", {} } })
  {
    std::vector<Point2> polygon;
    std::vector<int> tags;
    for (const char* v = c.Given; *v; ++v)
    {
      polygon.push_back(at.at(*v));
      tags.push_back(int(v - c.Given));
    }
    std::vector<std::pair<int, int>> merged;
    DropRepeatedVertices(polygon, tags, &merged);
    std::string kept;
    for (std::size_t k = 0; k < polygon.size(); ++k)
    {
      for (const auto& [letter, p] : at)
      {
        kept += p == polygon[k] ? std::string(1, letter) : std::string();
      }
      EXPECT_TRUE(polygon[k] == at.at(c.Given[tags[k]])) << c.Given << ": tag " << tags[k];
    }
    EXPECT_EQ(kept, c.Kept) << c.Given;
    EXPECT_EQ(merged, c.Merged) << c.Given;
    std::vector<Point2> untagged;
    for (const char* v = c.Given; *v; ++v)
    {
      untagged.push_back(at.at(*v));
    }
    DropRepeatedVertices(untagged);
    EXPECT_EQ(untagged.size(), polygon.size()) << c.Given;
  }
}

// Five points near the circle of radius 0.3 about (0.5, 0.5), not on it: three Voronoi vertices
// some 1e-17 apart near the centre, two of which round to one point, the third an ulp away. The
// tile around them went out to the third and back (a spike: vertex ids 1 0 8 5 9 0, the side 0-1
// used by four tiles' sides).
std::vector<Point2> NearlyCocircularFive()
{
  return { { 0x1.99991bc569925p-1, 0x1.00c49b7033733p-1 },
    { 0x1.2ebbe7fde48bep-1, 0x1.925159f5ef30bp-1 },
    { 0x1.0691fc019d6d4p-2, 0x1.59a94f2263138p-1 },
    { 0x1.08603c509e002p-2, 0x1.4a3125c6915e6p-2 },
    { 0x1.3031e013942b2p-1, 0x1.b8a0a250c6664p-3 } };
}

// Points on a convex arc: each joined to many others, so the tiles of the first and last have
// hundreds of sides, clipped by the window (their mesh vertices are found through an index of
// their edges' ends).
std::vector<Point2> PointsOnAParabola(int n)
{
  std::vector<Point2> points;
  for (int k = 0; k < n; ++k)
  {
    const double t = double(k) / n;
    points.push_back({ 0.1 + 0.8 * t, 0.1 + 0.8 * t * t });
  }
  return points;
}

// The mesh form of the tiles (what vtkDirichletTessellation writes): tile for tile the same
// polygons, bit for bit, areas and side counts as Tiles(), the same contiguities, and a
// conforming mesh: every vertex is used, no two vertices coincide (tiles that meet share the
// vertex), and every polygon side is also a side of the neighbouring tile, by vertex ids, unless
// it runs along the window boundary. 12,000 points make two chunks, whose crossings are merged.
TEST(Tiles, TileMeshExpandsToTheTilesAndIsConforming)
{
  const std::vector<Point2> parabola = PointsOnAParabola(400);
  {
    const TileSet tiles =
      ComputeTiles(DirichletTessellation(Window::Rectangle(0, 1, 0, 1), parabola));
    std::int64_t most = 0;
    for (std::size_t k = 0; k + 1 < tiles.Offsets.size(); ++k)
    {
      most = std::max(most, tiles.Offsets[k + 1] - tiles.Offsets[k]);
    }
    ASSERT_GT(most, 100); // the premise
  }
  // A lattice spaced 1/29 with every other point of a patch removed: distinct faces whose rounded
  // centres coincide, which one tile lists once and its neighbours each by their own face.
  ForEachDerivationInput({ { "uniform, two chunks", UniformPoints(12000, 7) },
                           { "checkerboard patch", tessera_test::SquareLattice(31, 29.0), 299, 2 },
                           { "one point", { { 0.4, 0.6 } } },
                           { "no point", {} },
                           { "five points nearly on a circle", NearlyCocircularFive() },
                           { "400 points on a parabola", parabola } },
    [](const DirichletTessellation& t, const std::string& set)
    {
      TessellationDual dual(t);
      const TilesAndGraph both = dual.TilesAndContiguities();
      const TileMeshAndGraph mesh = dual.TileMeshAndContiguities();
      const TileSet& tiles = both.Tiles;
      EXPECT_EQ(Plain(mesh.Tiles.PointIds), tiles.PointIds) << "set " << set;
      EXPECT_EQ(Plain(mesh.Tiles.Offsets), tiles.Offsets) << "set " << set;
      EXPECT_EQ(Plain(mesh.Tiles.Areas), tiles.Areas) << "set " << set;
      EXPECT_EQ(Plain(mesh.Tiles.NeighborCounts), tiles.NeighborCounts) << "set " << set;
      EXPECT_EQ(mesh.Graph.Pairs, both.Graph.Pairs) << "set " << set;
      EXPECT_EQ(mesh.Graph.Kinds, both.Graph.Kinds) << "set " << set;
      const auto& vertices = mesh.Tiles.Vertices;
      ASSERT_EQ(mesh.Tiles.VertexIds.size(), tiles.Vertices.size()) << "set " << set;
      std::vector<int> uses(vertices.size(), 0);
      for (std::size_t v = 0; v < tiles.Vertices.size(); ++v)
      {
        const std::int32_t id = mesh.Tiles.VertexIds[v];
        ASSERT_TRUE(id >= 0 && std::size_t(id) < vertices.size()) << "set " << set;
        ASSERT_EQ(std::memcmp(&vertices[id], &tiles.Vertices[v], sizeof(Point2)), 0)
          << "set " << set << " vertex " << v;
        ++uses[std::size_t(id)];
      }
      EXPECT_EQ(std::count(uses.begin(), uses.end(), 0), 0) << "set " << set;
      std::set<std::pair<double, double>> distinct;
      for (const Point2& p : vertices)
      {
        distinct.emplace(p.x, p.y);
      }
      EXPECT_EQ(distinct.size(), vertices.size()) << "set " << set;
      // Sides by vertex ids; an unmatched side must lie on a window line. Each tile is a simple
      // polygon: no vertex twice, and no side used twice in one direction over all tiles.
      std::set<std::pair<std::int32_t, std::int32_t>> sides;
      const auto& offsets = mesh.Tiles.Offsets;
      for (std::size_t k = 0; k + 1 < offsets.size(); ++k)
      {
        std::set<std::int32_t> own;
        for (std::int64_t v = offsets[k]; v < offsets[k + 1]; ++v)
        {
          const std::int64_t w = v + 1 < offsets[k + 1] ? v + 1 : offsets[k];
          EXPECT_TRUE(own.insert(mesh.Tiles.VertexIds[v]).second)
            << "set " << set << ": tile " << k << " has vertex " << mesh.Tiles.VertexIds[v]
            << " twice";
          EXPECT_TRUE(sides.emplace(mesh.Tiles.VertexIds[v], mesh.Tiles.VertexIds[w]).second)
            << "set " << set << ": side " << mesh.Tiles.VertexIds[v] << "-"
            << mesh.Tiles.VertexIds[w] << " used twice";
        }
      }
      const auto onOneLine = [&](const Point2& a, const Point2& b)
      {
        for (const HalfPlane& h : t.GetWindow().EffectiveConstraints())
        {
          const double norm = std::hypot(h.a, h.b);
          if (std::abs(h.a * a.x + h.b * a.y + h.c) <= 1e-12 * norm &&
            std::abs(h.a * b.x + h.b * b.y + h.c) <= 1e-12 * norm)
          {
            return true;
          }
        }
        return false;
      };
      std::size_t boundarySides = 0;
      for (const auto& [a, b] : sides)
      {
        if (!sides.count({ b, a }))
        {
          ++boundarySides;
          EXPECT_TRUE(onOneLine(vertices[a], vertices[b]))
            << "set " << set << ": side " << a << "-" << b << " has no twin";
        }
      }
      if (t.AcceptedCount() > 0)
      {
        EXPECT_GE(boundarySides, t.GetWindow().EffectiveConstraints().size()) << "set " << set;
      }
    });
}

// The 324 integer points of the circle x^2 + y^2 = 32045^2 (32045 = 5 * 13 * 17 * 29), scaled
// by 2^-16 (exactly) about (0.5, 0.5): one Delaunay face of 324 co-circular points, 52,002
// half-neighbour pairs. With uniform points outside the circle around it.
std::vector<Point2> BigCircleAmidUniformPoints(std::size_t outside)
{
  const std::int64_t radius = 32045;
  std::vector<Point2> points;
  for (std::int64_t x = -radius; x <= radius; ++x)
  {
    const std::int64_t rest = radius * radius - x * x;
    const auto y = std::int64_t(std::llround(std::sqrt(double(rest))));
    if (y * y != rest)
    {
      continue;
    }
    points.push_back({ 0.5 + double(x) / 65536.0, 0.5 + double(y) / 65536.0 });
    if (y != 0)
    {
      points.push_back({ 0.5 + double(x) / 65536.0, 0.5 - double(y) / 65536.0 });
    }
  }
  for (const Point2& p : UniformPoints(3 * outside, 12, -0.1, 1.1))
  {
    const double dx = p.x - 0.5, dy = p.y - 0.5;
    if (points.size() < outside + 324 && dx * dx + dy * dy > 0.25)
    {
      points.push_back(p);
    }
  }
  return points;
}

// Each derivation runs in chunks joined in order: the results, bit for bit, must not depend on
// how many threads there are. TESSERA_THREADS forces 1, 2, 3 and 7 chunks on any machine for the
// inputs with enough points (chunks hold at least MinimumTilesPerThread tiles), so the joins
// (crossings renumbered and merged, coinciding centres merged, vertex ids and pairs slid together
// or, when a chunk outgrew its estimated share, copied) run whatever the cores. The big circle's
// half-neighbour pairs all fall to the chunks that hold its points, more than their share: those
// spill. The smaller inputs ForEachDerivationInput adds run in one chunk: for them this only
// checks that the derivation is repeatable.
TEST(Tiles, DerivedResultsDoNotDependOnTheThreadCount)
{
  const std::vector<Point2> circle = BigCircleAmidUniformPoints(26000);
  ASSERT_EQ(circle.size(), 26324u);
  const std::vector<std::string> chunked = {
    "uniform, many chunks", "checkerboard patches, many chunks", "big circle, many chunks"
  };
  ForEachDerivationInput(
    { { "uniform, many chunks", UniformPoints(40000, 11) },
      { "checkerboard patch", tessera_test::SquareLattice(31, 29.0), 299, 2 },
      { "checkerboard patches, many chunks", tessera_test::SquareLattice(170, 165.0), 28900, 7 },
      { "big circle, many chunks", circle } },
    [&](const DirichletTessellation& t, const std::string& set)
    {
      if (std::find(chunked.begin(), chunked.end(), set) != chunked.end())
      {
        ASSERT_GE(t.AcceptedCount(), 7 * TessellationDual::MinimumTilesPerThread) << set;
      }
      const auto derive = [&](int threads)
      {
        const tessera_test::ThreadLimitOverride limit(threads);
        TessellationDual dual(t);
        return std::make_pair(dual.TileMeshAndContiguities(), dual.TilesAndContiguities());
      };
      const auto serial = derive(1);
      for (const int threads : { 2, 3, 7 })
      {
        const auto chunked = derive(threads);
        const TileMesh& a = serial.first.Tiles;
        const TileMesh& b = chunked.first.Tiles;
        EXPECT_EQ(a.PointIds, b.PointIds) << set << ", " << threads << " threads";
        EXPECT_EQ(a.Offsets, b.Offsets) << set << ", " << threads << " threads";
        EXPECT_EQ(a.VertexIds, b.VertexIds) << set << ", " << threads << " threads";
        ASSERT_EQ(a.Vertices.size(), b.Vertices.size()) << set << ", " << threads << " threads";
        EXPECT_EQ(
          std::memcmp(a.Vertices.data(), b.Vertices.data(), a.Vertices.size() * sizeof(Point2)), 0)
          << set << ", " << threads << " threads";
        EXPECT_EQ(a.Areas, b.Areas) << set << ", " << threads << " threads";
        EXPECT_EQ(serial.first.Graph.Pairs, chunked.first.Graph.Pairs) << set << ", " << threads;
        EXPECT_EQ(serial.first.Graph.Kinds, chunked.first.Graph.Kinds) << set << ", " << threads;
        const TileSet& c = serial.second.Tiles;
        const TileSet& d = chunked.second.Tiles;
        EXPECT_EQ(c.Offsets, d.Offsets) << set << ", " << threads << " threads";
        ASSERT_EQ(c.Vertices.size(), d.Vertices.size()) << set << ", " << threads << " threads";
        EXPECT_EQ(
          std::memcmp(c.Vertices.data(), d.Vertices.data(), c.Vertices.size() * sizeof(Point2)), 0)
          << set << ", " << threads << " threads";
        EXPECT_EQ(serial.second.Graph.Pairs, chunked.second.Graph.Pairs) << set << ", " << threads;
      }
    });
}

TEST(Tiles, SliverTrianglesGiveAccurateTilesInBothEngines)
{
  // Two points an ulp or a few ulps apart and one far away: the Voronoi vertex of such a sliver,
  // computed relative to the far point, once came out NaN (the rounded area cancelled to 0) or
  // far off (squared lengths cancelling: 100 m off for points 3e-13 apart and 650 m away), so
  // that tiles folded and a tile area was -427880 instead of 1.4e-9. Found by fuzzers.
  struct Case
  {
    Window TheWindow;
    std::vector<Point2> Points;
  };
  const std::vector<Case> cases{
    { Window::Rectangle(-2, 2, -2, 2), { { -0.9, -0.9 }, { 0.5, 1 }, { 0.49999999999999994, 1 } } },
    { Window::Rectangle(-18.5, 20.5, -11.5, 20.5),
      { { 8, -4 }, { 4, -2.0000000000000004 }, { 4, -2 } } },
    { Window::Rectangle(-20000, 20000, -20000, 20000),
      { { 43.464033582254537, -1075.1446211870732 },
        { -458.94559721606407, -1499.933501380531 },
        { -458.94559721606379, -1499.933501380531 },
        { -458.94559721606339, -1499.933501380531 },
        { 318.33129978483834, -8718.9008964872755 },
        { 445.89589776923708, 8625.0844053565652 } } },
  };
  for (std::size_t c = 0; c < cases.size(); ++c)
  {
    const Window& window = cases[c].TheWindow;
    const std::vector<Point2>& points = cases[c].Points;
    const double windowArea = window.Area();
    const TileSet green = ComputeTiles(DirichletTessellation(window, points));
    const TileSet sweep = ComputeThiessenSweep(window, points).Tiles;
    for (const TileSet* tiles : { &green, &sweep })
    {
      ASSERT_EQ(tiles->PointIds.size(), points.size()) << "case " << c;
      for (std::size_t k = 0; k < tiles->PointIds.size(); ++k)
      {
        const std::int32_t id = tiles->PointIds[k];
        const double exact = ExactTileArea(window, points, std::size_t(id)).get_d();
        // Rounded vertices of a sliver's tile err by ulps of the coordinates, times the tile's
        // length: 1e-12 of the window's area bounds that here.
        EXPECT_NEAR(tiles->Areas[k], exact, 1e-12 * windowArea)
          << "case " << c << " point " << id << (tiles == &green ? " (Green-Sibson)" : " (sweep)");
        EXPECT_GE(tiles->Areas[k], 0.0) << "case " << c << " point " << id;
      }
    }
  }
}

TEST(Tiles, IllConditionedCircumcentresAreAccurateInBothEngines)
{
  // Nearly collinear triples whose sides cannot be taken exactly in doubles: points near the
  // origin of very different exponents (the rounded differences moved a Voronoi vertex 2.66 along
  // the sliver, and a tile lost 6% of its area to a fold), and points a subnormal distance apart
  // (their squared sides underflowed: a vertex 12.6 off, or NaN). Found by a fuzzer feeding the
  // engine's tiles to the clip's convexity check. (Cases 1 and 2 have subnormal coordinates,
  // below the range of Green-Sibson's exact window predicates, window_predicates.h, whose products
  // underflow: its derivations refuse them, naming a point, and only the sweep's tiles are
  // checked.)
  struct Case
  {
    Window TheWindow;
    std::vector<Point2> Points;
    bool InWindowPredicateRange = true;
  };
  const std::vector<Case> cases{
    { Window::Rectangle(
        -18.600000000000005, 18.600000000000005, -18.600000000000005, 18.600000000000005),
      { { -2.0785436575227139e-20, 1.8510946363174358e-19 },
        { -1.9358563297209613e-19, 1.7240211701391554e-18 },
        { -1.1673428471637033e-12, 1.0396038954390572e-11 },
        { -5.02503548306755e-19, 4.4751603827736716e-18 } } },
    { Window::Rectangle(
        32752.499999999985, 32783.500000000022, -15.500000000000005, 15.500000000000009),
      { { 32768.000000000007, -4.9406564584124654e-324 },
        { 32768.000000000007, 4.9406564584124654e-324 },
        { 32767.999999999996, -1.2956746786585429e-11 },
        { 32778.31555423377, -12.589394815025768 } },
      false },
    { Window::Rectangle(
        -18599999999.998409, 18600000000.001831, -18599999999.999393, 18599999999.99966),
      { { 0.0008638645354608574, 0.00016253665080513281 },
        { 4.0118130442309219e-321, -1.7489923862780128e-321 },
        { -3.8932372892290228e-321, -3.6017385581826873e-321 },
        { 15500000000.001797, 15499999999.999725 } },
      false },
  };
  for (std::size_t c = 0; c < cases.size(); ++c)
  {
    const Window& window = cases[c].TheWindow;
    const std::vector<Point2>& points = cases[c].Points;
    // Vertices rounded to some ulps of the window's coordinates, along the window's perimeter.
    const Box2 box = BoundsOf(window.Vertices().data(), window.Vertices().size());
    const double magnitude = std::max(std::max(std::abs(box.XMin), std::abs(box.XMax)),
      std::max(std::abs(box.YMin), std::abs(box.YMax)));
    const double tolerance = 16.0 * std::numeric_limits<double>::epsilon() * magnitude * 2.0 *
      ((box.XMax - box.XMin) + (box.YMax - box.YMin));
    const std::vector<std::size_t> ringOffsets{ 0, window.Vertices().size() };
    const Catchment catchment(ringOffsets, window.Vertices());
    const DirichletTessellation tessellation(window, points);
    if (!cases[c].InWindowPredicateRange)
    {
      EXPECT_THROW(ComputeTiles(tessellation), InputError) << "case " << c;
    }
    const TileSet green = cases[c].InWindowPredicateRange ? ComputeTiles(tessellation) : TileSet();
    const TileSet sweep = ComputeThiessenSweep(window, points).Tiles;
    for (const TileSet* tiles : { &green, &sweep })
    {
      if (tiles == &green && !cases[c].InWindowPredicateRange)
      {
        continue;
      }
      const char* engine = tiles == &green ? " (Green-Sibson)" : " (sweep)";
      ASSERT_EQ(tiles->PointIds.size(), points.size()) << "case " << c << engine;
      for (std::size_t k = 0; k < tiles->PointIds.size(); ++k)
      {
        const std::int32_t id = tiles->PointIds[k];
        for (std::int64_t v = tiles->Offsets[k]; v < tiles->Offsets[k + 1]; ++v)
        {
          EXPECT_TRUE(std::isfinite(tiles->Vertices[v].x) && std::isfinite(tiles->Vertices[v].y))
            << "case " << c << " point " << id << engine;
        }
        const double exact = ExactTileArea(window, points, std::size_t(id)).get_d();
        EXPECT_NEAR(tiles->Areas[k], exact, tolerance) << "case " << c << " point " << id << engine;
        // Convex up to rounding: the clip's check for user tiles accepts it (a vertex 2.66 off
        // folded the tile of case 0 without changing its area much).
        const std::vector<Point2> tile(tiles->Vertices.begin() + tiles->Offsets[k],
          tiles->Vertices.begin() + tiles->Offsets[k + 1]);
        EXPECT_NO_THROW(catchment.ClipArea(tile)) << "case " << c << " point " << id << engine;
      }
    }
  }
}

// Tile vertices of flat triangles (three points within 1e-3 of a line, and slivers whose short
// side is 2^-9 of the others) against the exact rational circumcentre, relative to the
// circumradius: the rounded formula, taken while the area's condition stayed under 2^16, was up to
// 8.7e-12 off (16 bits; a numerical review); under 2^6, and the exact path above, under 1e-12.
TEST(Tiles, FlatTrianglesGiveCircumcentresWithinBitsOfExact)
{
  std::mt19937_64 rng(23);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  double worst = 0.0;
  for (int shape = 0; shape < 2; ++shape)
  {
    for (int k = 0; k < 4000; ++k)
    {
      const double angle = 6.283 * u(rng), length = 0.5 + u(rng), x0 = u(rng), y0 = u(rng);
      const double ux = std::cos(angle), uy = std::sin(angle);
      Point2 p[3];
      if (shape == 0) // along a line, the middle point 1e-3 of the length off it at most
      {
        const double along = u(rng) * length, off = (u(rng) - 0.5) * 2e-3 * length;
        p[0] = { x0, y0 };
        p[1] = { x0 + along * ux - off * uy, y0 + along * uy + off * ux };
        p[2] = { x0 + length * ux, y0 + length * uy };
      }
      else // a sliver: two points 2^-9 of the length apart, one far
      {
        const double turn = 6.283 * u(rng), side = 0x1p-9 * length;
        p[0] = { x0, y0 };
        p[1] = { x0 + side * std::cos(turn), y0 + side * std::sin(turn) };
        p[2] = { x0 + length * ux, y0 + length * uy };
      }
      std::sort(p, p + 3, [](const Point2& a, const Point2& b) { return ComesFirst(a, b); });
      if (orient2d(p[0], p[1], p[2]) < 0)
      {
        std::swap(p[1], p[2]); // anticlockwise, the first still first
      }
      if (orient2d(p[0], p[1], p[2]) == 0)
      {
        continue;
      }
      const Point2 centre = CircumcentreOf(p[0], p[1], p[2]);
      // Exactly: the centre o solves 2 (b - a) . o = |b|^2 - |a|^2, and likewise for c.
      const mpq_class ax = p[0].x, ay = p[0].y, bx = p[1].x, by = p[1].y, cx = p[2].x, cy = p[2].y;
      const mpq_class e1x = 2 * (bx - ax), e1y = 2 * (by - ay),
                      f1 = bx * bx + by * by - ax * ax - ay * ay;
      const mpq_class e2x = 2 * (cx - ax), e2y = 2 * (cy - ay),
                      f2 = cx * cx + cy * cy - ax * ax - ay * ay;
      const mpq_class det = e1x * e2y - e1y * e2x;
      const mpq_class ox = (f1 * e2y - f2 * e1y) / det, oy = (e1x * f2 - e2x * f1) / det;
      const double radius = std::hypot(mpq_class(ox - ax).get_d(), mpq_class(oy - ay).get_d());
      const double error = std::hypot(
        mpq_class(mpq_class(centre.x) - ox).get_d(), mpq_class(mpq_class(centre.y) - oy).get_d());
      worst = std::max(worst, error / radius);
    }
  }
  EXPECT_LT(worst, 1e-12);
}

TEST(Tiles, PointsASubnormalDistanceApartGiveFiniteHalves)
{
  // Two points 4.94e-324 apart split the window ±1 along their bisector (x = 2.47e-324, so
  // halves of area 2 each). The bisector's direction was of subnormal size: its crossing with a
  // window side had an infinite parameter, and t * 0 made a NaN vertex. Both engines, and the
  // exact areas. (A coordinate of 4.94e-324 is below the range of Green-Sibson's exact window
  // predicates, window_predicates.h, whatever the window: its derivations refuse it, naming the
  // point, and the sweep is checked; the engine's finite halves are kept for points just above
  // that range, 2^-200 of the window, here 1e-61 apart.)
  const Window window = Window::Rectangle(-1, 1, -1, 1);
  const std::vector<Point2> points{ { 0.0, 0.0 }, { 4.94e-324, 0.0 } };
  try
  {
    ComputeTiles(DirichletTessellation(window, points));
    ADD_FAILURE() << "tiles derived for a point below the exact range";
  }
  catch (const InputError& e)
  {
    EXPECT_NE(std::string(e.what()).find("point 1 (4.94065645841247e-324, 0)"), std::string::npos)
      << e.what();
  }
  const std::vector<Point2> above{ { 0.0, 0.0 }, { 1e-60, 0.0 } };
  const TileSet green = ComputeTiles(DirichletTessellation(window, above));
  const TileSet sweep = ComputeThiessenSweep(window, points).Tiles;
  for (const TileSet* tiles : { &green, &sweep })
  {
    const std::vector<Point2>& given = tiles == &green ? above : points;
    ASSERT_EQ(tiles->PointIds.size(), 2u);
    for (std::size_t k = 0; k < 2; ++k)
    {
      EXPECT_NEAR(tiles->Areas[k], ExactTileArea(window, given, std::size_t(k)).get_d(), 1e-15)
        << k;
      for (std::int64_t v = tiles->Offsets[k]; v < tiles->Offsets[k + 1]; ++v)
      {
        EXPECT_TRUE(std::isfinite(tiles->Vertices[v].x) && std::isfinite(tiles->Vertices[v].y));
      }
    }
  }
}

// Tiles of a window outside the exact range (coordinates of 2^400 or 2^-400) came out wrong
// without a word: corners inf or NaN, collapsed tiles. Deriving them is now an InputError that
// says how to scale; scaled by ScaleIntoExactRange, the tiles are those of the unit square scaled.
// The Delaunay faces need no window and stay exact at any scale.
TEST(Tiles, AWindowOutsideTheExactRangeIsAnErrorUnlessScaled)
{
  const std::vector<Point2> unit{ { 0.2, 0.3 }, { 0.7, 0.4 }, { 0.4, 0.8 }, { 0.9, 0.9 } };
  const DirichletTessellation reference(Window::Rectangle(0.0, 1.0, 0.0, 1.0), unit);
  const TileSet expected = ComputeTiles(reference);
  for (const int exponent : { 400, -400 })
  {
    std::vector<Point2> points = unit;
    for (Point2& p : points)
    {
      p = { std::ldexp(p.x, exponent), std::ldexp(p.y, exponent) };
    }
    const double one = std::ldexp(1.0, exponent);
    Window window = Window::Rectangle(0.0, one, 0.0, one);
    {
      const DirichletTessellation raw(window, points);
      try
      {
        ComputeTiles(raw);
        ADD_FAILURE() << "2^" << exponent << ": tiles derived outside the exact range";
      }
      catch (const InputError& e)
      {
        EXPECT_NE(std::string(e.what()).find("ScaleIntoExactRange"), std::string::npos) << e.what();
      }
      EXPECT_THROW(ComputeTilesOf(raw, { 0, 1 }), InputError);
      EXPECT_EQ(ComputeDelaunayFaces(raw, false).PointIds.size(),
        ComputeDelaunayFaces(reference, false).PointIds.size());
    }
    const int scale = ScaleIntoExactRange(window, points);
    TileMesh mesh =
      TessellationDual(DirichletTessellation(window, points)).TileMeshAndContiguities(false).Tiles;
    ScaleByPowerOfTwo(mesh, -scale);
    ASSERT_EQ(mesh.Areas.size(), expected.Areas.size());
    for (std::size_t k = 0; k < mesh.Areas.size(); ++k)
    {
      EXPECT_DOUBLE_EQ(mesh.Areas[k], std::ldexp(expected.Areas[k], 2 * exponent)) << k;
    }
  }
}

// A point with a nonzero coordinate below 2^-200 of the window's reach: the window decisions of
// its tiles are not exact, and the core's derivations gave wrong tiles without a word (from the C++
// user's review: 50 points within 1e-200 of a corner made tiles whose areas summed to 44.9 times
// the window's, and a tile of 3 sides for one of 4). Every derivation names the first such point
// that is accepted, whether it came in a batch or was inserted; once it is removed the tiles are
// derived again, and equal those of the points without it. The faces need no window, and
// Brassel-Reif takes such points.
TEST(Tiles, APointBelowTheExactRangeIsNamedByEveryDerivation)
{
  const Window window = Window::Rectangle(0.0, 0.1, 0.0, 0.1);
  const std::vector<Point2> points{
    { 0.05, 0.05 }, { 1e-200, 0.0375 }, { 0.0375, 5e-201 }, { 0.08, 0.02 }
  };
  const auto named = [](const std::function<void()>& derive, const std::string& fragment)
  {
    try
    {
      derive();
      return std::string("no error");
    }
    catch (const InputError& e)
    {
      return std::string(e.what()).find(fragment) != std::string::npos ? std::string()
                                                                       : std::string(e.what());
    }
  };
  DirichletTessellation batch(window, points);
  DirichletTessellation streamed(window);
  for (const Point2& p : points)
  {
    streamed.Insert(p);
  }
  for (DirichletTessellation* t : { &batch, &streamed })
  {
    const std::string first = "point 1 (1e-200, 0.0375) has a coordinate below 2^-200";
    EXPECT_EQ(named([&] { ComputeTiles(*t); }, first), "");
    EXPECT_EQ(named([&] { ComputeContiguityGraph(*t); }, first), "");
    EXPECT_EQ(named([&] { ComputeTilesOf(*t, { 0 }); }, first), "");
    EXPECT_EQ(named([&] { TessellationDual(*t).TileMeshAndContiguities(); }, first), "");
    EXPECT_EQ(ComputeDelaunayFaces(*t, false).PointIds.size(), 6u);
    t->Remove(1);
    EXPECT_EQ(named([&] { ComputeTiles(*t); }, "point 2 (0.0375, 5e-201)"), "");
    t->Remove(2);
    const TileSet tiles = ComputeTiles(*t);
    const TileSet without = ComputeTiles(
      DirichletTessellation(window, { points[0], { 0.0, 0.0 }, { 0.0, 0.0 }, points[3] }));
    EXPECT_EQ(tiles.PointIds, (std::vector<std::int32_t>{ 0, 3 }));
    EXPECT_EQ(tiles.Areas, without.Areas);
  }
  const TileSet sweep = ComputeThiessenSweep(window, points).Tiles;
  double total = 0.0;
  for (const double area : sweep.Areas)
  {
    total += area;
  }
  EXPECT_NEAR(total, 0.01, 1e-17);
}

// Points an ulp apart: the middle tile's corners round onto each other (a polygon of one or two
// points); CollapsedTilePoints names it, and a true strip (points 2^20 ulps apart) is not named.
TEST(Tiles, TilesNarrowerThanAnUlpAreCollapsed)
{
  const double x = 4.0;
  for (const bool ulp : { true, false })
  {
    const double left = ulp ? std::nextafter(x, 0.0) : x - std::ldexp(1.0, -30);
    const double right = ulp ? std::nextafter(x, 9.0) : x + std::ldexp(1.0, -30);
    const DirichletTessellation t(
      Window::Rectangle(0.0, 6.0, 4.5, 5.5), { { left, 5.0 }, { x, 5.0 }, { right, 5.0 } });
    const TileMesh mesh = TessellationDual(t).TileMeshAndContiguities(false).Tiles;
    EXPECT_EQ(
      CollapsedTilePoints(mesh), ulp ? std::vector<std::int32_t>{ 1 } : std::vector<std::int32_t>{})
      << (ulp ? "an ulp apart" : "2^-30 apart");
  }
}

// A window whose area is inf or 0 (1e308 or 1e-200 on a side) cannot be compared with the tiles'
// areas: said so, not "the points lie too close together" (from the C++ user's review).
TEST(Tiles, AWindowAreaBeyondTheDoublesIsNamedAsSuch)
{
  TileMesh mesh;
  mesh.Areas = { 1.0, 2.0 };
  for (const double area : { HUGE_VAL, 0.0 })
  {
    try
    {
      CheckTilesFillWindow(mesh, area);
      ADD_FAILURE() << "window area " << area << ": no error";
    }
    catch (const InputError& e)
    {
      EXPECT_NE(std::string(e.what()).find("is beyond the doubles' range"), std::string::npos)
        << e.what();
    }
  }
  EXPECT_NO_THROW(CheckTilesFillWindow(mesh, 3.0));
  EXPECT_THROW(CheckTilesFillWindow(mesh, 4.0), InputError);
}

// A triangle 2^-40 wide at 0.5: the tiles' corners on its slanted side are rounded off the side,
// and their areas add up some 1e-5 from the window's, which CheckTilesFillWindow took for points
// too close together and refused (the filter with it). CornerRoundingOfTiles bounds the drift;
// the sum, taken here exactly over the rounded boundary, lies within it, and a rectangle's is 0.
TEST(Tiles, RoundedCornersOnASlantedSideStayWithinTheirBound)
{
  for (const int k : { 40, 44 })
  {
    const double e = std::ldexp(1.0, -k);
    std::mt19937_64 random(11);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::vector<Point2> points;
    for (int i = 0; i < 2000; ++i)
    {
      points.push_back({ 0.5 + e * unit(random), 0.5 + e * unit(random) });
    }
    const Window triangle({ { -1.0, 0.0, 0.5 }, { 0.0, -1.0, 0.5 }, { 1.0, 1.0, -(1.0 + e) } });
    const Window square = Window::Rectangle(0.5, 0.5 + e, 0.5, 0.5 + e);
    EXPECT_EQ(CornerRoundingOfTiles(square), 0.0);
    const double bound = CornerRoundingOfTiles(triangle);
    EXPECT_GT(bound, 1e-6 * triangle.Area()) << "2^-" << k << ": the drift the check allows";
    EXPECT_LT(bound, 0.25 * triangle.Area()) << "2^-" << k; // (not so loose as to pass anything)
    const DirichletTessellation t(triangle, points);
    const TileMesh mesh = TessellationDual(t).TileMeshAndContiguities(false).Tiles;
    long double sum = 0.0L;
    for (const double area : mesh.Areas)
    {
      sum += area;
    }
    EXPECT_LE(std::fabs(double(sum) - triangle.Area()), bound) << "2^-" << k;
    EXPECT_NO_THROW(CheckTilesFillWindow(mesh, triangle.Area(), bound)) << "2^-" << k;
    // (the points too close together this check is for give sums many times the window's)
    EXPECT_THROW(CheckTilesFillWindow(mesh, 2.0 * triangle.Area(), bound), InputError);
  }
}
