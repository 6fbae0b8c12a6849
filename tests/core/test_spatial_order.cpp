// The spatial insertion order: the Hilbert index is a bijection whose consecutive cells are
// grid neighbours, and the BRIO order is a permutation of the given ids, reproducible, with its
// last round holding about half of the points; points on lines, which crowd a few cells of a
// grid sized for points that fill the box, are in order within those cells too.

#include "spatial_order.h"
#include "test_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <random>
#include <vector>

using namespace tessera;

TEST(SpatialOrder, HilbertIndexIsAContinuousBijection)
{
  for (int levels = 1; levels <= 6; ++levels)
  {
    const std::uint32_t side = 1U << levels;
    std::vector<std::pair<std::uint32_t, std::uint32_t>> cellAt(side * side, { side, side });
    for (std::uint32_t x = 0; x < side; ++x)
    {
      for (std::uint32_t y = 0; y < side; ++y)
      {
        const std::uint32_t h = HilbertIndex(x, y, levels);
        ASSERT_LT(h, side * side);
        EXPECT_EQ(cellAt[h].first, side) << "index " << h << " used twice";
        cellAt[h] = { x, y };
      }
    }
    for (std::uint32_t h = 0; h + 1 < side * side; ++h)
    {
      const int dx = std::abs(int(cellAt[h].first) - int(cellAt[h + 1].first));
      const int dy = std::abs(int(cellAt[h].second) - int(cellAt[h + 1].second));
      EXPECT_EQ(dx + dy, 1) << "levels " << levels << " index " << h;
    }
  }
}

TEST(SpatialOrder, BrioOrderIsAReproduciblePermutation)
{
  const std::vector<Point2> points = tessera_test::UniformPoints(5000, 3, -5.0, 7.0);
  std::vector<std::int32_t> ids;
  for (std::int32_t k = 0; k < 5000; k += 2)
  {
    ids.push_back(k);
  }
  const std::vector<std::int32_t> order = BrioHilbertOrder(points, ids);
  EXPECT_EQ(order, BrioHilbertOrder(points, ids));
  std::vector<std::int32_t> sorted = order;
  std::sort(sorted.begin(), sorted.end());
  EXPECT_EQ(sorted, ids);
  // Locality: the mean step between consecutive points of the last round (about half of them, in
  // Hilbert order) is far below the mean distance of two random points (about 0.52 * 12).
  const std::size_t half = order.size() / 2;
  double total = 0.0;
  for (std::size_t k = order.size() - half; k + 1 < order.size(); ++k)
  {
    total += std::hypot(
      points[order[k + 1]].x - points[order[k]].x, points[order[k + 1]].y - points[order[k]].y);
  }
  EXPECT_LT(total / double(half - 1), 1.0);
  EXPECT_TRUE(BrioHilbertOrder(points, {}).empty());
  EXPECT_EQ(BrioHilbertOrder(points, { 7 }), std::vector<std::int32_t>{ 7 });
  // Given the selected points' box (found here serially), the same order.
  Box2 box = BoundsOf(&points[ids[0]], 1);
  for (const std::int32_t id : ids)
  {
    box.Extend(points[id]);
  }
  EXPECT_EQ(BrioHilbertOrder(points, ids, box), order);
}

// From 500,000 ids the order's sort runs in chunks on the cores (2 at this size; test_radix_sort
// tries more), and its keys are computed and its ids taken out in as many chunks as threads: the
// order must be the serial one, and a permutation.
TEST(SpatialOrder, BrioOrderInChunksIsTheSerialOrder)
{
  const std::vector<Point2> points = tessera_test::UniformPoints(600000, 5, -1.0, 1.0);
  std::vector<std::int32_t> ids(points.size());
  for (std::size_t k = 0; k < ids.size(); ++k)
  {
    ids[k] = std::int32_t(ids.size() - 1 - k); // (not in id order)
  }
  std::vector<std::int32_t> serial;
  {
    const tessera_test::ThreadLimitOverride oneThread(1);
    serial = BrioHilbertOrder(points, ids);
  }
  std::vector<std::int32_t> sorted = serial;
  std::sort(sorted.begin(), sorted.end());
  std::vector<std::int32_t> expected = ids;
  std::sort(expected.begin(), expected.end());
  ASSERT_EQ(sorted, expected);
  for (const int threads : { 2, 3, 7 })
  {
    const tessera_test::ThreadLimitOverride limit(threads);
    EXPECT_EQ(BrioHilbertOrder(points, ids), serial) << threads << " threads";
  }
}

