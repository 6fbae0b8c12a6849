// The nearest-feature transform against brute force, and the partition against a brute-force
// nearest contour pixel and an independent arc-length computation.
#include "distance_transform.h"
#include "errors.h"
#include "point_partition.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <string>
#include <utility>
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

// Contours from pixel lists (i, j), each open; lengths as sums of the steps.
tessera::RidgeContours OpenContours(const std::vector<std::vector<std::pair<int, int>>>& lines,
  int width)
{
  tessera::RidgeContours contours;
  for (const auto& line : lines)
  {
    double length = 0.0;
    for (std::size_t m = 0; m < line.size(); ++m)
    {
      contours.Pixels.push_back(line[m].second * width + line[m].first);
      if (m > 0)
      {
        length +=
          std::hypot(line[m].first - line[m - 1].first, line[m].second - line[m - 1].second);
      }
    }
    contours.Offsets.push_back(static_cast<int>(contours.Pixels.size()));
    contours.Closed.push_back(0);
    contours.Lengths.push_back(length);
  }
  return contours;
}

std::vector<std::pair<int, int>> Row(int j, int from, int to)
{
  std::vector<std::pair<int, int>> pixels;
  for (int i = from; i <= to; ++i)
  {
    pixels.push_back({ i, j });
  }
  return pixels;
}

// Appends points (x, y) for x = from, from + step, ... up to to.
void AppendRowOfPoints(std::vector<Point2>& points, double y, double from, double to, double step)
{
  for (double x = from; x <= to; x += step)
  {
    points.push_back({ x, y });
  }
}

// The distance from p to the nearest pixel of any contour, and that pixel's contour (brute force).
std::pair<double, int> NearestContour(const Point2& p,
  const tessera::RidgeContours& contours,
  int width)
{
  std::pair<double, int> best{ std::numeric_limits<double>::infinity(), -1 };
  for (int c = 0; c < contours.Count(); ++c)
  {
    for (int k = contours.Offsets[c]; k < contours.Offsets[c + 1]; ++k)
    {
      const int pixel = contours.Pixels[k];
      const double d = std::hypot(p.x - pixel % width, p.y - pixel / width);
      if (d < best.first)
      {
        best = { d, c };
      }
    }
  }
  return best;
}

// Two parallel lines 10 pixels (2.5 gaps) apart: the lower's contour (0) runs their whole length,
// the upper's (1) stops at x = 50 while its points run on to x = 90, a chain 1.5 pixels apart.
// Past x = 60 those points are nearer to the lower contour; they continue the upper one, with
// nodes increasing along x. A point of the upper line after a gap of 15 pixels (x = 105), and one
// beside the upper contour's middle (6 pixels above it), keep their nearest contour.
TEST(PointPartition, AChainPastAnEndContinuesItsContourNotTheNearestOne)
{
  const int width = 120, height = 40;
  const tessera::RidgeContours contours = OpenContours({ Row(10, 5, 110), Row(20, 5, 50) }, width);
  const double gap = 4.0;
  std::vector<Point2> points;
  AppendRowOfPoints(points, 10.3, 5.0, 110.0, 1.5);
  const std::size_t firstUpper = points.size();
  for (double x = 5.0; x <= 90.0; x += 1.5)
  {
    // a little noise across the line: y = 19.6 .. 20.4
    points.push_back({ x, 20.0 + 0.4 * std::sin(1.7 * x) });
  }
  const std::size_t lone = points.size();
  points.push_back({ 105.0, 20.0 });
  const std::size_t beside = points.size();
  points.push_back({ 30.0, 26.0 });
  const tessera::PointPartition partition =
    tessera::PartitionPoints(points, contours, width, height, gap);
  int taken = 0; // upper points whose nearest contour is the lower one
  for (std::size_t k = 0; k < lone; ++k)
  {
    const int line = k < firstUpper ? 0 : 1;
    EXPECT_EQ(partition.GroupId[k], line) << "x = " << points[k].x << ", y = " << points[k].y;
    taken += line == 1 && NearestContour(points[k], contours, width).second == 0;
  }
  EXPECT_GT(taken, 15) << "no upper point is nearer to the lower contour: the test checks nothing";
  for (std::size_t k = firstUpper + 1; k < lone; ++k)
  {
    EXPECT_GE(partition.Node[k], partition.Node[k - 1]) << "x = " << points[k].x;
    if (points[k].x > 50.0)
    {
      EXPECT_GT(partition.Node[k], partition.Node[k - 1]) << "x = " << points[k].x;
      EXPECT_TRUE(partition.Continues[k]) << "x = " << points[k].x;
      EXPECT_NEAR(partition.Beyond[k], points[k].x - 50.0, 1e-12) << "x = " << points[k].x;
    }
  }
  EXPECT_NEAR(partition.Node[lone - 1], 1.0, 1e-12);
  // After the gap: the lower contour, nearest (10 pixels below, the upper end 55 away).
  EXPECT_EQ(partition.GroupId[lone], 0);
  EXPECT_EQ(partition.Projection[lone], 100); // (105, 10)
  EXPECT_EQ(partition.GroupId[beside], 1);
  EXPECT_EQ(partition.Projection[beside], contours.Offsets[1] + 25); // (30, 20)
  // Without a gap limit no point is far: the paper's nearest contour.
  const tessera::PointPartition nearest =
    tessera::PartitionPoints(points, contours, width, height, NoGapLimit);
  for (std::size_t k = 0; k < points.size(); ++k)
  {
    EXPECT_EQ(nearest.GroupId[k], NearestContour(points[k], contours, width).second) << k;
  }
}

