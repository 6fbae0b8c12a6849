// JoinSegmentsIntoRings against a brute-force reading: every ring is a closed cycle of the given
// segments, each segment is in one ring or listed as unjoined, and components with a dead end or
// a branching point stay unjoined whole.
#include "segment_rings.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <random>
#include <set>

using namespace tessera;
using Segments = std::vector<std::pair<std::int64_t, std::int64_t>>;

namespace
{

// The segments of ring k as unordered pairs; checks that consecutive ids (cyclically) are joined
// by a given segment, each used once.
void ExpectRingsAreCyclesOfSegments(const Segments& segments, const SegmentRings& rings)
{
  std::multiset<std::pair<std::int64_t, std::int64_t>> unused;
  for (std::size_t s = 0; s < segments.size(); ++s)
  {
    if (!std::binary_search(rings.Unjoined.begin(), rings.Unjoined.end(), s))
    {
      const auto [a, b] = segments[s];
      unused.insert({ std::min(a, b), std::max(a, b) });
    }
  }
  for (std::size_t r = 0; r + 1 < rings.Offsets.size(); ++r)
  {
    const std::size_t begin = rings.Offsets[r], end = rings.Offsets[r + 1];
    ASSERT_GE(end - begin, 2u);
    for (std::size_t k = begin; k < end; ++k)
    {
      const std::int64_t a = rings.Ids[k], b = rings.Ids[k + 1 == end ? begin : k + 1];
      const auto it = unused.find({ std::min(a, b), std::max(a, b) });
      ASSERT_NE(it, unused.end()) << "ring " << r << " edge " << a << "-" << b;
      unused.erase(it);
    }
  }
  EXPECT_TRUE(unused.empty()) << "a joined segment is in no ring";
}

} // namespace

TEST(SegmentRings, ASquareInAnyOrderAndDirectionIsOneRing)
{
  const Segments square{ { 1, 2 }, { 3, 2 }, { 3, 4 }, { 4, 1 } };
  Segments shuffled{ { 4, 3 }, { 1, 4 }, { 2, 1 }, { 2, 3 } };
  for (const Segments& segments : { square, shuffled })
  {
    const SegmentRings rings = JoinSegmentsIntoRings(segments);
    ASSERT_EQ(rings.Offsets.size(), 2u);
    EXPECT_EQ(rings.Ids.size(), 4u);
    EXPECT_TRUE(rings.Unjoined.empty());
    ExpectRingsAreCyclesOfSegments(segments, rings);
  }
  const SegmentRings rings = JoinSegmentsIntoRings(square);
  EXPECT_EQ(rings.Ids, (std::vector<std::int64_t>{ 1, 2, 3, 4 })) << "the first segment's way";
}

TEST(SegmentRings, DeadEndsBranchesAndPointSegmentsStayUnjoined)
{
  // A triangle (ring), an open chain, a square with a dangling segment at a corner (three
  // segments meet there: the whole square stays unjoined), a figure eight, a point segment.
  const Segments segments{
    { 10, 11 },
    { 11, 12 },
    { 12, 10 }, // 0-2: ring
    { 20, 21 },
    { 21, 22 }, // 3-4: open chain
    { 30, 31 },
    { 31, 32 },
    { 32, 33 },
    { 33, 30 }, // 5-8: square ...
    { 30, 34 }, // 9: ... with a dangling segment
    { 40, 41 },
    { 41, 42 },
    { 42, 40 },
    { 40, 43 },
    { 43, 44 },
    { 44, 40 }, // 10-15: eight
    { 50, 50 }, // 16: a point
  };
  const SegmentRings rings = JoinSegmentsIntoRings(segments);
  ASSERT_EQ(rings.Offsets.size(), 2u);
  EXPECT_EQ(rings.Ids, (std::vector<std::int64_t>{ 10, 11, 12 }));
  std::vector<std::size_t> expected;
  for (std::size_t s = 3; s < segments.size(); ++s)
  {
    expected.push_back(s);
  }
  EXPECT_EQ(rings.Unjoined, expected);
}

