// The spatial insertion order: the Hilbert index is a bijection whose consecutive cells are
// grid neighbours, and the BRIO order is a permutation of the given ids, reproducible, with its
// last round holding about half of the points.

#include "spatial_order.h"

#include <gtest/gtest.h>

#include <algorithm>
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
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(-5.0, 7.0);
  std::vector<Point2> points(5000);
  for (Point2& p : points)
  {
    p = { u(rng), u(rng) };
  }
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