// Chains only run past the end: a row of far points beside the contour (4.5 pixels off, the gap
// being 4), joined by a chain to the points continuing it past its end, keeps its nearest pixels
// where it lies beside the contour (its chain from the end would make it the end's).
TEST(PointPartition, FarPointsBesideAContourAreNotTakenToItsEnd)
{
  const int width = 80, height = 40;
  const tessera::RidgeContours contours = OpenContours({ Row(20, 5, 50) }, width);
  const double gap = 4.0;
  std::vector<Point2> points;
  AppendRowOfPoints(points, 20.0, 5.0, 70.0, 1.5);
  points.push_back({ 56.0, 22.5 }); // from the chain past the end to the row beside
  const std::size_t firstBeside = points.size();
  AppendRowOfPoints(points, 24.5, 20.0, 56.0, 2.0);
  const tessera::PointPartition partition =
    tessera::PartitionPoints(points, contours, width, height, gap);
  for (std::size_t k = firstBeside; k < points.size(); ++k)
  {
    if (points[k].x <= 50.0)
    {
      EXPECT_EQ(partition.Projection[k], static_cast<int>(points[k].x) - 5) << points[k].x;
      EXPECT_FALSE(partition.Extended[k]) << points[k].x;
    }
    else
    {
      EXPECT_TRUE(partition.Continues[k]) << points[k].x;
    }
  }
}

// A T: the stem's contour (1) stops 5 pixels short of the bar's (0) middle, pointing at it, and
// the stem's points continue it to 1.5 pixels past its end, within the gap (4) of bar points. The
// bar's points lie within the gap of their contour and stay with it, and so do the points of the
// stem's line beyond the bar (far from every contour, but no chain reaches them over far points:
// the bar's points in between are near theirs).
TEST(PointPartition, AContourEndingAtAnotherTakesNoneOfItsPoints)
{
  const int width = 80, height = 70;
  std::vector<std::pair<int, int>> stem;
  for (int j = 5; j <= 25; ++j)
  {
    stem.push_back({ 40, j });
  }
  const tessera::RidgeContours contours = OpenContours({ Row(30, 10, 70), stem }, width);
  const double gap = 4.0;
  std::vector<Point2> points;
  for (double x = 10.0; x <= 70.0; x += 0.5)
  {
    points.push_back({ x, 30.0 + 1.5 * std::sin(x) }); // the bar's line, within 1.5 pixels
  }
  const std::size_t firstStem = points.size();
  for (double y = 5.5; y <= 60.0; y += 1.0)
  {
    if (y < 27.0 || y > 34.0) // the stem's line, on both sides of the bar
    {
      points.push_back({ 40.2, y });
    }
  }
  const tessera::PointPartition partition =
    tessera::PartitionPoints(points, contours, width, height, gap);
  int farBeyond = 0;
  for (std::size_t k = 0; k < points.size(); ++k)
  {
    const auto [distance, contour] = NearestContour(points[k], contours, width);
    EXPECT_EQ(partition.GroupId[k], contour) << "x = " << points[k].x << ", y = " << points[k].y;
    farBeyond += k >= firstStem && distance > gap;
  }
  EXPECT_GT(farBeyond, 10) << "no far point beyond the bar: the test checks nothing";
}

