// OutlinesOfPieces: a clipped tile's display pieces joined back into polygons with holes. Checked
// against the clip itself: the outline's signed area is the clipped area, every ring is simple,
// and point by point the polygons hold exactly the tile's part of the catchment; no edge of the
// outline is a cut between pieces.

#include "areal_average.h"
#include "clip.h"
#include "display_pieces.h"
#include "meridian_cut.h"
#include "piece_outlines.h"
#include "polygon_area.h"
#include "shared_borders.h"

#include "test_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
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

/// Polygons of outlines that hold p: inside the outer ring and in none of its holes.
int PolygonsHolding(const RegionOutlines& outlines, const Point2& p)
{
  int holding = 0;
  for (std::size_t k = 0; k + 1 < outlines.PolygonOffsets.size(); ++k)
  {
    const std::size_t outer = outlines.PolygonOffsets[k];
    bool inside = InRing(outlines.Rings, outer, p);
    for (std::size_t h = outer + 1; inside && h < outlines.PolygonOffsets[k + 1]; ++h)
    {
      inside = !InRing(outlines.Rings, h, p);
    }
    holding += inside;
  }
  return holding;
}

double RingArea(const ClippedRings& rings, std::size_t r)
{
  return CompensatedPolygonArea(
    &rings.Vertices[rings.RingOffsets[r]], rings.RingOffsets[r + 1] - rings.RingOffsets[r]);
}

/// The signed area of outlines' rings, each checked to be simple (where names a failure).
double SimpleRingsArea(const RegionOutlines& outlines, const std::string& where)
{
  double area = 0.0;
  for (std::size_t r = 0; r + 1 < outlines.Rings.RingOffsets.size(); ++r)
  {
    const std::vector<Point2> ring = RingOf(outlines.Rings, r);
    EXPECT_EQ(tessera_test::RingDefect(ring), "") << where << "ring " << r;
    area += RingArea(outlines.Rings, r);
  }
  return area;
}

/// The tile's part of the catchment as pieces, their borders made alike (as the areal average
/// does before it joins them), and their outline. Checks that each ring is simple, each polygon's
/// first ring anticlockwise and the others clockwise, the signed areas sum to the clip's, no edge
/// is walked both ways (a cut left in), and each sample point of a grid over the tile's box lies
/// in one polygon when it is in one piece, in none otherwise. Returns the outline.
RegionOutlines ExpectOutlineOfTheRegion(const Catchment& catchment, const std::vector<Point2>& tile)
{
  const ClippedTile clipped = catchment.Clip(tile);
  const ClippedRings pieces = ShareBorderVertices(DisplayPieces(clipped.Rings));
  const RegionOutlines outlines = OutlinesOfPieces(pieces, 0, pieces.RingOffsets.size() - 1);
  const ClippedRings& rings = outlines.Rings;
  EXPECT_EQ(outlines.PolygonOffsets.back(), rings.RingOffsets.size() - 1);
  double total = 0.0;
  std::vector<std::pair<Point2, Point2>> edges;
  for (std::size_t k = 0; k + 1 < outlines.PolygonOffsets.size(); ++k)
  {
    for (std::size_t r = outlines.PolygonOffsets[k]; r < outlines.PolygonOffsets[k + 1]; ++r)
    {
      const std::vector<Point2> ring = RingOf(rings, r);
      EXPECT_EQ(tessera_test::RingDefect(ring), "") << "ring " << r << " is not simple";
      const double area = RingArea(rings, r);
      if (r == outlines.PolygonOffsets[k])
      {
        EXPECT_GT(area, 0.0) << "outer ring " << r;
      }
      else
      {
        EXPECT_LT(area, 0.0) << "hole " << r;
      }
      total += area;
      for (std::size_t v = 0; v < ring.size(); ++v)
      {
        edges.emplace_back(ring[v], ring[(v + 1) % ring.size()]);
      }
    }
  }
  EXPECT_NEAR(total, clipped.Area, 1e-12 * std::max(1.0, clipped.Area));
  for (const auto& [a, b] : edges)
  {
    EXPECT_EQ(
      std::count_if(
        edges.begin(), edges.end(), [&](const auto& e) { return e.first == b && e.second == a; }),
      0)
      << "edge (" << a.x << ", " << a.y << ") - (" << b.x << ", " << b.y << ") walked both ways";
  }
  for (const Point2& p : SampleGrid(BoundsOf(tile.data(), tile.size()), 50))
  {
    EXPECT_EQ(PolygonsHolding(outlines, p), RingsHolding(pieces, p))
      << "at (" << p.x << ", " << p.y << ")";
  }
  return outlines;
}

