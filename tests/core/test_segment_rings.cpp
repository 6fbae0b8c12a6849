// JoinSegmentsIntoRings against a brute-force reading: every ring is a closed cycle of the given
// segments, each segment is in one ring or listed as unjoined, and components with a dead end or
// a branching point stay unjoined whole.
#include "segment_rings.h"

#include "polygon_validation.h"

#include "test_support.h"

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

  // Segments of no length (as vtkContourFilter gives between two ids of one point): at a corner
  // of the ring it is not listed, off the ring it is, and at a NaN end too.
  std::vector<Point2> withPoints = ends;
  withPoints.insert(withPoints.end(), { c, c, { 3, 3 }, { 3, 3 }, { nan, 1 }, { nan, 1 } });
  const PointRings points = JoinSegmentsAtEqualEnds(withPoints);
  EXPECT_EQ(points.Vertices, (std::vector<Point2>{ c, b, a, d }));
  EXPECT_EQ(points.Unjoined, (std::vector<std::size_t>{ 5, 6 }));
}

namespace
{

// The rings of a PointRings as vectors of points.
std::vector<std::vector<Point2>> RingsOf(const PointRings& rings)
{
  std::vector<std::vector<Point2>> result;
  for (std::size_t r = 0; r + 1 < rings.Offsets.size(); ++r)
  {
    result.emplace_back(rings.Vertices.begin() + std::ptrdiff_t(rings.Offsets[r]),
      rings.Vertices.begin() + std::ptrdiff_t(rings.Offsets[r + 1]));
  }
  return result;
}

// The segments of the rings, each as its two ends, shuffled and some reversed.
std::vector<Point2> EndsOfRings(const std::vector<std::vector<Point2>>& rings, std::mt19937& rng)
{
  std::vector<std::pair<Point2, Point2>> segments;
  for (const auto& ring : rings)
  {
    for (std::size_t k = 0; k < ring.size(); ++k)
    {
      segments.push_back({ ring[k], ring[(k + 1) % ring.size()] });
    }
  }
  std::shuffle(segments.begin(), segments.end(), rng);
  std::vector<Point2> ends;
  for (auto [a, b] : segments)
  {
    if (rng() % 2)
    {
      std::swap(a, b);
    }
    ends.push_back(a);
    ends.push_back(b);
  }
  return ends;
}

// Each ring as the set of its points, the rings as a multiset of those (start and way aside).
std::multiset<std::set<std::pair<double, double>>> PointSets(
  const std::vector<std::vector<Point2>>& rings)
{
  std::multiset<std::set<std::pair<double, double>>> sets;
  for (const auto& ring : rings)
  {
    std::set<std::pair<double, double>> points;
    for (const Point2& p : ring)
    {
      points.insert({ p.x, p.y });
    }
    EXPECT_EQ(points.size(), ring.size()) << "a ring stands on a point twice";
    sets.insert(points);
  }
  return sets;
}

// Every segment given is in exactly one ring (as an unordered pair of ends).
void ExpectRingsUseEachSegmentOnce(const std::vector<Point2>& ends, const PointRings& rings)
{
  using Key = std::pair<std::pair<double, double>, std::pair<double, double>>;
  const auto key = [](const Point2& a, const Point2& b)
  {
    const std::pair<double, double> p{ a.x, a.y }, q{ b.x, b.y };
    return p < q ? Key{ p, q } : Key{ q, p };
  };
  std::multiset<Key> given;
  for (std::size_t s = 0; 2 * s < ends.size(); ++s)
  {
    given.insert(key(ends[2 * s], ends[2 * s + 1]));
  }
  for (const auto& ring : RingsOf(rings))
  {
    for (std::size_t k = 0; k < ring.size(); ++k)
    {
      const auto it = given.find(key(ring[k], ring[(k + 1) % ring.size()]));
      ASSERT_NE(it, given.end()) << "a ring side that is no segment given";
      given.erase(it);
    }
  }
  EXPECT_TRUE(given.empty()) << given.size() << " segment(s) in no ring";
}

} // namespace

