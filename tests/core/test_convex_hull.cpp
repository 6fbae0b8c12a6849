// ConvexHullPositions against what defines a convex hull, checked with exact orientations: the
// result is a strictly convex anticlockwise polygon of input points with every input point inside
// or on it, starting at the lowest of the leftmost. Such a polygon is the hull, with its vertices
// and no other point; so a missed hull vertex, a point inside an edge or a copy listed twice fails.
// MoveHullToFront: the hull's vertices in front, in their order, the ids with their points.
#include "fp_contract_off.h" // (first: a test computes orientations rounded as a naive filter would)

#include "convex_hull.h"
#include "predicates.h"
#include "test_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <set>
#include <vector>

using namespace tessera;
using tessera_test::UniformPoints;

namespace
{

/// Fails unless hull (positions into points) is the strictly convex hull of points.
void ExpectHull(const std::vector<Point2>& points, const std::vector<std::int32_t>& hull)
{
  ASSERT_GE(hull.size(), 3u);
  std::set<std::pair<double, double>> places;
  for (const std::int32_t k : hull)
  {
    ASSERT_GE(k, 0);
    ASSERT_LT(std::size_t(k), points.size());
    EXPECT_TRUE(places.insert({ points[k].x, points[k].y }).second) << "vertex listed twice: " << k;
  }
  const std::size_t h = hull.size();
  for (std::size_t i = 0; i < h; ++i)
  {
    const Point2& a = points[hull[i]];
    const Point2& b = points[hull[(i + 1) % h]];
    const Point2& c = points[hull[(i + 2) % h]];
    EXPECT_GT(orient2d(a, b, c), 0) << "no strict left turn at vertex " << (i + 1) % h;
    for (std::size_t k = 0; k < points.size(); ++k)
    {
      ASSERT_GE(orient2d(a, b, points[k]), 0) << "point " << k << " outside edge " << i;
    }
  }
  const Point2& first = points[hull[0]];
  for (const Point2& p : points)
  {
    EXPECT_TRUE(first.x < p.x || (first.x == p.x && first.y <= p.y)) << "not the first vertex";
  }
}

std::vector<std::int32_t> HullOf(const std::vector<Point2>& points, std::int32_t cap)
{
  return ConvexHullPositions(points.data(), std::int32_t(points.size()), cap);
}

} // namespace

TEST(ConvexHull, UniformPointsGiveTheirHull)
{
  for (const std::size_t n : { 3, 4, 10, 300, 10000 })
  {
    for (const std::uint64_t seed : { 1, 2, 3 })
    {
      const std::vector<Point2> points = UniformPoints(n, seed, -3.0, 5.0);
      const std::vector<std::int32_t> hull = HullOf(points, std::int32_t(n));
      SCOPED_TRACE(testing::Message() << n << " points, seed " << seed);
      ExpectHull(points, hull);
    }
  }
}

// Points near one line (2^30 plus offsets of a few units: rounded orientations would be wrong
// here) and at 10^-9 and 10^9 scales: the filter decides with exact signs.
TEST(ConvexHull, NearlyDegenerateSetsAtAnyScaleGiveTheirHull)
{
  std::mt19937_64 random(5);
  std::uniform_int_distribution<int> offset(-3, 3);
  std::uniform_real_distribution<double> along(0.0, 1.0);
  std::vector<Point2> nearLine(2000);
  for (Point2& p : nearLine)
  {
    const double t = std::ldexp(std::floor(along(random) * 4096.0), 18); // up to 2^30
    p = { 1073741824.0 + t + offset(random), 1073741824.0 + t + offset(random) };
  }
  ExpectHull(nearLine, HullOf(nearLine, 2000));
  for (const double scale : { 1e-9, 1e9 })
  {
    std::vector<Point2> scaled = UniformPoints(5000, 7);
    for (Point2& p : scaled)
    {
      p = { p.x * scale, p.y * scale };
    }
    SCOPED_TRACE(testing::Message() << "scale " << scale);
    ExpectHull(scaled, HullOf(scaled, 5000));
  }
}

