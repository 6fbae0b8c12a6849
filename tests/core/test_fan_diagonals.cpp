// FansByDiagonals: a ring that no vertex sees whole split along diagonals into fans. Checked
// against exact orientation tests and the ring's own area, and for adding no vertex.

#include "fan_diagonals.h"
#include "polygon_area.h"
#include "polygon_validation.h"
#include "predicates.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

using namespace tessera;

namespace
{

/// An annular sector (anticlockwise): count points along the outer arc from angle 0 to sweep,
/// then back along the inner one; bent enough, no vertex sees it whole.
std::vector<Point2> Arc(double inner, double outer, double sweep, int count)
{
  std::vector<Point2> ring;
  for (int k = 0; k < count; ++k)
  {
    const double a = sweep * k / (count - 1);
    ring.push_back({ outer * std::cos(a), outer * std::sin(a) });
  }
  for (int k = count - 1; k >= 0; --k)
  {
    const double a = sweep * k / (count - 1);
    ring.push_back({ inner * std::cos(a), inner * std::sin(a) });
  }
  return ring;
}

bool IsFan(const std::vector<Point2>& ring)
{
  for (std::size_t k = 1; k + 1 < ring.size(); ++k)
  {
    if (orient2d(ring[0], ring[k], ring[k + 1]) < 0)
    {
      return false;
    }
  }
  return true;
}

} // namespace

// Strips bent into arcs (a thin one of 200 vertices a side, as a tile along a parallel in lon/lat,
// and a thick half annulus): each part is a simple fan about its first vertex, made of the ring's
// own vertices, and the parts' areas add up to the ring's.
TEST(FanDiagonals, BentStripsAreSplitIntoFansOfTheirOwnVertices)
{
  for (const auto& [ring, most] :
    { std::make_pair(Arc(99.9, 100.0, 0.3, 200), 16u), std::make_pair(Arc(1.0, 2.0, 3.1, 40), 8u) })
  {
    SCOPED_TRACE(std::to_string(ring.size()) + " vertices");
    const std::vector<std::vector<Point2>> parts = FansByDiagonals(ring);
    EXPECT_GT(parts.size(), 1u);
    EXPECT_LE(parts.size(), most);
    double area = 0.0;
    for (const std::vector<Point2>& part : parts)
    {
      EXPECT_TRUE(IsFan(part));
      EXPECT_NO_THROW(ValidateRings({ 0, part.size() }, part));
      for (const Point2& p : part)
      {
        EXPECT_NE(std::find(ring.begin(), ring.end(), p), ring.end()) << "a new vertex";
      }
      area += CompensatedPolygonArea(part.data(), part.size());
    }
    const double whole = CompensatedPolygonArea(ring.data(), ring.size());
    EXPECT_NEAR(area, whole, 1e-12 * whole);
  }
}

// A fan is returned whole, started at a vertex that sees it whole (an L given from an outer
// corner that does not: from its inner corner, tried first as reflex); a ring of three vertices
// too.
TEST(FanDiagonals, AFanIsOnePart)
{
  const std::vector<Point2> l{ { 2, 0 }, { 2, 1 }, { 1, 1 }, { 1, 2 }, { 0, 2 }, { 0, 0 } };
  const std::vector<std::vector<Point2>> parts = FansByDiagonals(l);
  ASSERT_EQ(parts.size(), 1u);
  EXPECT_TRUE(IsFan(parts[0]));
  EXPECT_EQ(parts[0][0].x, 1.0); // its inner corner
  EXPECT_EQ(parts[0][0].y, 1.0);
  EXPECT_EQ(FansByDiagonals({ { 0, 0 }, { 1, 0 }, { 0, 1 } }).size(), 1u);
}
