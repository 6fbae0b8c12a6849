// core/snap_to_segments: a vertex a hair off another ring's segment becomes a vertex of that
// segment too, in order along it; vertices near a segment's ends, of the segment's own ring, or
// beyond the tolerance are left alone; a T-junction rounded across the shared border made rings
// that crossed (ValidateRings), and no longer do.
#include "errors.h"
#include "polygon_validation.h"
#include "ring_insertions.h"
#include "snap_to_segments.h"
#include "test_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

using namespace tessera;
using tessera_test::ErrorOf;

namespace
{

// Two unit squares side by side sharing the border x = 1; the left one's border carries extra
// vertices at the given heights, each moved off the line by its own offset in x.
struct Neighbours
{
  std::vector<std::size_t> Offsets{ 0 };
  std::vector<Point2> Vertices;
  Neighbours(std::vector<std::pair<double, double>> junctions)
  {
    // Left square, anticlockwise: up its east side, through the junctions (ascending y).
    std::sort(junctions.begin(), junctions.end());
    Vertices = { { 0, 0 }, { 1, 0 } };
    for (const auto& [y, dx] : junctions)
    {
      Vertices.push_back({ 1 + dx, y });
    }
    Vertices.insert(Vertices.end(), { { 1, 1 }, { 0, 1 } });
    Offsets.push_back(Vertices.size());
    // Right square: its west side x = 1 is one segment, from (1, 1) down to (1, 0).
    Vertices.insert(Vertices.end(), { { 1, 0 }, { 2, 0 }, { 2, 1 }, { 1, 1 } });
    Offsets.push_back(Vertices.size());
  }
};

} // namespace

TEST(SnapToSegments, JunctionsBecomeVerticesOfTheOtherRingInOrder)
{
  const Neighbours rings({ { 0.25, 3e-7 }, { 0.7, -6e-7 }, { 0.5, 0.0 } });
  const SnappedRings out = SnapVerticesOntoSegments(rings.Offsets, rings.Vertices, 1e-6);
  ASSERT_EQ(out.Inserted, 3u);
  ASSERT_EQ(out.Offsets, (std::vector<std::size_t>{ 0, 7, 14 }));
  // The left ring unchanged (junctions at 0.25, 0.5, 0.7: vertices 2, 3, 4); the right one's
  // west side (its segment 3, from (1, 1) to (1, 0)) goes through them from the top down, each
  // with the left ring's own coordinates.
  for (std::size_t k = 0; k < 7; ++k)
  {
    EXPECT_EQ(out.Vertices[k], rings.Vertices[k]) << k;
    EXPECT_EQ(out.SegmentOf[k], k);
  }
  const std::vector<Point2> right = {
    { 1, 0 }, { 2, 0 }, { 2, 1 }, { 1, 1 }, rings.Vertices[4], rings.Vertices[3], rings.Vertices[2]
  };
  const std::vector<std::size_t> segments = { 0, 1, 2, 3, 3, 3, 3 };
  for (std::size_t k = 0; k < right.size(); ++k)
  {
    EXPECT_EQ(out.Vertices[7 + k], right[k]) << k;
    EXPECT_EQ(out.SegmentOf[7 + k], segments[k]) << k;
  }
}

TEST(RingInsertions, RingsWithoutSegmentNumbersAreTheSameRings)
{
  // Two rings; insertions on the first ring's edges 0 and 2 and on the second's last edge (6),
  // one of them equal to the vertex written before it (added once) and two on one edge.
  const std::vector<std::size_t> offsets{ 0, 4, 7 };
  const std::vector<Point2> vertices{
    { 0, 0 }, { 2, 0 }, { 2, 2 }, { 0, 2 }, { 3, 0 }, { 5, 0 }, { 4, 2 }
  };
  std::vector<RingInsertion> insertions{ { 2, 0.5, { 1, 2 } },
    { 0, 0.75, { 1.5, 0 } },
    { 6, 0.5, { 3.5, 1 } },
    { 0, 0.25, { 0.5, 0 } },
    { 6, 0.0, { 4, 2 } } };
  SortAlongEdges(insertions);
  const InsertedRings kept = InsertIntoRings(offsets, vertices, insertions, SegmentNumbers::Kept);
  const InsertedRings dropped =
    InsertIntoRings(offsets, vertices, insertions, SegmentNumbers::Dropped);
  EXPECT_EQ(kept.Offsets, (std::vector<std::size_t>{ 0, 7, 11 }));
  EXPECT_EQ(kept.Vertices,
    (std::vector<Point2>{ { 0, 0 },
      { 0.5, 0 },
      { 1.5, 0 },
      { 2, 0 },
      { 2, 2 },
      { 1, 2 },
      { 0, 2 }, //
      { 3, 0 },
      { 5, 0 },
      { 4, 2 },
      { 3.5, 1 } }));
  EXPECT_EQ(kept.SegmentOf, (std::vector<std::size_t>{ 0, 0, 0, 1, 2, 2, 3, 0, 1, 2, 2 }));
  EXPECT_EQ(kept.Inserted, 4u);
  EXPECT_EQ(dropped.Offsets, kept.Offsets);
  EXPECT_EQ(dropped.Vertices, kept.Vertices);
  EXPECT_EQ(dropped.Inserted, kept.Inserted);
  EXPECT_TRUE(dropped.SegmentOf.empty());
}

TEST(SnapToSegments, OnlyJunctionsOfOtherRingsWithinTheTolerance)
{
  // 2e-6 off the line (beyond the tolerance), and 5e-7 from the corner (1, 1) (within it of the
  // segment's end: two vertices of one place, not a junction): left alone.
  const Neighbours far({ { 0.5, 2e-6 }, { 1 - 5e-7, 1e-7 } });
  EXPECT_EQ(SnapVerticesOntoSegments(far.Offsets, far.Vertices, 1e-6).Inserted, 0u);
  // A ring's own vertex near its own segment is not a junction between rings.
  const std::vector<std::size_t> one{ 0, 5 };
  const std::vector<Point2> notch{ { 0, 0 }, { 2, 0 }, { 2, 1 }, { 1, 1e-7 }, { 0, 1 } };
  EXPECT_EQ(SnapVerticesOntoSegments(one, notch, 1e-6).Inserted, 0u);
}

TEST(SnapToSegments, RoundedJunctionsNoLongerMakeTheRingsCross)
{
  // Junctions rounded across the border crossed it (refused); put onto it, the rings validate.
  std::mt19937_64 random(5);
  std::uniform_real_distribution<double> height(0.05, 0.95), off(-7e-7, 7e-7);
  int crossedBefore = 0;
  for (int trial = 0; trial < 20; ++trial)
  {
    std::vector<std::pair<double, double>> junctions(3);
    for (auto& j : junctions)
    {
      j = { height(random), off(random) };
    }
    const Neighbours rings(junctions);
    const bool crossed = !ErrorOf([&] { ValidateRings(rings.Offsets, rings.Vertices); }).empty();
    crossedBefore += crossed;
    const SnappedRings out = SnapVerticesOntoSegments(rings.Offsets, rings.Vertices, 1e-6);
    EXPECT_EQ(out.Inserted, 3u);
    EXPECT_EQ(ErrorOf([&] { ValidateRings(out.Offsets, out.Vertices, &out.SegmentOf); }), "")
      << "trial " << trial << (crossed ? " (crossed before)" : "");
  }
  EXPECT_GT(crossedBefore, 0); // (a junction off to the right side crosses the other ring)
}