// Where four or six segments meet (a contour through a saddle, squares meeting at a corner, a
// hole touching its outline), segments given by their ends are paired by angle: the rings touch
// there, each stands on a point once, and validation accepts them.
TEST(SegmentRings, RingsMeetingAtAPointAreJoinedTouching)
{
  const std::vector<Point2> square1{ { 0, 0 }, { 1, 0 }, { 1, 1 }, { 0, 1 } };
  const std::vector<Point2> square2{ { 1, 1 }, { 2, 1 }, { 2, 2 }, { 1, 2 } };
  // The outline a b e f g and the hole b c d of the sketch in segment_rings.cpp.
  const std::vector<Point2> outline{ { 0, 4 }, { 2, 4 }, { 4, 4 }, { 4, 0 }, { 0, 0 } };
  const std::vector<Point2> hole{ { 2, 4 }, { 3, 2 }, { 1, 2 } };
  // Three triangles round the origin: six segments meet there.
  const std::vector<Point2> t1{ { 0, 0 }, { 2, 0 }, { 1, 1 } };
  const std::vector<Point2> t2{ { 0, 0 }, { -1, 1 }, { -2, 0 } };
  const std::vector<Point2> t3{ { 0, 0 }, { -1, -2 }, { 1, -2 } };
  const std::vector<std::vector<std::vector<Point2>>> cases{ { square1, square2 },
    { outline, hole },
    { t1, t2, t3 },
    { square1, square2, { { 2, 2 }, { 3, 2 }, { 3, 3 }, { 2, 3 } } } };
  std::mt19937 rng(3);
  for (std::size_t c = 0; c < cases.size(); ++c)
  {
    for (int trial = 0; trial < 20; ++trial)
    {
      const std::vector<Point2> ends = EndsOfRings(cases[c], rng);
      const PointRings rings = JoinSegmentsAtEqualEnds(ends);
      EXPECT_TRUE(rings.Unjoined.empty()) << "case " << c;
      EXPECT_EQ(PointSets(RingsOf(rings)), PointSets(cases[c]))
        << "case " << c << " trial " << trial;
      ExpectRingsUseEachSegmentOnce(ends, rings);
      EXPECT_NO_THROW(ValidateRings(rings.Offsets, rings.Vertices)) << "case " << c;
      for (const std::vector<Point2>& ring : RingsOf(rings))
      {
        EXPECT_EQ(tessera_test::RingDefect(ring), "") << "case " << c; // (apart from ValidateRings)
      }
    }
  }
  // The id-only join has no angles to pair by: it leaves the two squares unjoined.
  Segments ids;
  for (std::int64_t k = 0; k < 4; ++k)
  {
    ids.push_back({ k, (k + 1) % 4 });
    ids.push_back({ k == 2 ? 2 : 10 + k, k == 1 ? 2 : 10 + (k + 1) % 4 });
  }
  EXPECT_EQ(JoinSegmentsIntoRings(ids).Unjoined.size(), 8u);
}

// Dead ends, and the chains that lead to them, stay unjoined, and the closed paths through their
// points are joined without them: a square with a spur at a corner, or a lobe with two open
// branches at its corner (as a contour at a saddle's level whose branches reach its domain's edge),
// in each of four rotations. Where two of four segments leave in one direction (overlapping), or a
// far end is NaN, the chains through that point stay unjoined; a ring elsewhere is joined.
TEST(SegmentRings, DeadEndsOverlapsAndNaNEndsStayUnjoined)
{
  const double nan = std::nan("");
  // The ends of the sides of closed rings, in order.
  const auto closed = [](const std::vector<std::vector<Point2>>& rings)
  {
    std::vector<Point2> ends;
    for (const auto& ring : rings)
    {
      for (std::size_t k = 0; k < ring.size(); ++k)
      {
        ends.insert(ends.end(), { ring[k], ring[(k + 1) % ring.size()] });
      }
    }
    return ends;
  };
  const std::vector<Point2> apart{ { 20, 0 }, { 21, 0 }, { 21, 1 } };
  const auto joinedWith = [&](std::vector<Point2> junk)
  {
    std::vector<Point2> ends = closed({ apart });
    ends.insert(ends.end(), junk.begin(), junk.end());
    return JoinSegmentsAtEqualEnds(ends);
  };
  const auto rotated = [](std::vector<Point2> points, int quarterTurns)
  {
    for (Point2& p : points)
    {
      for (int q = 0; q < quarterTurns; ++q)
      {
        p = { -p.y, p.x };
      }
    }
    return points;
  };
  // A square (0,0)-(1,1) with a spur from (1,1) to (2,2); a lobe with branches to (-3,0), (0,-3).
  std::vector<Point2> spur = closed({ { { 0, 0 }, { 1, 0 }, { 1, 1 }, { 0, 1 } } });
  spur.insert(spur.end(), { { 1, 1 }, { 2, 2 } });
  std::vector<Point2> branches = closed({ { { 0, 0 }, { 1, 0 }, { 1, 1 }, { 0, 1 } } });
  branches.insert(branches.end(), { { -3, 0 }, { 0, 0 }, { 0, 0 }, { 0, -3 } });
  for (const auto& [junk, deadSegments] : { std::make_pair(spur, std::vector<std::size_t>{ 7 }),
         std::make_pair(branches, std::vector<std::size_t>{ 7, 8 }) })
  {
    for (int q = 0; q < 4; ++q)
    {
      const PointRings rings = joinedWith(rotated(junk, q));
      ASSERT_EQ(rings.Offsets.size(), 3u) << "rotation " << q;
      EXPECT_EQ(RingsOf(rings)[0], apart);
      EXPECT_EQ(PointSets({ RingsOf(rings)[1] }),
        PointSets({ rotated({ { 0, 0 }, { 1, 0 }, { 1, 1 }, { 0, 1 } }, q) }));
      EXPECT_EQ(rings.Unjoined, deadSegments) << "rotation " << q;
    }
  }
  // Two triangles at (0,0) whose sides from it to (1,0) and (2,0) run along one direction.
  const PointRings overlap =
    joinedWith(closed({ { { 0, 0 }, { 1, 0 }, { 0, 1 } }, { { 0, 0 }, { 2, 0 }, { 0, -1 } } }));
  ASSERT_EQ(overlap.Offsets.size(), 2u);
  EXPECT_EQ(overlap.Unjoined, (std::vector<std::size_t>{ 3, 4, 5, 6, 7, 8 }));
  // Two triangles at (0,0), one of whose far ends is NaN: its NaN ends meet nothing, so its
  // three segments are a dead chain, and the other triangle is joined.
  const PointRings withNaN =
    joinedWith(closed({ { { 0, 0 }, { 1, 0 }, { 0, 1 } }, { { 0, 0 }, { nan, 0 }, { 0, -1 } } }));
  ASSERT_EQ(withNaN.Offsets.size(), 3u);
  EXPECT_EQ(RingsOf(withNaN)[1], (std::vector<Point2>{ { 0, 0 }, { 1, 0 }, { 0, 1 } }));
  EXPECT_EQ(withNaN.Unjoined, (std::vector<std::size_t>{ 6, 7, 8 }));
}

