// The core alone: four points in the unit square, whose tiles are its quarters. Prints "ok" and
// returns 0, or names what failed and returns 1.
#include "dirichlet_tessellation.h"
#include "tiles.h"
#include "window.h"

#include <cmath>
#include <cstdio>
#include <vector>

int main()
{
  const std::vector<tessera::Point2> points{
    { 0.25, 0.25 }, { 0.75, 0.25 }, { 0.25, 0.75 }, { 0.75, 0.75 }
  };
  const tessera::DirichletTessellation tessellation(
    tessera::Window::Rectangle(0.0, 1.0, 0.0, 1.0), points);
  const tessera::TileSet tiles = tessera::ComputeTiles(tessellation);
  for (const double area : tiles.Areas)
  {
    if (std::abs(area - 0.25) > 1e-15)
    {
      std::printf("a tile's area is %.17g, not a quarter\n", area);
      return 1;
    }
  }
  std::printf(tiles.Areas.size() == 4 ? "ok\n" : "not four tiles\n");
  return tiles.Areas.size() == 4 ? 0 : 1;
}
