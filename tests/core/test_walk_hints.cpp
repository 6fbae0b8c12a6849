// Walk hints (core/walk_hints.h): the triangles indexed beside a point along the Hilbert curve lie
// near it, so that a streamed point's walk is short, and the index built for half the triangles
// still finds triangles near points inserted since. (Streams that use them equal the batch:
// test_dirichlet_tessellation's StreamingWithJumpsEqualsBatch.)

#include "dirichlet_tessellation.h"
#include "tiles.h"
#include "walk_hints.h"
#include "window.h"

#include "test_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

using namespace tessera;

namespace
{

// The distance from p to the nearest vertex of the triangles (HUGE_VAL for none).
double NearestVertex(const DirichletTessellation& t,
  const Point2& p,
  const std::int32_t* near,
  int count)
{
  double best = HUGE_VAL;
  for (int k = 0; k < count; ++k)
  {
    for (int c = 0; c < 3; ++c)
    {
      const std::int32_t v = t.Origin()[3 * std::size_t(near[k]) + c];
      if (v >= 0)
      {
        best = std::min(best, std::hypot(t.Points()[v].x - p.x, t.Points()[v].y - p.y));
      }
    }
  }
  return best;
}

} // namespace

TEST(WalkHints, TrianglesBesidePointsLieNearThem)
{
  const std::vector<Point2> points = tessera_test::UniformPoints(20000, 3);
  // Built for the first half of the points: the second half's points still find triangles
  // within a few spacings (1 / sqrt(10^4) = 0.01) nearly always.
  const std::vector<Point2> half(points.begin(), points.begin() + 10000);
  const DirichletTessellation t(Window::Rectangle(-0.1, 1.1, -0.1, 1.1), half);
  WalkHints hints;
  std::int32_t near[3];
  EXPECT_EQ(hints.Near({ 0.5, 0.5 }, near), 0); // (before a Build)
  hints.Build(t.Origin().data(), t.Origin().size(), t.Points(), 0);
  EXPECT_EQ(hints.BuiltFor(), t.Origin().size() / 3);
  int close = 0;
  for (std::size_t k = 10000; k < points.size(); ++k)
  {
    const int count = hints.Near(points[k], near);
    ASSERT_GE(count, 1);
    ASSERT_LE(count, 3);
    close += NearestVertex(t, points[k], near, count) < 0.05;
  }
  EXPECT_GT(close, 9500) << close; // (the Hilbert curve's rare jumps across quadrant borders aside)
  // Points far outside the indexed box take its edge's cells and still get triangles.
  EXPECT_GE(hints.Near({ -50.0, 1e9 }, near), 1);
}

// A box so small that its scale overflows (a side below 65536 / DBL_MAX) gives no index: the
// point at the box's edge made 0 * inf, a NaN cell (undefined behaviour, caught by the sanitizer
// build's float-cast-overflow); streaming such points, copies included, still equals the batch.
TEST(WalkHints, ABoxTooSmallToScaleGivesNoIndex)
{
  std::vector<Point2> points = tessera_test::UniformPoints(3000, 5, 0.0, 1e-305);
  points.push_back(*std::min_element(
    points.begin(), points.end(), [](const Point2& a, const Point2& b) { return a.x < b.x; }));
  const Window window = Window::Rectangle(-1e-305, 2e-305, -1e-305, 2e-305);
  const DirichletTessellation batch(window, points);
  WalkHints hints;
  hints.Build(batch.Origin().data(), batch.Origin().size(), batch.Points(), 0);
  std::int32_t near[3];
  EXPECT_EQ(hints.Near(points.back(), near), 0);
  DirichletTessellation streamed(window);
  for (const Point2& p : points)
  {
    streamed.Insert(p);
  }
  EXPECT_EQ(streamed.AcceptedCount(), batch.AcceptedCount());
  EXPECT_EQ(streamed.Duplicates(), batch.Duplicates());
  EXPECT_EQ(tessera_test::SortedFaces(TessellationDual(streamed).Faces(false)),
    tessera_test::SortedFaces(TessellationDual(batch).Faces(false)));
}
