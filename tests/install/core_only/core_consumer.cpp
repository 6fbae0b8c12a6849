// The core alone, as a GoogleTest of a user's own: four points in the unit square, whose tiles
// must be its quarters.
#include "dirichlet_tessellation.h"
#include "tiles.h"
#include "window.h"

#include <gtest/gtest.h>

#include <vector>

TEST(InstalledCore, FourPointsInTheUnitSquareGetItsQuarters)
{
  const std::vector<tessera::Point2> points{
    { 0.25, 0.25 }, { 0.75, 0.25 }, { 0.25, 0.75 }, { 0.75, 0.75 }
  };
  const tessera::DirichletTessellation tessellation(
    tessera::Window::Rectangle(0.0, 1.0, 0.0, 1.0), points);
  const tessera::TileSet tiles = tessera::ComputeTiles(tessellation);
  ASSERT_EQ(tiles.Areas.size(), 4u);
  for (const double area : tiles.Areas)
  {
    EXPECT_NEAR(area, 0.25, 1e-15);
  }
}
