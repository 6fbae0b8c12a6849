// IdenticalRingPairs against a brute-force reading: two rings are paired exactly when one is the
// other's closed path, read from some start either way round.
#include "identical_rings.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

using namespace tessera;
using Pairs = std::vector<std::pair<std::size_t, std::size_t>>;

namespace
{
struct RingSet
{
  std::vector<std::size_t> Offsets{ 0 };
  std::vector<Point2> Vertices;
  void Add(const std::vector<Point2>& ring)
  {
    this->Vertices.insert(this->Vertices.end(), ring.begin(), ring.end());
    this->Offsets.push_back(this->Vertices.size());
  }
};

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

TEST(IdenticalRings, ThreeCopiesPairTwoAndNearCopiesNone)
{
  const std::vector<Point2> square{ { 0, 0 }, { 1, 0 }, { 1, 1 }, { 0, 1 } };
  RingSet rings;
  rings.Add(square);                                                 // 0
  rings.Add({ { 0, 0 }, { 1, 0 }, { 1, 1 } });                       // 1: another ring
  rings.Add(Rotated(square, 3));                                     // 2: the square
  rings.Add({ { 0, 0 }, { 0.5, 0 }, { 1, 0 }, { 1, 1 }, { 0, 1 } }); // 3: same region, other path
  rings.Add(Reversed(square));                                       // 4: the square
  rings.Add({ { 0, 0 }, { 1, 0 }, { 0, 1 }, { 1, 1 } }); // 5: its vertices in another order
  rings.Add({ { 0, 0 }, { 1, 0 }, { std::nan(""), 1 }, { 0, 1 } }); // 6: NaN
  rings.Add({ { 0, 0 }, { 1, 0 }, { std::nan(""), 1 }, { 0, 1 } }); // 7: NaN
  rings.Add({ { 2, 2 }, { 3, 3 }, { 2, 2 } });                      // 8: two distinct vertices
  rings.Add({ { 3, 3 }, { 2, 2 } });                                // 9: the same two
  EXPECT_EQ(IdenticalRingPairs(rings.Offsets, rings.Vertices), (Pairs{ { 0, 2 } }));
}

// Random rings from a few shapes, each given rotated, reversed, closed or with repeated vertices:
// the pairs agree with a brute-force comparison of every two rings (each group of identical rings
// paired first with second, third with fourth, ...).
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
        shape.push_back({ double(rng() % 4), double(rng() % 4) });
      }
      shape.erase(std::unique(shape.begin(), shape.end()), shape.end());
      while (shape.size() > 1 && shape.front() == shape.back())
      {
        shape.pop_back();
      }
      if (shape.size() >= 3)
      {
        shapes.push_back(shape);
      }
    }
    if (shapes.empty())
    {
      continue;
    }
    RingSet rings;
    std::vector<std::vector<Point2>> plain; // each ring without its repeats, as given
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
    for (std::size_t a = 0; a < plain.size(); ++a)
    {
      for (std::size_t b = a + 1; b < plain.size() && !used[a]; ++b)
      {
        // (a shape whose path visits a point twice reads the same from two starts: still one path)
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
