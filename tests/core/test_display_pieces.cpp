// DisplayPieces: the region of a clipped tile as simple anticlockwise pieces. Checked against the
// clip's own area and, point by point, against the catchment's and the tile's membership.

#include "areal_average.h"
#include "clip.h"
#include "dirichlet_tessellation.h"
#include "display_pieces.h"
#include "errors.h"
#include "polygon_area.h"
#include "predicates.h"
#include "tiles.h"
#include "window.h"

#include "test_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>
#include <string>
#include <vector>

using namespace tessera;
using tessera_test::Comb;
using tessera_test::InRing;
using tessera_test::MakeCatchment;
using tessera_test::RandomInscribedTile;
using tessera_test::Rectangle;
using tessera_test::RingOf;
using tessera_test::RingsHolding;
using tessera_test::SampleGrid;

namespace
{

/// A square (0, 0) - (10, 10) with a bay from the top down to y = 3 between x = 4 and 6.
Catchment Bay()
{
  return MakeCatchment(
    { { { 0, 0 }, { 10, 0 }, { 10, 10 }, { 6, 10 }, { 6, 3 }, { 4, 3 }, { 4, 10 }, { 0, 10 } } });
}

/// Each piece is a simple ring (where names it in a failure) with a positive area; returns the
/// sum of their areas.
double ExpectSimplePieces(const ClippedRings& pieces, const std::string& where)
{
  double total = 0.0;
  for (std::size_t r = 0; r + 1 < pieces.RingOffsets.size(); ++r)
  {
    const std::vector<Point2> ring = RingOf(pieces, r);
    EXPECT_EQ(tessera_test::RingDefect(ring), "") << where << "piece " << r << " is not simple";
    const double area = CompensatedPolygonArea(ring.data(), ring.size());
    EXPECT_GT(area, 0.0) << where << "piece " << r;
    total += area;
  }
  return total;
}

/// Each piece is a fan about its first vertex, as VTK draws and measures a polygon: every triangle
/// of that vertex and an edge not at it turns anticlockwise or is flat (exactly), so the
/// triangles' unsigned areas add up to the piece's.
void ExpectFansAboutTheFirstVertex(const ClippedRings& pieces, const std::string& where)
{
  for (std::size_t r = 0; r + 1 < pieces.RingOffsets.size(); ++r)
  {
    const Point2* ring = &pieces.Vertices[pieces.RingOffsets[r]];
    const std::size_t n = pieces.RingOffsets[r + 1] - pieces.RingOffsets[r];
    for (std::size_t k = 1; k + 1 < n; ++k)
    {
      EXPECT_GE(orient2d(ring[0], ring[k], ring[k + 1]), 0)
        << where << "piece " << r << " is no fan about its first vertex at edge " << k;
    }
  }
}

bool InConvexTile(const std::vector<Point2>& tile, const Point2& p)
{
  for (std::size_t i = 0; i < tile.size(); ++i)
  {
    const Point2& a = tile[i];
    const Point2& b = tile[(i + 1) % tile.size()];
    if ((b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x) <= 0.0)
    {
      return false;
    }
  }
  return true;
}

/// Every piece is a simple anticlockwise ring, a fan about its first vertex; their areas sum to
/// the clip's; each sample point of
/// a grid over the tile's box lies in exactly one piece when it is in tile & catchment, in none
/// otherwise. Returns the number of pieces.
std::size_t ExpectPiecesOfTheRegion(const Catchment& catchment, const std::vector<Point2>& tile)
{
  const ClippedTile clipped = catchment.Clip(tile);
  const ClippedRings pieces = DisplayPieces(clipped.Rings);
  const double total = ExpectSimplePieces(pieces, "");
  ExpectFansAboutTheFirstVertex(pieces, "");
  EXPECT_NEAR(total, clipped.Area, 1e-12 * std::max(1.0, clipped.Area));
  for (const Point2& p : SampleGrid(BoundsOf(tile.data(), tile.size()), 60))
  {
    const int expected = InConvexTile(tile, p) && catchment.Contains(p);
    EXPECT_EQ(RingsHolding(pieces, p), expected) << "at (" << p.x << ", " << p.y << ")";
  }
  return pieces.RingOffsets.size() - 1;
}

} // namespace