std::size_t PolygonCount(const RegionOutlines& outlines)
{
  return outlines.PolygonOffsets.size() - 1;
}

std::size_t RingCount(const RegionOutlines& outlines)
{
  return outlines.Rings.RingOffsets.size() - 1;
}

} // namespace

TEST(PieceOutlines, ATileRoundALakeIsOnePolygonWithAHole)
{
  const Catchment lake = MakeCatchment({ Rectangle(0, 0, 10, 10), Rectangle(4, 4, 6, 6) });
  const RegionOutlines outlines = ExpectOutlineOfTheRegion(lake, Rectangle(1, 1, 9, 9));
  ASSERT_EQ(PolygonCount(outlines), 1U); // (from three pieces)
  ASSERT_EQ(RingCount(outlines), 2U);
  EXPECT_EQ(RingArea(outlines.Rings, 0), 64.0);
  EXPECT_EQ(RingArea(outlines.Rings, 1), -4.0);
}

TEST(PieceOutlines, LobesOfABayAreTwoPolygons)
{
  const Catchment bay = MakeCatchment(
    { { { 0, 0 }, { 10, 0 }, { 10, 10 }, { 6, 10 }, { 6, 3 }, { 4, 3 }, { 4, 10 }, { 0, 10 } } });
  EXPECT_EQ(PolygonCount(ExpectOutlineOfTheRegion(bay, Rectangle(2, 5, 8, 12))), 2U);
  // a U, two pieces joined again into one polygon without a hole
  const RegionOutlines u = ExpectOutlineOfTheRegion(bay, Rectangle(2, 1, 8, 12));
  EXPECT_EQ(PolygonCount(u), 1U);
  EXPECT_EQ(RingCount(u), 1U);
}

TEST(PieceOutlines, AnIslandInALakeIsAPolygonOfItsOwn)
{
  const Catchment lake = MakeCatchment(
    { Rectangle(0, 0, 10, 10), Rectangle(3, 3, 7, 7), Rectangle(4.5, 4.5, 5.5, 5.5) });
  const RegionOutlines outlines = ExpectOutlineOfTheRegion(lake, Rectangle(1, 1, 9, 9));
  ASSERT_EQ(PolygonCount(outlines), 2U);
  EXPECT_EQ(RingCount(outlines), 3U);
  // polygons in the order of their lowest vertices: the tile's part round the lake, then the island
  EXPECT_EQ(outlines.PolygonOffsets[1], 2U);
  EXPECT_EQ(RingArea(outlines.Rings, 2), 1.0);
}

// Rings that touch at a point come out as separate simple rings: a hole touching the outline
// (which the chaining's turn first joins to it) and two lobes meeting at a corner.
TEST(PieceOutlines, RingsTouchingAtAPointAreSeparateRings)
{
  const Catchment touching = MakeCatchment(
    { Rectangle(0, 0, 10, 10), { { 5, 0 }, { 7, 3 }, { 3, 3 } } }); // a hole from the bottom edge
  const RegionOutlines hole = ExpectOutlineOfTheRegion(touching, Rectangle(-1, -1, 11, 11));
  ASSERT_EQ(PolygonCount(hole), 1U);
  ASSERT_EQ(RingCount(hole), 2U);
  EXPECT_EQ(RingArea(hole.Rings, 1), -6.0);

  ClippedRings bowTie;
  for (const auto& square : { Rectangle(0, 0, 1, 1), Rectangle(1, 1, 2, 2) })
  {
    bowTie.Vertices.insert(bowTie.Vertices.end(), square.begin(), square.end());
    bowTie.RingOffsets.push_back(bowTie.Vertices.size());
  }
  const RegionOutlines lobes = OutlinesOfPieces(bowTie, 0, 2);
  ASSERT_EQ(PolygonCount(lobes), 2U);
  EXPECT_EQ(RingArea(lobes.Rings, 0), 1.0);
  EXPECT_EQ(RingArea(lobes.Rings, 1), 1.0);
}

