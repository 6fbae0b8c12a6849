// The nearest-feature transform against brute force, and the partition against a brute-force
// nearest contour pixel and an independent arc-length computation.
#include "distance_transform.h"
#include "errors.h"
#include "point_partition.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <vector>

namespace
{

using tessera::Point2;

// Every point past a contour end extends it (the gap rule is tested on its own).
const double NoGapLimit = std::numeric_limits<double>::infinity();

double SquaredDistance(int a, int b, int width)
{
  const double dx = a % width - b % width;
  const double dy = a / width - b / width;
  return dx * dx + dy * dy;
}

TEST(NearestFeatureTransform, MatchesBruteForce)
{
  std::mt19937 rng(4);
  for (int trial = 0; trial < 20; ++trial)
  {
    const int width = 5 + trial * 3;
    const int height = 40 - trial;
    std::bernoulli_distribution feature(trial % 2 ? 0.02 : 0.2);
    std::vector<std::uint8_t> mask(width * height, 0);
    std::vector<int> features;
    for (int p = 0; p < width * height; ++p)
    {
      if (feature(rng))
      {
        mask[p] = 1;
        features.push_back(p);
      }
    }
    const std::vector<int> nearest = tessera::NearestFeatureTransform(mask, width, height);
    for (int p = 0; p < width * height; ++p)
    {
      if (features.empty())
      {
        EXPECT_EQ(nearest[p], -1);
        continue;
      }
      double best = 1e300;
      for (int f : features)
      {
        best = std::min(best, SquaredDistance(p, f, width));
      }
      ASSERT_GE(nearest[p], 0);
      ASSERT_TRUE(mask[nearest[p]]) << "pixel " << p << " maps to a non-feature";
      EXPECT_EQ(SquaredDistance(p, nearest[p], width), best) << "pixel " << p;
    }
  }
}

// Two hand-made contours on a 40 x 30 image: an open L-shaped polyline and a closed square.
tessera::RidgeContours TwoContours(int width)
{
  tessera::RidgeContours contours;
  auto add = [&](std::vector<std::pair<int, int>> pixels, bool closed)
  {
    for (auto [i, j] : pixels)
    {
      contours.Pixels.push_back(j * width + i);
    }
    contours.Offsets.push_back(static_cast<int>(contours.Pixels.size()));
    contours.Closed.push_back(closed ? 1 : 0);
  };
  std::vector<std::pair<int, int>> open;
  for (int i = 3; i <= 20; ++i)
  {
    open.push_back({ i, 5 });
  }
  for (int j = 6; j <= 15; ++j)
  {
    open.push_back({ 21, j - 1 + 1 });
  }
  add(open, false);
  std::vector<std::pair<int, int>> square;
  for (int i = 28; i <= 35; ++i)
    square.push_back({ i, 18 });
  for (int j = 19; j <= 25; ++j)
    square.push_back({ 35, j });
  for (int i = 34; i >= 28; --i)
    square.push_back({ i, 25 });
  for (int j = 24; j >= 19; --j)
    square.push_back({ 28, j });
  add(square, true);
  // Lengths computed independently: sum of steps (+ closing step).
  for (int c = 0; c < 2; ++c)
  {
    double length = 0.0;
    const int first = contours.Offsets[c];
    const int last = contours.Offsets[c + 1];
    for (int k = first + 1; k < last; ++k)
    {
      length += std::sqrt(SquaredDistance(contours.Pixels[k - 1], contours.Pixels[k], width));
    }
    if (contours.Closed[c])
    {
      length +=
        std::sqrt(SquaredDistance(contours.Pixels[last - 1], contours.Pixels[first], width));
    }
    contours.Lengths.push_back(length);
  }
  return contours;
}

TEST(PointPartition, AssignsTheNearestContourPixelAndItsArcLength)
{
  const int width = 40;
  const int height = 30;
  const tessera::RidgeContours contours = TwoContours(width);
  std::mt19937 rng(8);
  std::uniform_real_distribution<double> x(-0.5, width - 0.5);
  std::uniform_real_distribution<double> y(-0.5, height - 0.5);
  std::vector<Point2> points(3000);
  for (Point2& p : points)
  {
    p = { x(rng), y(rng) };
  }
  const tessera::PointPartition partition =
    tessera::PartitionPoints(points, contours, width, height, NoGapLimit);
  int exact = 0;
  for (std::size_t k = 0; k < points.size(); ++k)
  {
    double best = 1e300;
    for (int pixel : contours.Pixels)
    {
      best = std::min(best, std::hypot(points[k].x - pixel % width, points[k].y - pixel / width));
    }
    const int position = partition.Projection[k];
    ASSERT_GE(position, 0);
    const int pixel = contours.Pixels[position];
    const double chosen = std::hypot(points[k].x - pixel % width, points[k].y - pixel / width);
    // Exact except in near-ties (see point_partition.h): never more than 0.1 pixel worse.
    EXPECT_LE(chosen, best + 0.1) << "point " << k;
    exact += chosen <= best + 1e-12;
    EXPECT_EQ(partition.GroupId[k], position < contours.Offsets[1] ? 0 : 1);
    EXPECT_GE(partition.Node[k], 0.0);
    EXPECT_LE(partition.Node[k], 1.0);
  }
  EXPECT_GT(exact, 0.99 * points.size());
  // Points off the ends of the open contour get nodes beyond those of its end pixels; every
  // other point's node is its projection's arc length over the node span.
  for (std::size_t k = 0; k < points.size(); ++k)
  {
    const int c = partition.GroupId[k];
    double arc = 0.0;
    for (int m = contours.Offsets[c] + 1; m <= partition.Projection[k]; ++m)
    {
      arc += std::sqrt(SquaredDistance(contours.Pixels[m - 1], contours.Pixels[m], width));
    }
    if (!partition.Extended[k])
    {
      EXPECT_NEAR(
        partition.Node[k], partition.NodeOrigin[c] + arc * partition.NodePerPixel[c], 1e-12);
    }
    if (c == 1)
    {
      // Closed contours are never extended: the paper's node, arc / length.
      EXPECT_NEAR(partition.Node[k], arc / contours.Lengths[1], 1e-12);
    }
  }
}

TEST(PointPartition, NodesIncreaseAlongAnOpenContourAndBeyondItsEnds)
{
  const int width = 40;
  const tessera::RidgeContours contours = TwoContours(width);
  // Points walking along row 5 from x = 0 (before the start pixel 3) to the corner.
  std::vector<Point2> points;
  for (double x = 0.0; x <= 20.0; x += 0.5)
  {
    points.push_back({ x, 5.2 });
  }
  const tessera::PointPartition partition =
    tessera::PartitionPoints(points, contours, width, 30, NoGapLimit);
  for (std::size_t k = 1; k < points.size(); ++k)
  {
    EXPECT_GE(partition.Node[k], partition.Node[k - 1]) << "x = " << points[k].x;
  }
  EXPECT_EQ(partition.Node[0], 0.0);
  EXPECT_TRUE(partition.Extended[0]);
}

TEST(PointPartition, AFarPointPastAnEndDoesNotStretchTheNodes)
{
  // One open contour along row 5, x = 10 .. 30 (end pixel at x = 30, tangent +x). Points on it,
  // continuations at x = 31 .. 35 (1 pixel apart), and an outlier at x = 55, 20 pixels further.
  const int width = 60;
  tessera::RidgeContours contour;
  for (int i = 10; i <= 30; ++i)
  {
    contour.Pixels.push_back(5 * width + i);
  }
  contour.Offsets.push_back(static_cast<int>(contour.Pixels.size()));
  contour.Closed.push_back(0);
  contour.Lengths.push_back(20.0);
  std::vector<Point2> points;
  for (double x = 10.0; x <= 35.0; x += 1.0)
  {
    points.push_back({ x, 5.3 });
  }
  const std::size_t lastContinuation = points.size() - 1;
  const std::vector<Point2> withoutOutlier = points;
  points.push_back({ 55.0, 5.3 });
  const double gap = 4.0;
  const tessera::PointPartition clean =
    tessera::PartitionPoints(withoutOutlier, contour, width, 12, gap);
  const tessera::PointPartition result = tessera::PartitionPoints(points, contour, width, 12, gap);
  // Continuations are extended: x = 10 .. 35 spans 25 pixels, node k / 25.
  for (std::size_t k = 0; k <= lastContinuation; ++k)
  {
    EXPECT_NEAR(clean.Node[k], double(k) / 25.0, 1e-12) << "x = " << points[k].x;
    EXPECT_EQ(result.Node[k], clean.Node[k]) << "x = " << points[k].x;
  }
  EXPECT_TRUE(result.Extended[lastContinuation]);
  EXPECT_EQ(result.Node.back(), result.Node[lastContinuation]);
  // Without the gap rule the outlier took the node range: x = 35 got 25 / 45 of it.
  const tessera::PointPartition stretched =
    tessera::PartitionPoints(points, contour, width, 12, NoGapLimit);
  EXPECT_NEAR(stretched.Node[lastContinuation], 25.0 / 45.0, 1e-12);
  // An outlier with no continuation before it gets the end pixel's node, the paper's.
  const std::vector<Point2> lone = { { 10.0, 5.3 }, { 30.0, 5.3 }, { 45.0, 5.3 } };
  const tessera::PointPartition alone = tessera::PartitionPoints(lone, contour, width, 12, gap);
  EXPECT_EQ(alone.Node, (std::vector<double>{ 0.0, 1.0, 1.0 }));
  EXPECT_FALSE(alone.Extended[2]);
}

// Points without order (PointsWithoutOrder): those further than the gap from their projection
// pixel along the contour (past an end after a gap, beyond a bend) and not continuing it, against
// points on the contour, beside it far off (their order is their pixel's: not named), continuing
// past its end, and just beyond the bend.
TEST(PointPartition, PointsAlongTheContourBeyondTheirPixelAreNamedAsWithoutOrder)
{
  // An L: row 5 from x = 10 to 30, then column 30 from y = 6 to 25 (the bend at (30, 5)).
  const int width = 80, height = 60;
  tessera::RidgeContours contour;
  for (int i = 10; i <= 30; ++i)
  {
    contour.Pixels.push_back(5 * width + i);
  }
  for (int j = 6; j <= 25; ++j)
  {
    contour.Pixels.push_back(j * width + 30);
  }
  contour.Offsets.push_back(static_cast<int>(contour.Pixels.size()));
  contour.Closed.push_back(0);
  contour.Lengths.push_back(40.0);
  const std::vector<Point2> points{
    { 15.0, 5.2 },  // 0: on the row
    { 20.0, 0.0 },  // 1: beside the row, 5 pixels off (its x is its pixel's): ordered
    { 10.0, 5.0 },  // 2: the start
    { 8.0, 5.0 },   // 3: 2 pixels before the start: continues it
    { 0.5, 5.0 },   // 4: 7.5 pixels before that, after a gap: without order
    { 30.0, 27.0 }, // 5: past the far end, 2 pixels: continues
    { 30.0, 45.0 }, // 6: 18 pixels further: without order
    { 40.0, 2.0 },  // 7: beyond the bend, nearest (30, 5), 10 pixels along the row's line
    { 32.0, 4.0 },  // 8: just beyond the bend: its pixel's place
  };
  const double gap = 4.0;
  const tessera::PointPartition partition =
    tessera::PartitionPoints(points, contour, width, height, gap);
  ASSERT_EQ(partition.Projection[7], 20); // (30, 5), the bend
  EXPECT_EQ(tessera::PointsWithoutOrder(points, contour, partition, width, gap),
    (std::vector<std::size_t>{ 4, 6, 7 }));
  // Without a gap limit every point past an end continues it: only the bend's is named.
  const tessera::PointPartition continuing =
    tessera::PartitionPoints(points, contour, width, height, NoGapLimit);
  EXPECT_EQ(tessera::PointsWithoutOrder(points, contour, continuing, width, gap),
    (std::vector<std::size_t>{ 7 }));
}

TEST(PointPartition, NoContourLeavesEveryPointUnassigned)
{
  tessera::RidgeContours none;
  const tessera::PointPartition partition =
    tessera::PartitionPoints({ { 1, 1 }, { 2, 3 } }, none, 10, 10, NoGapLimit);
  EXPECT_EQ(partition.GroupId, (std::vector<int>{ -1, -1 }));
  EXPECT_THROW(tessera::PartitionPoints({ { 1, 1 }, { 20, 3 } }, none, 10, 10, NoGapLimit),
    tessera::InputError);
}

} // namespace