TEST(DisplayPieces, AHoleInTheTileIsLeftOut)
{
  const Catchment lake = MakeCatchment({ Rectangle(0, 0, 10, 10), Rectangle(4, 4, 6, 6) });
  // Split by the hole into a U (left, below, right) and the part above it, and the U, a fan about
  // no vertex, into two Ls, each a fan about its inner corner.
  EXPECT_EQ(ExpectPiecesOfTheRegion(lake, Rectangle(1, 1, 9, 9)), 3U);
  // A hole with many vertices still gives few pieces: a 64-gon lake.
  std::vector<Point2> round;
  for (int k = 0; k < 64; ++k)
  {
    round.push_back({ 5 + 1.5 * std::cos(k * M_PI / 32), 5 + 1.5 * std::sin(k * M_PI / 32) });
  }
  EXPECT_LE(ExpectPiecesOfTheRegion(
              MakeCatchment({ Rectangle(0, 0, 10, 10), round }), Rectangle(1, 1, 9, 9)),
    4U);
}

// Many lakes over one x range (a column of them, the case that made a quadratic match of pieces
// and a sort of every slab cost seconds): each lake still splits the tile once, into lakes + 1
// x-monotone pieces, and the two beside the column, whose sides are the lakes' ragged ends, are
// cut into fans: fewer than lakes / 2 more pieces. They cover the region exactly (checked on the
// sample grid), whatever the lakes' order.
TEST(DisplayPieces, AColumnOfLakesGivesOnePieceMoreThanLakes)
{
  std::mt19937_64 random(4);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const int lakes = 120;
  std::vector<std::vector<Point2>> rings{ Rectangle(0, 0, 10, 40) };
  for (int j = 0; j < lakes; ++j)
  {
    const double x = 3.0 + u(random), y = (j + 0.25) * 40.0 / lakes;
    rings.push_back(Rectangle(x, y, x + 3.0 + u(random), y + 0.5 * 40.0 / lakes));
  }
  std::shuffle(rings.begin() + 1, rings.end(), random);
  const std::size_t pieces = ExpectPiecesOfTheRegion(MakeCatchment(rings), Rectangle(1, -1, 9, 41));
  EXPECT_GE(pieces, std::size_t(lakes + 1));
  EXPECT_LT(pieces, std::size_t(lakes + 1 + lakes / 2));
}

TEST(DisplayPieces, LobesOfABayAreSeparatePieces)
{
  // A tile across the bay meets both shores.
  const Catchment bay = Bay();
  EXPECT_EQ(ExpectPiecesOfTheRegion(bay, Rectangle(2, 5, 8, 12)), 2U);
  EXPECT_EQ(ExpectPiecesOfTheRegion(bay, Rectangle(2, 1, 8, 12)), 2U); // a U: two Ls
}

TEST(DisplayPieces, AnXMonotoneFanIsOnePiece)
{
  const Catchment bay = Bay();
  // convex; an L beside the bay, given from its inner corner (6, 3), about which it is a fan
  for (const auto& tile : { Rectangle(1, 1, 3, 3), Rectangle(5, 1, 7, 5) })
  {
    const ClippedTile clipped = bay.Clip(tile);
    const ClippedRings pieces = DisplayPieces(clipped.Rings);
    ASSERT_EQ(pieces.RingOffsets.size(), 2U);
    EXPECT_NEAR(
      CompensatedPolygonArea(pieces.Vertices.data(), pieces.Vertices.size()), clipped.Area, 1e-12);
    ExpectFansAboutTheFirstVertex(pieces, "");
  }
  const ClippedRings l = DisplayPieces(bay.Clip(Rectangle(5, 1, 7, 5)).Rings);
  EXPECT_EQ(l.Vertices[0].x, 6.0);
  EXPECT_EQ(l.Vertices[0].y, 3.0);
}