// A window with a slanted slit some 60 ulps wide: the display pieces either side of it overlap by
// a sliver, and once their borders were made alike the outline had a bow tie of no area, listed
// as an outer ring, beside the tile's part. Every ring is simple, and the bow tie is gone.
TEST(PieceOutlines, ASlitSomeUlpsWideLeavesNoBowTie)
{
  for (const double width : { 6e-14, 8e-14, 1e-13 })
  {
    SCOPED_TRACE("width " + std::to_string(width));
    const Catchment slit = MakeCatchment({ { { 0, 0 },
      { 10, 0 },
      { 10, 10 },
      { 6 + width, 10 },
      { 5 + width, 2 },
      { 5, 2 },
      { 6, 10 },
      { 0, 10 } } });
    const ClippedTile clipped = slit.Clip(Rectangle(-1, -1, 11, 11));
    const ClippedRings pieces = ShareBorderVertices(DisplayPieces(clipped.Rings));
    const RegionOutlines outlines = OutlinesOfPieces(pieces, 0, pieces.RingOffsets.size() - 1);
    const double area = SimpleRingsArea(outlines, "");
    EXPECT_NEAR(area, clipped.Area, 1e-11);
  }
}

// Pieces given by the caller: a range of rings only, repeated vertices passed over, and a
// T-junction (a vertex on a neighbour's edge that the neighbour lacks) leaving both edges.
TEST(PieceOutlines, TakesARangeOfRings)
{
  ClippedRings pieces;
  for (const auto& square : { Rectangle(5, 5, 6, 6), Rectangle(0, 0, 1, 1), Rectangle(1, 0, 2, 1) })
  {
    pieces.Vertices.insert(pieces.Vertices.end(), square.begin(), square.end());
    pieces.RingOffsets.push_back(pieces.Vertices.size());
  }
  pieces.Vertices.insert(pieces.Vertices.begin() + 5, pieces.Vertices[4]); // a repeated vertex
  for (std::size_t r = 2; r < pieces.RingOffsets.size(); ++r)
  {
    ++pieces.RingOffsets[r];
  }
  const RegionOutlines joined = OutlinesOfPieces(pieces, 1, 3);
  ASSERT_EQ(PolygonCount(joined), 1U);
  EXPECT_EQ(RingArea(joined.Rings, 0), 2.0);
  EXPECT_EQ(joined.Rings.Vertices.size(), 6U); // (the shared side's ends stay vertices)
  EXPECT_EQ(PolygonCount(OutlinesOfPieces(pieces, 0, 0)), 0U);
}

// Random convex tiles over a comb with bays, two holes and an island in one of them, and over a
// wavy shore: the polygons hold exactly the pieces' points, their areas sum to the clip's, and no
// cut between pieces is left in.
TEST(PieceOutlines, RandomTilesOverHolesBaysAndAWavyShore)
{
  const Catchment comb = Comb();
  std::vector<Point2> shore{ { 20, -5 } };
  for (int k = 400; k >= 0; --k)
  {
    const double x = 20.0 * k / 400;
    shore.push_back({ x, 5 + 0.3 * std::sin(30 * 2 * M_PI * x / 10) });
  }
  shore.push_back({ 0, -5 });
  const Catchment wavy = MakeCatchment({ shore });
  std::mt19937 random(11);
  std::uniform_real_distribution<double> where(-2.0, 22.0), size(0.5, 9.0);
  std::size_t joined = 0;
  for (int t = 0; t < 120; ++t)
  {
    const Point2 centre{ where(random), where(random) / 2.0 };
    const std::vector<Point2> tile = RandomInscribedTile(random, centre, size(random));
    if (CompensatedPolygonArea(tile.data(), tile.size()) < 1e-3)
    {
      continue;
    }
    SCOPED_TRACE("tile " + std::to_string(t));
    for (const Catchment* catchment : { &comb, &wavy })
    {
      const ClippedRings pieces = DisplayPieces(catchment->Clip(tile).Rings);
      const RegionOutlines outlines = ExpectOutlineOfTheRegion(*catchment, tile);
      joined += PolygonCount(outlines) < pieces.RingOffsets.size() - 1;
    }
  }
  EXPECT_GT(joined, 40U); // (tiles whose pieces were joined)
}