TEST(SpatialOrder, ABoxWiderThanTheLargestDoubleStillGivesAPermutation)
{
  // XMax - XMin overflows to infinity: the scale is 0 and offsets of points far from XMin are
  // infinite too (0 * inf = NaN), which must still land in a valid cell.
  std::vector<Point2> points;
  std::vector<std::int32_t> ids;
  for (std::int32_t k = 0; k < 1000; ++k)
  {
    const double t = double(k) / 999.0;
    points.push_back({ -1.7e308 + t * 1.7e308 + t * 1.7e308, 0.5 * t });
    ids.push_back(k);
  }
  std::vector<std::int32_t> sorted = BrioHilbertOrder(points, ids);
  std::sort(sorted.begin(), sorted.end());
  EXPECT_EQ(sorted, ids);
}

namespace
{
// The distance travelled along the lines y = 0 and y = 10 by consecutive points of order[from,
// end) on one line, and how often the order changes lines.
std::pair<double, int> AlongTheLines(const std::vector<Point2>& points,
  const std::vector<std::int32_t>& order,
  std::size_t from)
{
  double along = 0.0;
  int switches = 0;
  for (std::size_t k = from; k + 1 < order.size(); ++k)
  {
    const Point2& a = points[order[k]];
    const Point2& b = points[order[k + 1]];
    if (a.y == b.y)
    {
      along += std::fabs(b.x - a.x);
    }
    else
    {
      ++switches;
    }
  }
  return { along, switches };
}
} // namespace

TEST(SpatialOrder, PointsOnLinesAreInOrderWithinTheirCells)
{
  // Two lines of length 1, 10 apart: the grid's cells (sized for 4 cells a point over the
  // 10 x 10 box) each held some 2.5 sqrt(N) of them in random order, so that the order went back
  // and forth within each cell: hundreds of line lengths per round. In order, a round sweeps
  // each line a few times, and the order changes lines a few times.
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<Point2> points(200000);
  std::vector<std::int32_t> ids(points.size());
  for (std::size_t k = 0; k < points.size(); ++k)
  {
    points[k] = { u(rng), k % 2 ? 10.0 : 0.0 };
    ids[k] = std::int32_t(k);
  }
  const std::vector<std::int32_t> order = BrioHilbertOrder(points, ids);
  const auto [along, switches] = AlongTheLines(points, order, order.size() / 2);
  EXPECT_LT(along, 8.0);
  EXPECT_LT(switches, 40);
  // The same along the finest curve alone (a serial insertion's few points): at 10^6 points some
  // 75 of them shared each of its cells.
  points.resize(1000000);
  ids.resize(points.size());
  for (std::size_t k = 0; k < points.size(); ++k)
  {
    points[k] = { u(rng), k % 2 ? 10.0 : 0.0 };
    ids[k] = std::int32_t(k);
  }
  Box2 box = BoundsOf(points.data(), points.size());
  SortAlongHilbertCurve(points.data(), box, ids);
  const auto [curveAlong, curveSwitches] = AlongTheLines(points, ids, 0);
  EXPECT_LT(curveAlong, 8.0);
  EXPECT_LT(curveSwitches, 40);
  std::vector<std::int32_t> sorted = ids;
  std::sort(sorted.begin(), sorted.end());
  for (std::size_t k = 0; k < sorted.size(); ++k)
  {
    ASSERT_EQ(sorted[k], std::int32_t(k));
  }
}