// Tiles under a wavy shore (a catchment whose top is a sine of 400 vertices, 30 waves) are fans
// about no vertex: they are cut, and each part is a fan; the parts are fewer than the waves over
// the tiles, and cover the region exactly.
TEST(DisplayPieces, TilesUnderAWavyShoreAreCutIntoFans)
{
  std::vector<Point2> shore{ { 10, -5 } };
  for (int k = 400; k >= 0; --k)
  {
    const double x = 10.0 * k / 400;
    shore.push_back({ x, 5 + 0.3 * std::sin(30 * 2 * M_PI * x / 10) });
  }
  shore.push_back({ 0, -5 });
  const Catchment wavy = MakeCatchment({ shore });
  std::mt19937 random(12);
  std::uniform_real_distribution<double> where(0.0, 10.0), size(0.2, 4.0);
  std::size_t pieces = 0;
  double waves = 0.0; // the waves over the tiles' widths, and two more a tile (ends)
  for (int t = 0; t < 60; ++t)
  {
    SCOPED_TRACE("tile " + std::to_string(t));
    const std::vector<Point2> tile =
      RandomInscribedTile(random, { where(random), 4.0 + where(random) / 5 }, size(random));
    const Box2 box = BoundsOf(tile.data(), tile.size());
    waves += 3.0 * (box.XMax - box.XMin) + 2.0;
    pieces += ExpectPiecesOfTheRegion(wavy, tile);
  }
  EXPECT_GT(pieces, 120U); // (tiles were cut: 60 before)
  EXPECT_LT(static_cast<double>(pieces), waves);
}

TEST(DisplayPieces, RandomTilesOverHolesAndBays)
{
  // A comb (bays from the top) with two holes and an island in one of them; random convex tiles
  // of random sizes anywhere over it.
  const Catchment comb = Comb();
  std::mt19937 random(7);
  std::uniform_real_distribution<double> where(-2.0, 22.0), size(0.5, 9.0);
  for (int t = 0; t < 150; ++t)
  {
    const Point2 centre{ where(random), where(random) / 2.0 };
    const std::vector<Point2> tile = RandomInscribedTile(random, centre, size(random));
    if (CompensatedPolygonArea(tile.data(), tile.size()) < 1e-3)
    {
      continue;
    }
    SCOPED_TRACE("tile " + std::to_string(t));
    ExpectPiecesOfTheRegion(comb, tile);
  }
}

// Tessellation tiles (random points in the unit square) over a star-shaped catchment and over a
// square with a star-shaped hole: every tile's pieces are simple and their areas add up to its
// clipped area to 1e-12 of it (or of a hundredth of the tile, for slivers, whose clipped area is
// a sum of signed rings that cancel). Tiles have steep edges, and Sutherland-Hodgman runs along
// them to a tile corner and back from a crossing that lies on the edge only to rounding. Where a
// piece's corner took the edge's height interpolated at the crossing's x instead of the
// crossing's own (6.7e-14 off at a slope of 3700; where the corners of a side met, or where a
// piece went on into the next slab), the piece came out up to 3.4e-16 too large or small, 2e-12 of
// the tile's clipped area: 10 tiles of the 100 trials.
TEST(DisplayPieces, PiecesOfTessellatedTilesAddUpToTheClippedArea)
{
  std::mt19937 random(3);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const auto star = [&](Point2 centre, int count, double rMin, double rMax)
  {
    std::vector<Point2> ring;
    for (int k = 0; k < count; ++k)
    {
      const double angle = 2.0 * M_PI * (k + 0.1 + 0.8 * u(random)) / count;
      const double radius = rMin + (rMax - rMin) * u(random);
      ring.push_back({ centre.x + radius * std::cos(angle), centre.y + radius * std::sin(angle) });
    }
    return ring;
  };
  int tilesChecked = 0;
  for (int trial = 0; trial < 100; ++trial)
  {
    const Catchment catchment = trial % 2 == 0
      ? MakeCatchment({ star({ 0.5, 0.5 }, 23, 0.12, 0.45) })
      : MakeCatchment({ Rectangle(0.05, 0.05, 0.95, 0.95), star({ 0.52, 0.47 }, 17, 0.1, 0.3) });
    std::vector<Point2> points(static_cast<std::size_t>(100 + 50 * trial));
    for (Point2& p : points)
    {
      p = { u(random), u(random) };
    }
    const DirichletTessellation tessellation(Window::Rectangle(-0.01, 1.01, -0.02, 1.03), points);
    const TileSet tiles = ComputeTiles(tessellation);
    for (std::size_t t = 0; t + 1 < tiles.Offsets.size(); ++t)
    {
      const std::vector<Point2> tile(
        tiles.Vertices.begin() + tiles.Offsets[t], tiles.Vertices.begin() + tiles.Offsets[t + 1]);
      const ClippedTile clipped = catchment.Clip(tile);
      const ClippedRings pieces = DisplayPieces(clipped.Rings);
      const double total = ExpectSimplePieces(
        pieces, "trial " + std::to_string(trial) + " tile " + std::to_string(t) + ": ");
      ExpectFansAboutTheFirstVertex(
        pieces, "trial " + std::to_string(trial) + " tile " + std::to_string(t) + ": ");
      EXPECT_NEAR(total, clipped.Area, 1e-12 * std::max(clipped.Area, 1e-2 * tiles.Areas[t]))
        << "trial " << trial << " tile " << t;
      tilesChecked += clipped.Area > 0.0 && clipped.Area < tiles.Areas[t];
    }
  }
  EXPECT_GT(tilesChecked, 1000); // tiles that the catchment cuts
}