// Outlines of the areal average's tiles in lon/lat (tiles round a lake, across a bay with an
// island-hole, on lattices and at random): every ring is simple, outer rings anticlockwise and
// holes clockwise, a tile's outline holds its pieces' area, and across all tiles every outline
// edge is either walked the other way by a neighbour's outline (a shared border, vertex for
// vertex) or lies on the catchment's boundary: their union is the catchment, as a GIS's dissolve
// would find.
TEST(PieceOutlines, OutlinesOfLonLatTilesShareTheirBordersAndFillTheCatchment)
{
  std::mt19937 random(5);
  std::uniform_real_distribution<double> where(-0.2, 1.2);
  int withHoles = 0, joined = 0;
  for (int trial = 0; trial < 12; ++trial)
  {
    SCOPED_TRACE("trial " + std::to_string(trial));
    const tessera_test::Rings catchment = tessera_test::LakeOrBay(trial % 2 == 0);
    const std::vector<std::size_t>& offsets = catchment.Offsets;
    const std::vector<Point2>& ring = catchment.Vertices;
    std::vector<Point2> gauges;
    const double step = trial < 4 ? 0.25 : 0.0; // lattices, then random gauges
    for (int k = 0; step > 0.0 ? k < 36 : k < 3 + 2 * trial; ++k)
    {
      gauges.push_back(step > 0.0
          ? Point2{ (trial % 2 ? 0.05 : 0.0) + step * (k % 6) - 0.1, step * (k / 6) - 0.1 }
          : Point2{ where(random), where(random) });
    }
    ThiessenArealAverage average(gauges, offsets, ring);
    average.Step(std::vector<double>(gauges.size(), 1.0));
    const ClippedTilesLonLat tiles = average.CurrentClippedTiles(5000.0);
    const RegionOutlines& outlines = tiles.Outlines;
    ASSERT_EQ(tiles.TileOutlineOffsets.size(), tiles.Gauges.size() + 1);
    std::vector<std::pair<std::size_t, std::pair<Point2, Point2>>> edges; // (tile, edge)
    for (std::size_t k = 0; k < tiles.Gauges.size(); ++k)
    {
      double pieceArea = 0.0, outlineArea = 0.0;
      for (std::size_t r = tiles.TilePieceOffsets[k]; r < tiles.TilePieceOffsets[k + 1]; ++r)
      {
        pieceArea += RingArea(tiles.Pieces, r);
      }
      const std::size_t firstRing = outlines.PolygonOffsets[tiles.TileOutlineOffsets[k]];
      const std::size_t endRing = outlines.PolygonOffsets[tiles.TileOutlineOffsets[k + 1]];
      for (std::size_t p = tiles.TileOutlineOffsets[k]; p < tiles.TileOutlineOffsets[k + 1]; ++p)
      {
        withHoles += outlines.PolygonOffsets[p + 1] - outlines.PolygonOffsets[p] > 1;
        EXPECT_GT(RingArea(outlines.Rings, outlines.PolygonOffsets[p]), 0.0) << "tile " << k;
      }
      for (std::size_t r = firstRing; r < endRing; ++r)
      {
        const std::vector<Point2> one = RingOf(outlines.Rings, r);
        EXPECT_EQ(tessera_test::RingDefect(one), "") << "tile " << k << " ring " << r;
        outlineArea += RingArea(outlines.Rings, r);
        for (std::size_t v = 0; v < one.size(); ++v)
        {
          edges.push_back({ k, { one[v], one[(v + 1) % one.size()] } });
        }
      }
      EXPECT_NEAR(outlineArea, pieceArea, 1e-13) << "tile " << k;
      joined += endRing - firstRing < tiles.TilePieceOffsets[k + 1] - tiles.TilePieceOffsets[k];
    }
    // An edge that no other tile's outline walks the other way (within 1e-9 degrees: a border's
    // vertices are one point in the plane only to rounding, shared_borders.h) lies on the
    // catchment's boundary, to the sagitta of a step (the tiles' edges are straight in the plane,
    // the catchment's in lon/lat); and no tile's outline walks an edge both ways (a cut between
    // its pieces left in).
    const auto near = [](const Point2& p, const Point2& q)
    { return std::abs(p.x - q.x) <= 1e-9 && std::abs(p.y - q.y) <= 1e-9; };
    for (std::size_t e = 0; e < edges.size(); ++e)
    {
      const auto& [a, b] = edges[e].second;
      bool shared = false;
      for (std::size_t f = 0; f < edges.size(); ++f)
      {
        if (near(edges[f].second.first, b) && near(edges[f].second.second, a))
        {
          EXPECT_NE(edges[f].first, edges[e].first)
            << "tile " << edges[e].first << " walks its edge (" << a.x << ", " << a.y << ") - ("
            << b.x << ", " << b.y << ") both ways";
          shared = true;
        }
      }
      if (shared)
      {
        continue;
      }
      const Point2 mid{ 0.5 * (a.x + b.x), 0.5 * (a.y + b.y) };
      double nearest = 1e300;
      for (std::size_t r = 0; r < 2; ++r)
      {
        for (std::size_t v = offsets[r]; v < offsets[r + 1]; ++v)
        {
          const Point2& p = ring[v];
          const Point2& q = ring[v + 1 < offsets[r + 1] ? v + 1 : offsets[r]];
          const double dx = q.x - p.x, dy = q.y - p.y;
          const double t =
            std::clamp(((mid.x - p.x) * dx + (mid.y - p.y) * dy) / (dx * dx + dy * dy), 0.0, 1.0);
          nearest = std::min(nearest, std::hypot(mid.x - p.x - t * dx, mid.y - p.y - t * dy));
        }
      }
      EXPECT_LT(nearest, 1e-4) << "an edge of tile " << edges[e].first
                               << " that no neighbour shares, inside the catchment at (" << mid.x
                               << ", " << mid.y << ")";
    }
  }
  EXPECT_GT(withHoles, 2);
  EXPECT_GT(joined, 10);
}

