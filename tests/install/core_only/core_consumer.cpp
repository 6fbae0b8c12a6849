// The core alone: four points in the unit square, whose tiles must be its quarters (Failed,
// require.h). Prints "ok" when every requirement held.
#include "../require.h"

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
  if (!(tiles.Areas.size() == 4))
  {
    return Failed("%zu tiles, not four", tiles.Areas.size());
  }
  for (const double area : tiles.Areas)
  {
    if (!(std::abs(area - 0.25) <= 1e-15))
    {
      return Failed("a tile's area is %.17g, not a quarter", area);
    }
  }
  std::printf("ok\n");
  return 0;
}
