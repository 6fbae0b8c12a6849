// FansByDiagonals: a ring that no vertex sees whole split along diagonals into fans. Checked
// against exact orientation tests and the ring's own area, and for adding no vertex.

#include "areal_average.h"
#include "fan_diagonals.h"
#include "polygon_area.h"
#include "predicates.h"

#include "test_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

using namespace tessera;
using tessera_test::RingOf;

namespace
{

/// An annular sector (anticlockwise): count points along the outer arc from angle 0 to sweep,
/// then back along the inner one (innerCount of them, count by default); bent enough, no vertex
/// sees it whole.
std::vector<Point2> Arc(double inner, double outer, double sweep, int count, int innerCount = 0)
{
  innerCount = innerCount > 0 ? innerCount : count;
  std::vector<Point2> ring;
  for (int k = 0; k < count; ++k)
  {
    const double a = sweep * k / (count - 1);
    ring.push_back({ outer * std::cos(a), outer * std::sin(a) });
  }
  for (int k = innerCount - 1; k >= 0; --k)
  {
    const double a = sweep * k / (innerCount - 1);
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
  // (and a strip of 10 vertices outside, 200 inside: halving diagonals from 16 starts only found
  // none, and it was left whole)
  for (const auto& [ring, most] : { std::make_pair(Arc(99.9, 100.0, 0.3, 200), 16u),
         std::make_pair(Arc(1.0, 2.0, 3.1, 40), 8u),
         std::make_pair(Arc(99.0, 100.0, 0.5, 10, 200), 2u) })
  {
    SCOPED_TRACE(std::to_string(ring.size()) + " vertices");
    const std::vector<std::vector<Point2>> parts = FansByDiagonals(ring);
    EXPECT_GT(parts.size(), 1u);
    EXPECT_LE(parts.size(), most);
    double area = 0.0;
    for (const std::vector<Point2>& part : parts)
    {
      EXPECT_TRUE(IsFan(part));
      EXPECT_EQ(tessera_test::RingDefect(part), "");
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

// A ring bent round most of a circle needs many parts: at most 64 are made (the count did not
// take the halves still waiting into account, and 66 came out).
TEST(FanDiagonals, NoMoreThanSixtyFourParts)
{
  for (const double sweep : { 6.0, 6.2 })
  {
    const std::vector<std::vector<Point2>> parts = FansByDiagonals(Arc(99.9, 100.0, sweep, 1000));
    EXPECT_LE(parts.size(), 64u) << "sweep " << sweep;
    EXPECT_GT(parts.size(), 16u) << "sweep " << sweep;
  }
}

// The areal average's pieces in lon/lat (a box over Colorado's latitudes and three gauges, whose
// tiles are long strips; a box by the North Pole): every piece a fan, and, measured
// geodesically, a tile's pieces add up to its clipped area (the parts of a split piece had summed
// to 1.2e-7 off it).
TEST(FanDiagonals, PiecesOfTheArealAverageAreFansThatAddUpToTheirTiles)
{
  struct Case
  {
    std::vector<Point2> Box, Gauges;
  };
  const std::vector<Case> cases{
    { { { -109, 37 }, { -102, 37 }, { -102, 41 }, { -109, 41 } },
      { { -103.728, 41.099 }, { -103.342, 40.670 }, { -105.5, 38 } } },
    { { { -40, 85 }, { 40, 85 }, { 40, 89.5 }, { -40, 89.5 } },
      { { 0, 89.9 }, { 20, 87 }, { -20, 87 }, { 0, 86 } } },
  };
  for (const Case& c : cases)
  {
    for (const AreaMethod method : { AreaMethod::EqualAreaPlane, AreaMethod::GeodesicPolygon })
    {
      SCOPED_TRACE(std::to_string(c.Box[0].y) + " N, method " + std::to_string(int(method)));
      ArealAverageSettings settings;
      settings.Areas = method;
      ThiessenArealAverage average(c.Gauges, { 0, 4 }, c.Box, settings);
      const ArealStep step = average.Step(std::vector<double>(c.Gauges.size(), 1.0));
      const ClippedTilesLonLat tiles = average.CurrentClippedTiles();
      for (std::size_t k = 0; k < tiles.Gauges.size(); ++k)
      {
        double sum = 0.0;
        for (std::size_t r = tiles.TilePieceOffsets[k]; r < tiles.TilePieceOffsets[k + 1]; ++r)
        {
          const std::vector<Point2> piece = RingOf(tiles.Pieces, r);
          EXPECT_TRUE(IsFan(piece)) << "tile " << k << " piece " << r;
          sum += tiles.PieceAreasM2[r];
        }
        const auto at = std::find(step.Gauges.begin(), step.Gauges.end(), tiles.Gauges[k]);
        ASSERT_NE(at, step.Gauges.end());
        const double area = step.AreasM2[static_cast<std::size_t>(at - step.Gauges.begin())];
        EXPECT_NEAR(sum, area, 1e-12 * area) << "tile " << k;
      }
    }
  }
}