// Two pieces sharing a slanted edge, cut at a vertical line: the edge's crossing point is the
// same from either piece, so the parts on each side join into one polygon each, and nothing of
// the pieces' area is lost or gained.
TEST(PieceOutlines, PiecesCutAtAMeridianJoinOnEachSide)
{
  ClippedRings pieces;
  const std::vector<std::vector<Point2>> quads{ { { 0, 0 }, { 1, 0 }, { 1, 1.3 }, { 0, 1 } },
    { { 0, 1 }, { 1, 1.3 }, { 1, 2 }, { 0, 2 } } };
  for (const auto& quad : quads)
  {
    pieces.Vertices.insert(pieces.Vertices.end(), quad.begin(), quad.end());
    pieces.RingOffsets.push_back(pieces.Vertices.size());
  }
  const std::array<ClippedRings, 2> sides = CutAtMeridian(pieces, 0, 2, 0.3);
  RegionOutlines outlines;
  for (const ClippedRings& side : sides)
  {
    ASSERT_EQ(side.RingOffsets.size(), 3U); // a part of each piece
    AppendOutlines(OutlinesOfPieces(side, 0, 2), outlines);
  }
  ASSERT_EQ(PolygonCount(outlines), 2U);
  ASSERT_EQ(RingCount(outlines), 2U);
  EXPECT_NEAR(RingArea(outlines.Rings, 0), 0.6, 1e-15); // west: 0.3 wide, 2 high
  EXPECT_NEAR(RingArea(outlines.Rings, 1), 1.4, 1e-15);
  EXPECT_EQ(outlines.Rings.Vertices.size(), 12U); // (each side: its shared edge gone, 6 vertices)
  for (std::size_t r = 0; r < 2; ++r)
  {
    const Box2 box = BoundsOf(&outlines.Rings.Vertices[outlines.Rings.RingOffsets[r]],
      outlines.Rings.RingOffsets[r + 1] - outlines.Rings.RingOffsets[r]);
    EXPECT_TRUE(box.XMax <= 0.3 || box.XMin >= 0.3) << "polygon " << r << " spans the line";
  }
  // A piece that only touches the line keeps one part.
  const std::array<ClippedRings, 2> touching = CutAtMeridian(pieces, 0, 1, 1.0);
  EXPECT_EQ(touching[0].RingOffsets.size(), 2U);
  EXPECT_EQ(touching[1].RingOffsets.size(), 1U);
}