// A chain that turns back past an end: the contour runs along row 20 to x = 30 (tangent +x), its
// points on to x = 40, then up and back at 120 degrees to x = 32. The points after the turn keep
// a distance beyond the end within the gap of the turn's (10): it is the largest along their
// chain from the end (steps of at most the gap: each chain passes within the gap of the turn),
// not the point's own, which falls to 2, so their nodes do not run back along the curve. The
// points that came back by more than the gap do not count as continuing.
TEST(PointPartition, NodesDoNotRunBackAlongAChainThatTurnsBack)
{
  const int width = 60, height = 40;
  const tessera::RidgeContours contours = OpenContours({ Row(20, 10, 30) }, width);
  const double gap = 4.0;
  std::vector<Point2> points;
  AppendRowOfPoints(points, 20.0, 10.0, 40.0, 1.0);
  const std::size_t turn = points.size() - 1;
  std::vector<double> own; // distance beyond the end along +x, per point after the turn
  int backwards = 0;       // points after the turn not continuing
  for (int t = 1; t <= 16; ++t)
  {
    points.push_back({ 40.0 - 0.5 * t, 20.0 - 0.8660254037844386 * t });
    own.push_back(points.back().x - 30.0);
  }
  const tessera::PointPartition partition =
    tessera::PartitionPoints(points, contours, width, height, gap);
  for (std::size_t k = 0; k < points.size(); ++k)
  {
    EXPECT_EQ(partition.GroupId[k], 0);
    if (k > 0 && k <= turn)
    {
      EXPECT_GT(partition.Node[k], partition.Node[k - 1]) << "x = " << points[k].x;
    }
  }
  EXPECT_NEAR(partition.Beyond[turn], 10.0, 1e-12);
  for (std::size_t m = 0; m < own.size(); ++m)
  {
    const std::size_t k = turn + 1 + m;
    EXPECT_GE(partition.Beyond[k], own[m]) << "point " << k;
    EXPECT_GE(partition.Beyond[k], 10.0 - gap) << "point " << k;
    EXPECT_EQ(partition.Continues[k], own[m] >= partition.Beyond[k] - gap) << "point " << k;
    backwards += !partition.Continues[k];
  }
  EXPECT_GE(backwards, 3);
}

// Whether p is past the end pixel at `end` of open contour c (brute force): some pixel of c at most
// `within` from p is one of the 5 before the end (fewer on a short contour) and lies behind the end
// pixel in the direction from the fifth pixel before it to it (or is the end pixel), and p lies
// beyond the end pixel in that direction.
bool PastAHookedEnd(const Point2& p,
  const tessera::RidgeContours& contours,
  int c,
  int end,
  double within,
  int width)
{
  const int first = contours.Offsets[c], last = contours.Offsets[c + 1] - 1;
  const int reach = std::min(5, last - first);
  const auto at = [&](int position)
  {
    const int pixel = contours.Pixels[position];
    return Point2{ double(pixel % width), double(pixel / width) };
  };
  const Point2 e = at(end), inner = at(end == first ? first + reach : last - reach);
  const auto along = [&](const Point2& q)
  { return (q.x - e.x) * (e.x - inner.x) + (q.y - e.y) * (e.y - inner.y); };
  bool nearTheEnd = false;
  for (int position = first; position <= last; ++position)
  {
    const Point2 q = at(position);
    nearTheEnd = nearTheEnd ||
      (std::abs(position - end) <= reach && (position == end || along(q) < 0.0) &&
        std::hypot(p.x - q.x, p.y - q.y) <= within);
  }
  return nearTheEnd && along(p) > 0.0;
}