TEST(DisplayPieces, PiecesOfTessellatedTilesAreSimpleInLonLat)
{
  // Tiles as the areal average derives them (rounded vertices; on a lattice, edges through
  // catchment vertices, nearly vertical edges and rings running along the tiles' edges), around a
  // lake and across a bay with an island-hole: every piece that output 0 would show is a simple
  // ring in lon/lat, most are fans about their first vertex, and the pieces' areas add up to the
  // catchment's.
  std::mt19937 random(11);
  std::uniform_real_distribution<double> where(-0.2, 1.2);
  int fans = 0, pieces = 0;   // pieces in lon/lat that are fans about their first vertex
  std::size_t shownTiles = 0; // tiles with a part of the catchment
  for (int trial = 0; trial < 32; ++trial)
  {
    const tessera_test::Rings catchment = tessera_test::LakeOrBay(trial % 2 == 0);
    const std::vector<std::size_t>& offsets = catchment.Offsets;
    const std::vector<Point2>& ring = catchment.Vertices;
    std::vector<Point2> gauges;
    if (trial < 16) // lattices of 4 spacings and 2 offsets
    {
      const double step = std::vector<double>{ 0.1, 0.125, 0.2, 0.25 }[(trial / 2) % 4];
      const double offset = trial < 8 ? 0.0 : 0.05;
      for (int i = 0; offset + i * step < 1.2; ++i)
      {
        for (int j = 0; offset + j * step < 1.2; ++j)
        {
          gauges.push_back({ offset + i * step, offset + j * step });
        }
      }
    }
    else
    {
      for (int k = 0; k < 3 + trial; ++k)
      {
        gauges.push_back({ where(random), where(random) });
      }
    }
    ThiessenArealAverage average(gauges, offsets, ring);
    average.Step(std::vector<double>(gauges.size(), 1.0));
    const ClippedTilesLonLat tiles = average.CurrentClippedTiles();
    ExpectSimplePieces(tiles.Pieces, "trial " + std::to_string(trial) + ": ");
    for (std::size_t r = 0; r + 1 < tiles.Pieces.RingOffsets.size(); ++r)
    {
      const Point2* ring = &tiles.Pieces.Vertices[tiles.Pieces.RingOffsets[r]];
      const std::size_t n = tiles.Pieces.RingOffsets[r + 1] - tiles.Pieces.RingOffsets[r];
      bool fan = true;
      for (std::size_t k = 1; k + 1 < n; ++k)
      {
        fan = fan && orient2d(ring[0], ring[k], ring[k + 1]) >= 0;
      }
      fans += fan;
      pieces += 1;
    }
    ASSERT_EQ(tiles.PieceAreasM2.size() + 1, tiles.Pieces.RingOffsets.size()) << "trial " << trial;
    for (std::size_t k = 0; k < tiles.Gauges.size(); ++k)
    {
      EXPECT_LT(tiles.TilePieceOffsets[k], tiles.TilePieceOffsets[k + 1])
        << "trial " << trial << ": the tile of gauge " << tiles.Gauges[k] << " has no piece";
    }
    shownTiles += tiles.Gauges.size();
    const double total = std::accumulate(tiles.PieceAreasM2.begin(), tiles.PieceAreasM2.end(), 0.0);
    EXPECT_NEAR(total, average.CatchmentAreaM2(), 1e-9 * average.CatchmentAreaM2())
      << "trial " << trial;
  }
  // Made fans in the plane, bent in lon/lat, and started again at a vertex that sees them whole
  // where one does (1455 of 1543; 355 before they were started again), the others split along
  // diagonals into fans (fan_diagonals.h): all of them.
  EXPECT_EQ(fans, pieces);
  EXPECT_GE(std::size_t(pieces), shownTiles); // (a piece or more per tile)
  EXPECT_GT(shownTiles, 0u);
}