// Pieces with a vertex or an edge on the line, or crossing it four times: each side's outline is
// simple rings (Sutherland-Hodgman's spikes and bridges along the line cancel once the edges
// along it are cut at the side's points there), holding the side's part of the pieces' area.
TEST(PieceOutlines, PiecesTouchingOrRecrossingTheMeridianGiveSimpleRings)
{
  const std::vector<std::pair<std::vector<Point2>, double>> cases{
    // an L with its inner edge on the line: a spike along it on the west side
    { { { 0, 0 }, { 2, 0 }, { 2, 3 }, { 1, 3 }, { 1, 1 }, { 0, 1 } }, 1.0 },
    // a U open to the east, across the line four times: two arms joined by bridges on the east
    { { { -2, 0 }, { 2, 0 }, { 2, 1 }, { -1, 1 }, { -1, 2 }, { 2, 2 }, { 2, 3 }, { -2, 3 } }, 0.0 },
    // a notch whose tip is on the line: two lobes that touch there on the east
    { { { -1, -1 }, { 1, -1 }, { 1, -0.5 }, { 0, 0 }, { 1, 0.5 }, { 1, 1 }, { -1, 1 } }, 0.0 },
  };
  const std::vector<std::vector<double>> sideAreas{ { 1.0, 3.0 }, { 5.0, 4.0 }, { 2.0, 1.5 } };
  const std::vector<std::vector<std::size_t>> sideRings{ { 1, 1 }, { 1, 2 }, { 1, 2 } };
  for (std::size_t c = 0; c < cases.size(); ++c)
  {
    SCOPED_TRACE("case " + std::to_string(c));
    ClippedRings piece;
    piece.Vertices = cases[c].first;
    piece.RingOffsets.push_back(piece.Vertices.size());
    const std::array<ClippedRings, 2> sides = CutAtMeridian(piece, 0, 1, cases[c].second);
    for (std::size_t s = 0; s < 2; ++s)
    {
      const RegionOutlines outlines =
        OutlinesOfPieces(sides[s], 0, sides[s].RingOffsets.size() - 1);
      ASSERT_EQ(RingCount(outlines), sideRings[c][s]) << "side " << s;
      const double area = SimpleRingsArea(outlines, "side " + std::to_string(s) + " ");
      EXPECT_EQ(area, sideAreas[c][s]) << "side " << s;
    }
  }
}

// Longitudes within 1e-10 degrees of 180 + 360 k snap onto it, on either side and at any turn;
// 0, and a vertex 1e-9 away, stay; a ring whose every vertex is that near keeps its own (snapped,
// it would have no area).
TEST(PieceOutlines, SnapToMeridianMovesOnlyVerticesBesideIt)
{
  std::vector<Point2> ring{ { 179.99999999999997, -16.0 },
    { 180.00000000005, -16.5 },
    { -180.00000000000003, -17.0 },
    { 540.0 - 5e-11, -17.2 },
    { 180.0 - 1e-9, -17.5 },
    { 0.0, -18.0 },
    { 179.0, -18.0 } };
  SnapToMeridian(ring);
  const std::vector<double> expected{ 180.0, 180.0, -180.0, 540.0, 180.0 - 1e-9, 0.0, 179.0 };
  for (std::size_t k = 0; k < ring.size(); ++k)
  {
    EXPECT_EQ(ring[k].x, expected[k]) << "vertex " << k;
  }
  std::vector<Point2> thin{ { 180.0, 0.0 }, { 180.0 + 5e-11, 0.5 }, { 179.99999999999997, 1.0 } };
  const std::vector<Point2> before = thin;
  SnapToMeridian(thin);
  EXPECT_TRUE(thin == before);
}

