// IdenticalRingPairs against a brute-force reading: two rings are paired exactly when one is the
// other's closed path, read from some start either way round.
#include "identical_rings.h"
#include "test_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

using namespace tessera;
using Pairs = std::vector<std::pair<std::size_t, std::size_t>>;

namespace
{
using RingSet = tessera_test::Rings;

std::vector<Point2> Rotated(std::vector<Point2> ring, std::size_t by)
{
  std::rotate(ring.begin(), ring.begin() + std::ptrdiff_t(by % ring.size()), ring.end());
  return ring;
}

std::vector<Point2> Reversed(std::vector<Point2> ring)
{
  std::reverse(ring.begin(), ring.end());
  return ring;
}

// Brute force: whether b, as a cycle, is a, from some start either way round.
bool SamePath(const std::vector<Point2>& a, const std::vector<Point2>& b)
{
  if (a.size() != b.size())
  {
    return false;
  }
  for (const std::vector<Point2>& c : { b, Reversed(b) })
  {
    for (std::size_t s = 0; s < c.size(); ++s)
    {
      if (Rotated(c, s) == a)
      {
        return true;
      }
    }
  }
  return false;
}
} // namespace

TEST(IdenticalRings, AHoleAndTheIslandThatFillsItArePaired)
{
  const std::vector<Point2> outline{ { 0, 0 }, { 4, 0 }, { 4, 4 }, { 0, 4 } };
  const std::vector<Point2> hole{ { 1, 1 }, { 1, 3 }, { 3, 3 }, { 3, 1 } };
  RingSet rings;
  rings.Add(outline);
  rings.Add(hole);
  // The island: the hole's path from another start, the other way round, closed, with a vertex
  // repeated.
  std::vector<Point2> island = Rotated(Reversed(hole), 2);
  island.insert(island.begin() + 1, island[1]);
  island.push_back(island.front());
  rings.Add(island);
  EXPECT_EQ(IdenticalRingPairs(rings.Offsets, rings.Vertices), (Pairs{ { 1, 2 } }));
}

// Copies inside an outline (holes): the first two of three pair, near copies none. Copies of an
// outer boundary, or of an island inside a hole (inside two rings), would take their region away:
// no pair, left to validation.
TEST(IdenticalRings, CopiesOfAHolePairAndOtherCopiesNone)
{
  const std::vector<Point2> outline{ { -10, -10 }, { 10, -10 }, { 10, 10 }, { -10, 10 } };
  const std::vector<Point2> square{ { 0, 0 }, { 1, 0 }, { 1, 1 }, { 0, 1 } };
  const double inf = std::numeric_limits<double>::infinity();
  RingSet rings;
  rings.Add(outline);                                                // 0
  rings.Add(square);                                                 // 1
  rings.Add({ { 3, 0 }, { 4, 0 }, { 4, 1 } });                       // 2: another ring
  rings.Add(Rotated(square, 3));                                     // 3: the square
  rings.Add({ { 3, 3 }, { 3.5, 3 }, { 4, 3 }, { 4, 4 }, { 3, 4 } }); // 4: 15, a vertex more
  rings.Add(Reversed(square));                                       // 5: the square
  rings.Add({ { 3, 3 }, { 4, 3 }, { 3, 4 }, { 4, 4 } });             // 6: 15's, in another order
  rings.Add({ { 2, 2 }, { 3, 2 }, { std::nan(""), 3 } });            // 7: NaN
  rings.Add({ { 2, 2 }, { 3, 2 }, { std::nan(""), 3 } });            // 8: NaN
  rings.Add({ { 4, 4 }, { 5, 4 }, { inf, 5 } });                     // 9: infinite
  rings.Add({ { 4, 4 }, { 5, 4 }, { inf, 5 } });                     // 10: infinite
  rings.Add({ { 2, 2 }, { 3, 3 }, { 2, 2 } });                       // 11: two distinct vertices
  rings.Add({ { 3, 3 }, { 2, 2 } });                                 // 12: the same two
  // 13, 14: a ring through its smallest vertex twice (touching itself), given twice
  const std::vector<Point2> pinched{ { 5, 5 }, { 7, 5 }, { 7, 6 }, { 5, 5 }, { 6, 7 }, { 5, 7 } };
  rings.Add(pinched);
  rings.Add(pinched);
  rings.Add({ { 3, 3 }, { 4, 3 }, { 4, 4 }, { 3, 4 } }); // 15
  EXPECT_EQ(IdenticalRingPairs(rings.Offsets, rings.Vertices), (Pairs{ { 1, 3 } }));

  RingSet there; // a ring that goes to a point and back: read either way from its smallest vertex
  there.Add(outline);
  const std::vector<Point2> spike{ { 0, 0 }, { 1, 1 }, { 2, 0 }, { 1, 1 }, { 1, 3 } };
  there.Add(spike);
  there.Add(Rotated(Reversed(spike), 2));
  EXPECT_EQ(IdenticalRingPairs(there.Offsets, there.Vertices), (Pairs{ { 1, 2 } }));

  RingSet outer; // an outline given twice beside another ring: its region would go
  outer.Add(square);
  outer.Add({ { 1, 0 }, { 2, 0 }, { 2, 1 }, { 1, 1 } });
  outer.Add(Reversed(square));
  EXPECT_TRUE(IdenticalRingPairs(outer.Offsets, outer.Vertices).empty());

  RingSet island; // an island inside a hole (two rings around it), given twice
  island.Add(outline);
  island.Add({ { -5, -5 }, { 5, -5 }, { 5, 5 }, { -5, 5 } });
  island.Add(square);
  island.Add(Rotated(square, 1));
  EXPECT_TRUE(IdenticalRingPairs(island.Offsets, island.Vertices).empty());

  RingSet touching; // a hole sharing a side with its outline, and its island
  touching.Add({ { 0, 0 }, { 4, 0 }, { 4, 4 }, { 0, 4 } });
  touching.Add({ { 0, 1 }, { 0, 2 }, { 1, 2 }, { 1, 1 } });
  touching.Add({ { 1, 1 }, { 1, 2 }, { 0, 2 }, { 0, 1 } });
  EXPECT_EQ(IdenticalRingPairs(touching.Offsets, touching.Vertices), (Pairs{ { 1, 2 } }));
}

