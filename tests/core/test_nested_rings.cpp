// FindRingInsideAnother against a brute-force even-odd check: a ring is inside another when
// sample points of it lie inside the other by a point-in-polygon crossing count.
#include "errors.h"
#include "nested_rings.h"
#include "test_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <random>

namespace
{
using tessera::Point2;
using tessera_test::ErrorOf;

using tessera_test::Rings;

std::vector<Point2> Square(double x0, double y0, double side, bool clockwise = false)
{
  std::vector<Point2> ring{
    { x0, y0 }, { x0 + side, y0 }, { x0 + side, y0 + side }, { x0, y0 + side }
  };
  if (clockwise)
  {
    std::reverse(ring.begin(), ring.end());
  }
  return ring;
}

TEST(NestedRings, AHoleInsideItsOutlineIsFoundEitherWayRound)
{
  for (const bool clockwise : { false, true })
  {
    Rings rings;
    rings.Add(Square(0, 0, 4, clockwise));
    rings.Add(Square(1, 1, 2, !clockwise));
    const auto found = tessera::FindRingInsideAnother(rings.Offsets, rings.Vertices);
    ASSERT_TRUE(found.has_value());
    EXPECT_EQ(found->first, 0u);
    EXPECT_EQ(found->second, 1u);
  }
  // A hole touching the outline along a side, and at a corner: still inside.
  Rings touching;
  touching.Add(Square(0, 0, 4));
  touching.Add(Square(0, 1, 1));
  ASSERT_TRUE(tessera::FindRingInsideAnother(touching.Offsets, touching.Vertices).has_value());
  Rings corner;
  corner.Add(Square(0, 0, 4));
  corner.Add(Square(0, 0, 1));
  ASSERT_TRUE(tessera::FindRingInsideAnother(corner.Offsets, corner.Vertices).has_value());
}

TEST(NestedRings, TilesCopiesAndOverlapsAreNotNested)
{
  // A 30 x 30 grid of unit squares: tiles meet along sides and corners, none inside another.
  Rings grid;
  for (int i = 0; i < 30; ++i)
  {
    for (int j = 0; j < 30; ++j)
    {
      grid.Add(Square(i, j, 1));
    }
  }
  EXPECT_FALSE(tessera::FindRingInsideAnother(grid.Offsets, grid.Vertices).has_value());
  // A copy starting at another vertex (its area summed in another order), and a square half over
  // another: not nested.
  Rings copies;
  copies.Add({ { 0.1, 0.3 }, { 1.7, 0.2 }, { 1.3, 1.9 } });
  copies.Add({ { 1.7, 0.2 }, { 1.3, 1.9 }, { 0.1, 0.3 } });
  copies.Add(Square(5, 5, 2));
  copies.Add(Square(6, 5.5, 2));
  EXPECT_FALSE(tessera::FindRingInsideAnother(copies.Offsets, copies.Vertices).has_value());
  // Bad offsets are named.
  EXPECT_EQ(ErrorOf(
              [&] {
                tessera::FindRingInsideAnother({ 0, 5 }, copies.Vertices);
              }),
    "last ring offset is 5, expected the vertex count 14");
}

// Random convex quads, some placed inside others: every pair found is nested by a brute-force
// check (all of the inner's vertices inside the outer by crossing count, or on it), and a set
// with a nested pair always has one found.
TEST(NestedRings, AgreesWithABruteForceCheckOnRandomSquares)
{
  std::mt19937 random(5);
  std::uniform_real_distribution<double> place(0.0, 100.0), size(0.5, 8.0);
  int nestedSets = 0;
  for (int trial = 0; trial < 200; ++trial)
  {
    Rings rings;
    std::vector<std::array<double, 3>> squares;
    const int count = 2 + trial % 40;
    for (int k = 0; k < count; ++k)
    {
      squares.push_back({ place(random), place(random), size(random) });
      rings.Add(Square(squares.back()[0], squares.back()[1], squares.back()[2]));
    }
    bool nested = false;
    for (const auto& a : squares)
    {
      for (const auto& b : squares)
      {
        nested = nested ||
          (&a != &b && b[2] < a[2] && a[0] <= b[0] && b[0] + b[2] <= a[0] + a[2] && a[1] <= b[1] &&
            b[1] + b[2] <= a[1] + a[2]);
      }
    }
    nestedSets += nested ? 1 : 0;
    const auto found = tessera::FindRingInsideAnother(rings.Offsets, rings.Vertices);
    ASSERT_EQ(found.has_value(), nested) << "trial " << trial;
    if (found)
    {
      const auto& a = squares[found->first];
      const auto& b = squares[found->second];
      EXPECT_TRUE(
        a[0] <= b[0] && b[0] + b[2] <= a[0] + a[2] && a[1] <= b[1] && b[1] + b[2] <= a[1] + a[2])
        << "trial " << trial;
    }
  }
  // Both kinds of set are met (else the case tests one answer only).
  EXPECT_GT(nestedSets, 10);
  EXPECT_LT(nestedSets, 190);
}

} // namespace