// Tiles of an island across the 180th meridian (longitudes written 179.5 to 180.5, and as
// -180.5 to -179.5): every polygon of the outlines lies on one side of the meridian, and a tile's
// polygons hold its pieces' area.
TEST(PieceOutlines, TilesAcrossTheAntimeridianAreCutThere)
{
  // (then a coast with a notch from the east whose tip lies on the meridian, and gauges mirrored
  // across it, whose common border lies on it to rounding: parts that touch the line or run
  // along it. The mirrored gauges' border came back from the plane at 180 and an ulp below, and
  // the eastern tile was cut into its part and a sliver beyond the line; snapped to the meridian,
  // each tile is one polygon on its side)
  const std::vector<std::pair<std::vector<Point2>, std::vector<Point2>>> cases{
    { { { 179.5, -17 }, { 180.5, -17 }, { 180.5, -16 }, { 179.5, -16 } },
      { { 179.6, -16.2 },
        { 179.7, -16.8 },
        { 180.1, -16.7 },
        { 180.4, -16.4 },
        { 179.98, -16.5 } } },
    { { { 179.5, -17 },
        { 180.5, -17 },
        { 180.5, -16.8 },
        { 180.0, -16.5 },
        { 180.5, -16.2 },
        { 180.5, -16 },
        { 179.5, -16 } },
      { { 179.7, -16.5 }, { 180.3, -16.9 }, { 180.3, -16.1 } } },
    { { { 179.5, -17 }, { 180.5, -17 }, { 180.5, -16 }, { 179.5, -16 } },
      { { 179.1, -16.77 }, { -179.1, -16.77 } } },
  };
  for (std::size_t c = 0; c < 2 * cases.size(); ++c)
  {
    const double shift = c < cases.size() ? 0.0 : -360.0;
    SCOPED_TRACE("case " + std::to_string(c % cases.size()) + ", shift " + std::to_string(shift));
    std::vector<Point2> island = cases[c % cases.size()].first;
    std::vector<Point2> gauges = cases[c % cases.size()].second;
    for (std::vector<Point2>* points : { &island, &gauges })
    {
      for (Point2& p : *points)
      {
        p.x += p.x > 0.0 ? shift : 0.0; // (written west of -180 where they were east of 180)
      }
    }
    ThiessenArealAverage average(gauges, { 0, island.size() }, island);
    average.Step(std::vector<double>(gauges.size(), 1.0));
    const ClippedTilesLonLat tiles = average.CurrentClippedTiles();
    constexpr std::size_t MirroredGauges = 2; // (the case whose border lies on the meridian)
    const bool mirrored = c % cases.size() == MirroredGauges;
    int across = 0;
    for (std::size_t k = 0; k < tiles.Gauges.size(); ++k)
    {
      if (mirrored)
      {
        EXPECT_EQ(tiles.TileOutlineOffsets[k + 1] - tiles.TileOutlineOffsets[k], 1u)
          << "tile " << k;
      }
      double pieceArea = 0.0, outlineArea = 0.0;
      for (std::size_t r = tiles.TilePieceOffsets[k]; r < tiles.TilePieceOffsets[k + 1]; ++r)
      {
        pieceArea += RingArea(tiles.Pieces, r);
      }
      // (the pieces' longitudes run on across the meridian, from either side: 180 or -180)
      const std::size_t begin = tiles.Pieces.RingOffsets[tiles.TilePieceOffsets[k]];
      const Box2 tileBox = BoundsOf(&tiles.Pieces.Vertices[begin],
        tiles.Pieces.RingOffsets[tiles.TilePieceOffsets[k + 1]] - begin);
      const double meridian = tileBox.XMax > 0.0 ? 180.0 : -180.0;
      bool west = false, east = false;
      for (std::size_t p = tiles.TileOutlineOffsets[k]; p < tiles.TileOutlineOffsets[k + 1]; ++p)
      {
        for (std::size_t r = tiles.Outlines.PolygonOffsets[p];
             r < tiles.Outlines.PolygonOffsets[p + 1];
             ++r)
        {
          const std::size_t begin = tiles.Outlines.Rings.RingOffsets[r];
          const Box2 box = BoundsOf(
            &tiles.Outlines.Rings.Vertices[begin], tiles.Outlines.Rings.RingOffsets[r + 1] - begin);
          EXPECT_TRUE(box.XMax <= meridian || box.XMin >= meridian)
            << "tile " << k << " ring " << r << " spans " << box.XMin << " .. " << box.XMax;
          const std::vector<Point2> ring(&tiles.Outlines.Rings.Vertices[begin],
            &tiles.Outlines.Rings.Vertices[0] + tiles.Outlines.Rings.RingOffsets[r + 1]);
          EXPECT_EQ(tessera_test::RingDefect(ring), "") << "tile " << k << " ring " << r;
          west = west || box.XMax <= meridian;
          east = east || box.XMin >= meridian;
          outlineArea += RingArea(tiles.Outlines.Rings, r);
        }
      }
      EXPECT_NEAR(outlineArea, pieceArea, 1e-12 * pieceArea) << "tile " << k;
      across += west && east;
    }
    EXPECT_EQ(across >= 1, !mirrored) << across << " tile(s) on both sides";
  }
}