// Random sets of black squares of a checkerboard, which meet only at corners (four segments
// there, or none): every segment is in one ring, no ring stands on a point twice, validation
// accepts the rings, and by the even-odd rule each square's centre is inside exactly when it was
// chosen.
TEST(SegmentRings, RandomCheckerboardsAgainstTheirSquares)
{
  std::mt19937 rng(11);
  for (int trial = 0; trial < 300; ++trial)
  {
    const int n = std::uniform_int_distribution<int>(2, 7)(rng);
    std::vector<std::vector<Point2>> squares;
    std::set<std::pair<int, int>> chosen;
    for (int i = 0; i < n; ++i)
    {
      for (int j = (i % 2); j < n; j += 2)
      {
        if (rng() % 4 != 0)
        {
          chosen.insert({ i, j });
          squares.push_back({ { double(i), double(j) },
            { double(i + 1), double(j) },
            { double(i + 1), double(j + 1) },
            { double(i), double(j + 1) } });
        }
      }
    }
    const std::vector<Point2> ends = EndsOfRings(squares, rng);
    const PointRings rings = JoinSegmentsAtEqualEnds(ends);
    EXPECT_TRUE(rings.Unjoined.empty()) << "trial " << trial;
    ExpectRingsUseEachSegmentOnce(ends, rings);
    PointSets(RingsOf(rings)); // (each ring's points distinct)
    if (!squares.empty())
    {
      EXPECT_NO_THROW(ValidateRings(rings.Offsets, rings.Vertices)) << "trial " << trial;
      for (const std::vector<Point2>& ring : RingsOf(rings))
      {
        EXPECT_EQ(tessera_test::RingDefect(ring), "") << "trial " << trial;
      }
    }
    for (int i = 0; i < n; ++i)
    {
      for (int j = 0; j < n; ++j)
      {
        // Crossings of the ray from the centre to +x with the rings' sides, by the even-odd rule.
        const double x = i + 0.5, y = j + 0.5;
        bool inside = false;
        for (const auto& ring : RingsOf(rings))
        {
          for (std::size_t k = 0; k < ring.size(); ++k)
          {
            const Point2 a = ring[k], b = ring[(k + 1) % ring.size()];
            if ((a.y > y) != (b.y > y) && a.x + (y - a.y) * (b.x - a.x) / (b.y - a.y) > x)
            {
              inside = !inside;
            }
          }
        }
        EXPECT_EQ(inside, chosen.count({ i, j }) == 1)
          << "trial " << trial << " square " << i << "," << j;
      }
    }
  }
}