// Random rings from a few shapes apart from each other, each given rotated, reversed, closed or
// with repeated vertices, inside an outline or not: with the outline the pairs agree with a
// brute-force comparison of every two rings (each group of copies paired first with second, third
// with fourth, ...); without it (copies of outer boundaries) there are none.
TEST(IdenticalRings, RandomCopiesAgainstBruteForce)
{
  std::mt19937 rng(17);
  for (int trial = 0; trial < 300; ++trial)
  {
    std::vector<std::vector<Point2>> shapes;
    const int kinds = std::uniform_int_distribution<int>(1, 4)(rng);
    for (int k = 0; k < kinds; ++k)
    {
      std::vector<Point2> shape;
      const int n = std::uniform_int_distribution<int>(3, 6)(rng);
      for (int v = 0; v < n; ++v)
      {
        shape.push_back({ 10.0 * k + double(rng() % 4), double(rng() % 4) });
      }
      shape.erase(std::unique(shape.begin(), shape.end()), shape.end());
      while (shape.size() > 1 && shape.front() == shape.back())
      {
        shape.pop_back();
      }
      const Point2 smallest = *std::min_element(shape.begin(),
        shape.end(),
        [](const Point2& a, const Point2& b) { return a.x != b.x ? a.x < b.x : a.y < b.y; });
      // (a shape through its smallest vertex twice touches itself: in no pair, by design)
      if (shape.size() >= 3 && std::count(shape.begin(), shape.end(), smallest) == 1)
      {
        shapes.push_back(shape);
      }
    }
    if (shapes.empty())
    {
      continue;
    }
    const bool outline = rng() % 2 == 0;
    RingSet rings;
    std::vector<std::vector<Point2>> plain; // each ring without its repeats, as given
    if (outline)
    {
      rings.Add({ { -5, -5 }, { 50, -5 }, { 50, 10 }, { -5, 10 } });
      plain.push_back({});
    }
    const int count = std::uniform_int_distribution<int>(1, 8)(rng);
    for (int r = 0; r < count; ++r)
    {
      std::vector<Point2> ring = shapes[rng() % shapes.size()];
      ring = Rotated(rng() % 2 ? Reversed(ring) : ring, rng() % ring.size());
      plain.push_back(ring);
      if (rng() % 3 == 0)
      {
        ring.push_back(ring.front()); // closed
      }
      if (rng() % 3 == 0)
      {
        ring.insert(ring.begin(), ring.front()); // a repeat
      }
      rings.Add(ring);
    }
    Pairs expected;
    std::vector<char> used(plain.size(), 0);
    for (std::size_t a = outline ? 1 : 0; outline && a < plain.size(); ++a)
    {
      for (std::size_t b = a + 1; b < plain.size() && !used[a]; ++b)
      {
        if (!used[b] && SamePath(plain[a], plain[b]))
        {
          expected.push_back({ a, b });
          used[a] = used[b] = 1;
        }
      }
    }
    EXPECT_EQ(IdenticalRingPairs(rings.Offsets, rings.Vertices), expected) << "trial " << trial;
  }
}