// A contour hooking at its end: row 20 from x = 10 to 40, then its end pixel one row down, at
// (40, 21) (its end tangent, from (36, 20), points along (4, 1)). The points continuing the row
// past x = 40 are nearer to pixel (40, 20) than to the end pixel: they are past the end all the
// same, and take increasing nodes along x (they all took the node of (40, 20)). A point beside the
// contour before the end keeps its nearest pixel.
TEST(PointPartition, PointsPastAHookedEndAreOrderedAlongIt)
{
  const int width = 60, height = 40;
  std::vector<std::pair<int, int>> hooked = Row(20, 10, 40);
  hooked.push_back({ 40, 21 });
  const tessera::RidgeContours contours = OpenContours({ hooked }, width);
  const int end = contours.Offsets[1] - 1;
  std::vector<Point2> points;
  AppendRowOfPoints(points, 20.0, 10.0, 40.0, 1.0);
  const std::size_t firstPast = points.size();
  AppendRowOfPoints(points, 20.0, 41.0, 50.0, 1.0);
  points.push_back({ 37.0, 22.5 }); // beside the contour, before the end
  const tessera::PointPartition partition =
    tessera::PartitionPoints(points, contours, width, height, 4.0);
  for (std::size_t k = 1; k < points.size() - 1; ++k)
  {
    EXPECT_GE(partition.Node[k], partition.Node[k - 1]) << "x = " << points[k].x;
  }
  for (std::size_t k = firstPast; k < points.size() - 1; ++k)
  {
    EXPECT_EQ(partition.Projection[k], end) << "x = " << points[k].x;
    EXPECT_TRUE(partition.Extended[k]) << "x = " << points[k].x;
    EXPECT_GT(partition.Node[k], partition.Node[k - 1]) << "x = " << points[k].x;
    // Beyond the end along (4, 1) / sqrt(17), from (40, 21).
    const double along = ((points[k].x - 40.0) * 4.0 + (20.0 - 21.0)) / std::sqrt(17.0);
    EXPECT_NEAR(partition.Beyond[k], along, 1e-12) << "x = " << points[k].x;
  }
  EXPECT_EQ(partition.Node[points.size() - 2], 1.0);
  EXPECT_EQ(contours.Pixels[partition.Projection.back()], 20 * width + 37); // (37, 20)
  EXPECT_FALSE(partition.Extended.back());
}

// Hooks that are no ends: a contour that turns back at its end (row 20 to x = 40, then (41, 21),
// (40, 22) and the end pixel (39, 22)) has pixels beyond its end along the end tangent; points
// beside them keep those pixels, in order along the contour (moved to the end, the middle one took
// the largest node). And a point within the gap of a pixel before a hooked end is near, so another
// contour's chain past its end does not take it.
TEST(PointPartition, PointsBesideAContourTurningBackAtItsEndKeepTheirPixels)
{
  const int width = 60, height = 40;
  std::vector<std::pair<int, int>> turning = Row(20, 10, 40);
  for (const auto& pixel :
    { std::make_pair(41, 21), std::make_pair(40, 22), std::make_pair(39, 22) })
  {
    turning.push_back(pixel);
  }
  const tessera::RidgeContours contours = OpenContours({ turning }, width);
  const std::vector<Point2> points = { { 41.45, 21.0 }, { 40.0, 22.4 }, { 39.0, 22.4 } };
  const tessera::PointPartition partition =
    tessera::PartitionPoints(points, contours, width, height, 10.0);
  const int last = contours.Offsets[1] - 1;
  EXPECT_EQ(partition.Projection, (std::vector<int>{ last - 2, last - 1, last }));
  EXPECT_LT(partition.Node[0], partition.Node[1]);
  EXPECT_LT(partition.Node[1], partition.Node[2]);

  std::vector<std::pair<int, int>> hooked = Row(20, 10, 40);
  hooked.push_back({ 40, 21 });
  std::vector<std::pair<int, int>> column;
  for (int j = 5; j <= 18; ++j)
  {
    column.push_back({ 40, j });
  }
  const tessera::RidgeContours two = OpenContours({ hooked, column }, width);
  const std::vector<Point2> between = { { 40.3, 18.8 }, { 40.6, 19.6 } };
  const tessera::PointPartition kept = tessera::PartitionPoints(between, two, width, height, 1.0);
  EXPECT_EQ(kept.GroupId, (std::vector<int>{ 1, 0 })); // (0.72 from (40, 20): near the hooked row)
}