// Points just outside the octagon's edges, by less than a rounded orientation can tell: each is
// chosen so that the orientation computed in floating point puts it inside while orient2d puts it
// outside, so each is a hull vertex that a filter on rounded orientations would drop. (Where the
// differences to the point are exact, rounding is monotone and cannot err that way: the points are
// moved off the edge by a few units in the last place, and some edges give none.)
TEST(ConvexHull, PointsJustOutsideTheOctagonWhereRoundingSaysInsideAreVertices)
{
  constexpr double Pi = 3.14159265358979323846;
  std::vector<Point2> points;
  // Near a regular octagon: each vertex still reaches furthest in its direction (down,
  // down-right, ...).
  for (int i = 0; i < 8; ++i)
  {
    const double angle = Pi * (-0.5 + 0.25 * i) + 0.01 * (i + 1);
    const double radius = 1e6 + 1234.5678 * i;
    points.push_back({ radius * std::cos(angle), radius * std::sin(angle) });
  }
  std::mt19937_64 random(11);
  std::uniform_real_distribution<double> along(0.3, 0.7);
  std::uniform_int_distribution<int> ulps(-3, 3);
  int edgesWithOne = 0;
  for (int i = 0; i < 8; ++i)
  {
    const Point2 a = points[i], b = points[(i + 1) % 8];
    for (int attempt = 0; attempt < 200000; ++attempt)
    {
      const double t = along(random);
      Point2 p{ a.x + t * (b.x - a.x), a.y + t * (b.y - a.y) };
      for (int step = ulps(random); step != 0; step += step > 0 ? -1 : 1)
      {
        p.x = std::nextafter(p.x, step > 0 ? HUGE_VAL : -HUGE_VAL);
      }
      const double rounded = (a.x - p.x) * (b.y - p.y) - (a.y - p.y) * (b.x - p.x);
      if (rounded > 0.0 && orient2d(a, b, p) < 0)
      {
        points.push_back(p);
        ++edgesWithOne;
        break;
      }
    }
  }
  ASSERT_GE(edgesWithOne, 3);
  const std::vector<Point2> inside = UniformPoints(2000, 13, -5e5, 5e5);
  points.insert(points.end(), inside.begin(), inside.end());
  const std::vector<std::int32_t> hull = HullOf(points, std::int32_t(points.size()));
  ExpectHull(points, hull);
  // The octagon's vertices and the points outside its edges.
  EXPECT_EQ(hull.size(), std::size_t(8 + edgesWithOne));
}

// A lattice: its corners only (the points along its sides lie inside hull edges), each corner
// once although it has three copies.
TEST(ConvexHull, ALatticeWithCopiedCornersGivesItsFourCorners)
{
  std::vector<Point2> points = tessera_test::SquareLattice(20);
  const std::vector<Point2> corners = {
    { 0.5, 0.5 }, { 19.5, 0.5 }, { 19.5, 19.5 }, { 0.5, 19.5 }
  };
  for (int copy = 0; copy < 3; ++copy)
  {
    points.insert(points.end(), corners.begin(), corners.end());
  }
  std::shuffle(points.begin(), points.end(), std::mt19937(3));
  const std::vector<std::int32_t> hull = HullOf(points, std::int32_t(points.size()));
  ExpectHull(points, hull);
  EXPECT_EQ(hull.size(), 4u);
}

// A thin triangle whose apex reaches furthest in none of the eight directions the filter uses:
// its octagon has two points and keeps every point, and the apex is still found. The other two
// points lie exactly on the base.
TEST(ConvexHull, AnApexNoDirectionReachesIsAVertex)
{
  const std::vector<Point2> points = {
    { 0.0, 0.0 }, { 8.0, 1.0 }, { 4.0, 0.5 + 1.0 / 1024.0 }, { 2.0, 0.25 }, { 6.0, 0.75 }
  };
  const std::vector<std::int32_t> hull = HullOf(points, 5);
  ExpectHull(points, hull);
  EXPECT_EQ(hull, (std::vector<std::int32_t>{ 0, 1, 2 }));
}

// Points in convex position all pass the filter: their hull within the cap, nothing beyond it.
TEST(ConvexHull, PointsInConvexPositionStopAtTheCap)
{
  std::vector<Point2> circle;
  for (int k = 0; k < 500; ++k)
  {
    circle.push_back({ 1000.0 * std::cos(0.0125 * k), 1000.0 * std::sin(0.0125 * k) });
  }
  const std::vector<std::int32_t> hull = HullOf(circle, 500);
  ExpectHull(circle, hull);
  EXPECT_EQ(hull.size(), circle.size());
  EXPECT_TRUE(HullOf(circle, 499).empty());
}