// Rings that touch at points (a hole touching the outer boundary and another hole, an island
// touching its hole; a checkerboard of squares meeting at corners) or share stretches (adjacent
// rectangles, a lake on their outline): the pieces of random tiles are simple, and where the
// region is pinched at a contact they do not run through it.
TEST(DisplayPieces, RingsTouchingOrSharingBoundaryGiveSimplePieces)
{
  const Catchment touching = MakeCatchment({ Rectangle(0, 0, 10, 10),
    { { 0, 5 }, { 3, 2 }, { 6, 5 }, { 3, 8 } },
    { { 6, 5 }, { 8, 3 }, { 9, 5 }, { 8, 7 } },
    { { 3, 2 }, { 4, 4.5 }, { 3, 6 }, { 2, 4.5 } } });
  const Catchment checkerboard = MakeCatchment({ Rectangle(0, 0, 5, 5),
    Rectangle(5, 5, 10, 10),
    Rectangle(0, 10, 5, 15),
    Rectangle(10, 0, 15, 5) });
  const Catchment adjacent = MakeCatchment({ Rectangle(0, 0, 5, 10),
    Rectangle(5, 0, 10, 4),
    Rectangle(5, 4, 10, 10),
    { { 7, 10 }, { 6, 8 }, { 9, 8 }, { 8, 10 } } });
  // A tile centred on a contact has its pieces on either side of it.
  EXPECT_EQ(ExpectPiecesOfTheRegion(checkerboard, Rectangle(4, 4, 6, 6)), 2u);
  std::mt19937 random(8);
  std::uniform_real_distribution<double> where(-1.0, 11.0), size(0.3, 6.0);
  for (int t = 0; t < 300; ++t)
  {
    const Point2 centre{ where(random), where(random) };
    const std::vector<Point2> tile = RandomInscribedTile(random, centre, size(random));
    if (CompensatedPolygonArea(tile.data(), tile.size()) < 1e-3)
    {
      continue;
    }
    SCOPED_TRACE("tile " + std::to_string(t));
    ExpectPiecesOfTheRegion(t % 3 == 0 ? touching : t % 3 == 1 ? checkerboard : adjacent, tile);
  }
}

// A ring started where it is no fan is rotated to a vertex about which it is one (an L from an
// outer corner to its inner corner, the one vertex that sees it whole, or to the outer corner
// opposite); a U, which no vertex sees whole, is left as it is, and said.
TEST(DisplayPieces, StartAtFanApexRotatesToAVertexThatSeesTheWholeRing)
{
  std::vector<Point2> l{ { 0, 2 }, { 0, 0 }, { 2, 0 }, { 2, 1 }, { 1, 1 }, { 1, 2 } };
  const std::vector<Point2> given = l;
  ASSERT_TRUE(StartAtFanApex(l));
  ClippedRings one;
  one.Vertices = l;
  one.RingOffsets = { 0, l.size() };
  ExpectFansAboutTheFirstVertex(one, "the L: ");
  EXPECT_TRUE(std::is_permutation(l.begin(),
    l.end(),
    given.begin(),
    [](const Point2& a, const Point2& b) { return a.x == b.x && a.y == b.y; }));
  std::vector<Point2> u{
    { 0, 0 }, { 3, 0 }, { 3, 2 }, { 2, 2 }, { 2, 1 }, { 1, 1 }, { 1, 2 }, { 0, 2 }
  };
  const std::vector<Point2> before = u;
  EXPECT_FALSE(StartAtFanApex(u));
  EXPECT_TRUE(std::equal(u.begin(),
    u.end(),
    before.begin(),
    [](const Point2& a, const Point2& b) { return a.x == b.x && a.y == b.y; }));
}