// Random open contours (digital lines) and points (noisy lines, some past the contours' ends, and
// scattered points), against independent computations: a point whose pixel is not a nearest one
// is projected on an end pixel of an open contour, and is either past that end with a nearest
// pixel among the few before it (PastAHookedEnd), or far (beyond the gap from every contour),
// past the end (extended) and joined to it by a chain of far points with steps of at most the gap
// (from the end pixel, or from a point of that contour within the gap of the end pixel).
TEST(PointPartition, ReassignedPointsAreChainedToTheirEndOverFarPoints)
{
  std::mt19937 rng(21);
  const int width = 60, height = 60;
  std::uniform_int_distribution<int> coordinate(3, 56);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::normal_distribution<double> noise(0.0, 0.5);
  int reassigned = 0, movedToEnd = 0;
  for (int trial = 0; trial < 60; ++trial)
  {
    // 2-4 digital lines (Bresenham) of 8 pixels or more, sharing no pixel.
    std::vector<std::vector<std::pair<int, int>>> lines;
    std::vector<std::uint8_t> used(width * height, 0);
    const int wanted = 2 + trial % 3;
    while (static_cast<int>(lines.size()) < wanted)
    {
      int x0 = coordinate(rng), y0 = coordinate(rng);
      const int x1 = coordinate(rng), y1 = coordinate(rng);
      if (std::max(std::abs(x1 - x0), std::abs(y1 - y0)) < 8)
      {
        continue;
      }
      std::vector<std::pair<int, int>> line;
      const int dx = std::abs(x1 - x0), dy = -std::abs(y1 - y0);
      const int sx = x0 < x1 ? 1 : -1, sy = y0 < y1 ? 1 : -1;
      int error = dx + dy;
      bool free = true;
      while (true)
      {
        line.push_back({ x0, y0 });
        free = free && !used[y0 * width + x0];
        if (x0 == x1 && y0 == y1)
        {
          break;
        }
        const int e2 = 2 * error;
        if (e2 >= dy)
        {
          error += dy;
          x0 += sx;
        }
        if (e2 <= dx)
        {
          error += dx;
          y0 += sy;
        }
      }
      if (free)
      {
        for (auto [i, j] : line)
        {
          used[j * width + i] = 1;
        }
        lines.push_back(line);
      }
    }
    const tessera::RidgeContours contours = OpenContours(lines, width);
    // Points along lines through random points (one past a contour end most times), and scatter.
    std::vector<Point2> points;
    const auto inside = [&](const Point2& p)
    { return p.x >= -0.5 && p.y >= -0.5 && p.x <= width - 0.5 && p.y <= height - 0.5; };
    for (int l = 0; l < 4; ++l)
    {
      Point2 a{ coordinate(rng) * 1.0, coordinate(rng) * 1.0 };
      if (l < static_cast<int>(lines.size()))
      {
        const auto [i, j] = lines[l].back(); // start at a contour end
        a = { double(i), double(j) };
      }
      const double angle = 2.0 * 3.14159265358979 * unit(rng);
      const double step = 0.8 + 2.5 * unit(rng);
      for (int m = 0; m < 40; ++m)
      {
        const Point2 p{ a.x + m * step * std::cos(angle) + noise(rng),
          a.y + m * step * std::sin(angle) + noise(rng) };
        if (inside(p))
        {
          points.push_back(p);
        }
      }
    }
    for (int m = 0; m < 40; ++m)
    {
      points.push_back({ unit(rng) * (width - 1), unit(rng) * (height - 1) });
    }
    const double gap = 2.5 + 2.0 * unit(rng);
    const tessera::PointPartition partition =
      tessera::PartitionPoints(points, contours, width, height, gap);
    std::vector<double> nearest(points.size());
    for (std::size_t k = 0; k < points.size(); ++k)
    {
      nearest[k] = NearestContour(points[k], contours, width).first;
    }
    const auto distanceTo = [&](std::size_t k, int position)
    {
      const int pixel = contours.Pixels[position];
      return std::hypot(points[k].x - pixel % width, points[k].y - pixel / width);
    };
    for (std::size_t k = 0; k < points.size(); ++k)
    {
      const int position = partition.Projection[k];
      ASSERT_GE(position, 0);
      const int c = partition.GroupId[k];
      ASSERT_TRUE(position >= contours.Offsets[c] && position < contours.Offsets[c + 1]) << k;
      EXPECT_GE(partition.Node[k], 0.0);
      EXPECT_LE(partition.Node[k], 1.0);
      // A nearest pixel (up to the near-ties of point_partition.h).
      if (distanceTo(k, position) <= nearest[k] + 0.1)
      {
        continue;
      }
      const std::string where = "trial " + std::to_string(trial) + ", point " + std::to_string(k);
      const bool first = position == contours.Offsets[c];
      ASSERT_TRUE(first || position == contours.Offsets[c + 1] - 1) << where << ": not an end";
      if (PastAHookedEnd(points[k], contours, c, position, nearest[k] + 0.1, width))
      {
        // Past the end by its own distance along the end tangent, unless an outlier after a gap
        // (then by less) or reached by a chain (its largest distance, so more).
        ++movedToEnd;
        const int inner =
          contours.Pixels[first ? position + std::min(5, contours.Offsets[c + 1] - 1 - position)
                                : position - std::min(5, position - contours.Offsets[c])];
        const int pixel = contours.Pixels[position];
        const double tx = pixel % width - inner % width, ty = pixel / width - inner / width;
        const double own =
          ((points[k].x - pixel % width) * tx + (points[k].y - pixel / width) * ty) /
          std::hypot(tx, ty);
        if (partition.Continues[k])
        {
          EXPECT_TRUE(partition.Extended[k]) << where;
          EXPECT_GE(partition.Beyond[k], own - 1e-9) << where;
        }
        else
        {
          EXPECT_LE(partition.Beyond[k], own + 1e-9) << where;
        }
        continue;
      }
      ++reassigned;
      EXPECT_GT(nearest[k], gap - 0.1) << where << ": a near point was taken";
      EXPECT_TRUE(partition.Extended[k]) << where;
      EXPECT_GT(partition.Beyond[k], 0.0) << where;
      // Breadth-first search from the end over far points (and the contour's points near it).
      std::vector<std::uint8_t> reached(points.size(), 0);
      std::vector<std::size_t> queue;
      for (std::size_t q = 0; q < points.size(); ++q)
      {
        const bool start =
          distanceTo(q, position) <= gap && (nearest[q] > gap - 0.1 || partition.GroupId[q] == c);
        if (start)
        {
          reached[q] = 1;
          queue.push_back(q);
        }
      }
      for (std::size_t m = 0; m < queue.size() && !reached[k]; ++m)
      {
        const std::size_t p = queue[m];
        for (std::size_t q = 0; q < points.size(); ++q)
        {
          if (!reached[q] && nearest[q] > gap - 0.1 &&
            std::hypot(points[q].x - points[p].x, points[q].y - points[p].y) <= gap)
          {
            reached[q] = 1;
            queue.push_back(q);
          }
        }
      }
      EXPECT_TRUE(reached[k]) << where << ": no chain of far points from its end";
    }
  }
  EXPECT_GT(reassigned, 20) << "hardly a point reassigned: the test checks little";
  EXPECT_GT(movedToEnd, 5) << "hardly a point moved to a hooked end: the test checks little";
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