TEST(ConvexHull, NoHullOfFewerThanThreePlacesOrOfALine)
{
  EXPECT_TRUE(HullOf({}, 10).empty());
  EXPECT_TRUE(HullOf({ { 1.0, 2.0 }, { 3.0, 4.0 } }, 10).empty());
  EXPECT_TRUE(HullOf({ { 1.0, 2.0 }, { 1.0, 2.0 }, { 1.0, 2.0 }, { 3.0, 4.0 } }, 10).empty());
  std::vector<Point2> line;
  for (int k = 0; k < 100; ++k)
  {
    line.push_back({ 0.1 * k, 0.3 * k }); // (rounded: exactly collinear or not, no hull is wrong)
  }
  const std::vector<std::int32_t> hull = HullOf(line, 100);
  if (!hull.empty())
  {
    ExpectHull(line, hull);
  }
  std::vector<Point2> exactLine;
  for (int k = 0; k < 100; ++k)
  {
    exactLine.push_back({ double(k), 2.0 * k + 1.0 });
  }
  EXPECT_TRUE(HullOf(exactLine, 100).empty());
}

// The hull's vertices first, in their order, each point with its id, the others in place but for
// the ones they displaced: for uniform points in a square and in a disc.
TEST(ConvexHull, MoveHullToFrontPutsTheHullFirstAndKeepsEachIdWithItsPoint)
{
  for (const bool disc : { false, true })
  {
    std::vector<Point2> original = UniformPoints(3000, 17, -1.0, 1.0);
    if (disc)
    {
      original.erase(std::remove_if(original.begin(),
                       original.end(),
                       [](const Point2& p) { return p.x * p.x + p.y * p.y >= 1.0; }),
        original.end());
    }
    SCOPED_TRACE(disc ? "disc" : "square");
    std::vector<Point2> points = original;
    std::vector<std::int32_t> ids(points.size());
    for (std::size_t k = 0; k < ids.size(); ++k)
    {
      ids[k] = std::int32_t(k);
    }
    const std::int32_t n = std::int32_t(points.size());
    const std::int32_t moved = MoveHullToFront(points, ids, n, n);
    ASSERT_GE(moved, 3);
    std::set<std::int32_t> displaced;
    for (std::int32_t k = 0; k < n; ++k)
    {
      EXPECT_TRUE(points[k] == original[ids[k]]) << "point " << k << " lost its id";
      if (k < moved && k > 0)
      {
        EXPECT_LT(ids[k - 1], ids[k]) << "hull vertices out of their order";
      }
      if (k >= moved && ids[k] != k)
      {
        EXPECT_LT(ids[k], moved) << "a point moved that was neither hull nor displaced";
        displaced.insert(ids[k]);
      }
    }
    // The front, put round the hull by angle about its centroid, is the hull of all the points.
    std::vector<std::int32_t> front(std::size_t(moved), 0);
    Point2 centre;
    for (std::int32_t k = 0; k < moved; ++k)
    {
      front[k] = k;
      centre = { centre.x + points[k].x / moved, centre.y + points[k].y / moved };
    }
    const auto angle = [&](std::int32_t k)
    { return std::atan2(points[k].y - centre.y, points[k].x - centre.x); };
    std::sort(front.begin(),
      front.end(),
      [&](std::int32_t a, std::int32_t b) { return angle(a) < angle(b); });
    const auto first = std::min_element(front.begin(),
      front.end(),
      [&](std::int32_t a, std::int32_t b) {
        return points[a].x < points[b].x ||
          (points[a].x == points[b].x && points[a].y < points[b].y);
      });
    std::rotate(front.begin(), first, front.end());
    ExpectHull(points, front);
    // More vertices than allowed: nothing moves.
    std::vector<Point2> again = original;
    std::vector<std::int32_t> againIds(again.size(), 0);
    EXPECT_EQ(MoveHullToFront(again, againIds, n, moved - 1), 0);
    EXPECT_TRUE(std::equal(again.begin(), again.end(), original.begin()));
  }
}