// Random sets of disjoint cycles, open chains and branches, shuffled and flipped: the rings are
// exactly the cycles (by their point sets), against the construction.
TEST(SegmentRings, RandomCyclesChainsAndBranchesAgainstTheirConstruction)
{
  std::mt19937 rng(5);
  for (int trial = 0; trial < 200; ++trial)
  {
    Segments segments;
    std::set<std::set<std::int64_t>> cycles;
    std::size_t cycleSegments = 0;
    std::int64_t next = 0;
    const int components = std::uniform_int_distribution<int>(1, 6)(rng);
    for (int c = 0; c < components; ++c)
    {
      const int kind = std::uniform_int_distribution<int>(0, 2)(rng); // cycle, chain, branched
      const int length = std::uniform_int_distribution<int>(2, 9)(rng);
      const std::int64_t first = next;
      for (int k = 0; k + 1 < length; ++k)
      {
        segments.push_back({ first + k, first + k + 1 });
      }
      if (kind != 1)
      {
        segments.push_back({ first + length - 1, first }); // close it
      }
      if (kind == 2)
      {
        segments.push_back({ first, first + length }); // a third segment at `first`
        ++next;
      }
      if (kind == 0)
      {
        std::set<std::int64_t> ids;
        for (int k = 0; k < length; ++k)
        {
          ids.insert(first + k);
        }
        cycles.insert(ids);
        cycleSegments += std::size_t(length);
      }
      next += length;
    }
    std::shuffle(segments.begin(), segments.end(), rng);
    for (auto& segment : segments)
    {
      if (rng() % 2)
      {
        std::swap(segment.first, segment.second);
      }
    }
    const SegmentRings rings = JoinSegmentsIntoRings(segments);
    ExpectRingsAreCyclesOfSegments(segments, rings);
    std::set<std::set<std::int64_t>> found;
    for (std::size_t r = 0; r + 1 < rings.Offsets.size(); ++r)
    {
      found.insert(std::set<std::int64_t>(rings.Ids.begin() + std::ptrdiff_t(rings.Offsets[r]),
        rings.Ids.begin() + std::ptrdiff_t(rings.Offsets[r + 1])));
    }
    EXPECT_EQ(found, cycles) << "trial " << trial;
    EXPECT_EQ(rings.Unjoined.size(), segments.size() - cycleSegments) << "trial " << trial;
  }
}

// Ends meet where their coordinates are equal (each segment with points of its own, as line
// features read from a file); an end with a NaN coordinate meets none, and does not upset the sort.
TEST(SegmentRings, EndsMeetWhereTheirCoordinatesAreEqual)
{
  const Point2 a{ 0, 0 }, b{ 1, 0 }, c{ 1, 1 }, d{ 0, 1 };
  const std::vector<Point2> ends{ c, b, a, b, d, c, a, d };
  const PointRings rings = JoinSegmentsAtEqualEnds(ends);
  ASSERT_EQ(rings.Offsets, (std::vector<std::size_t>{ 0, 4 }));
  EXPECT_TRUE(rings.Unjoined.empty());
  // The first segment's direction: c, b, then on around the square.
  EXPECT_EQ(rings.Vertices, (std::vector<Point2>{ c, b, a, d }));

  const double nan = std::nan("");
  std::vector<Point2> withNan = ends;
  withNan.insert(
    withNan.end(), { { 5, 5 }, { nan, 5 }, { nan, 5 }, { 5, 5 }, { 2, nan }, { 2, 2 } });
  const PointRings partly = JoinSegmentsAtEqualEnds(withNan);
  EXPECT_EQ(partly.Offsets, (std::vector<std::size_t>{ 0, 4 }));
  EXPECT_EQ(partly.Unjoined, (std::vector<std::size_t>{ 4, 5, 6 }));
}
