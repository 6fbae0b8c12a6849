// Shared borders (core/shared_borders.h): display pieces of a tessellation's tiles clipped by a
// catchment with holes meet vertex for vertex once shared, and their edges, cut into steps and
// carried through a curving map (as the inverse projection carries them to lon/lat), still meet
// exactly; without sharing they leave T-junctions that the map moves off the neighbour's chords.

#include "clip.h"
#include "dirichlet_tessellation.h"
#include "display_pieces.h"
#include "shared_borders.h"
#include "tiles.h"
#include "window.h"

#include "test_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

using namespace tessera;
using tessera_test::MakeCatchment;
using tessera_test::Rectangle;

namespace
{

// The number of (vertex, edge) pairs of different pieces where the vertex lies within `near` of
// the edge's line, between its ends and farther than `same` from both: T-junctions.
int CountTJunctions(const ClippedRings& pieces, double near, double same)
{
  const std::vector<Point2>& v = pieces.Vertices;
  const std::vector<std::size_t>& at = pieces.RingOffsets;
  int found = 0;
  for (std::size_t q = 0; q + 1 < at.size(); ++q)
  {
    Point2 low{ HUGE_VAL, HUGE_VAL }, high{ -HUGE_VAL, -HUGE_VAL };
    for (std::size_t k = at[q]; k < at[q + 1]; ++k)
    {
      low = { std::min(low.x, v[k].x), std::min(low.y, v[k].y) };
      high = { std::max(high.x, v[k].x), std::max(high.y, v[k].y) };
    }
    for (std::size_t i = 0; i < v.size(); ++i)
    {
      const Point2& p = v[i];
      if ((i >= at[q] && i < at[q + 1]) || p.x < low.x - near || p.x > high.x + near ||
        p.y < low.y - near || p.y > high.y + near)
      {
        continue;
      }
      for (std::size_t k = at[q]; k < at[q + 1]; ++k)
      {
        const Point2& a = v[k];
        const Point2& b = v[k + 1 < at[q + 1] ? k + 1 : at[q]];
        const double length = std::hypot(b.x - a.x, b.y - a.y);
        const double along = ((p.x - a.x) * (b.x - a.x) + (p.y - a.y) * (b.y - a.y)) / length;
        const double off =
          std::fabs((p.x - a.x) * (b.y - a.y) - (p.y - a.y) * (b.x - a.x)) / length;
        found += off <= near && along > same && along < length - same;
      }
    }
  }
  return found;
}

// The number of pairs of vertices of different pieces that are distinct but within `near` of each
// other: copies of one point that would stay apart once mapped.
int CountNearCopies(const ClippedRings& pieces, double near)
{
  std::vector<std::size_t> ringOf(pieces.Vertices.size());
  for (std::size_t r = 0; r + 1 < pieces.RingOffsets.size(); ++r)
  {
    std::fill(
      ringOf.begin() + pieces.RingOffsets[r], ringOf.begin() + pieces.RingOffsets[r + 1], r);
  }
  int found = 0;
  for (std::size_t i = 0; i < pieces.Vertices.size(); ++i)
  {
    for (std::size_t j = i + 1; j < pieces.Vertices.size(); ++j)
    {
      const Point2& a = pieces.Vertices[i];
      const Point2& b = pieces.Vertices[j];
      found += ringOf[i] != ringOf[j] && !(a == b) && std::fabs(a.x - b.x) <= near &&
        std::fabs(a.y - b.y) <= near;
    }
  }
  return found;
}

// The pieces of all tiles of random points in the unit square clipped by a catchment with a bay
// and holes (every tile over a hole or the bay's end is cut vertically into several pieces).
ClippedRings PiecesOfAllTiles(std::mt19937& random, int pointCount)
{
  // (small holes and a narrow bay: tiles hold them whole, and are cut on either side of them)
  const Catchment comb = MakeCatchment({ { { 0, 0 },
                                           { 1, 0 },
                                           { 1, 1 },
                                           { 0.72, 1 },
                                           { 0.72, 0.4 },
                                           { 0.7, 0.4 },
                                           { 0.7, 1 },
                                           { 0, 1 } },
    Rectangle(0.2, 0.2, 0.23, 0.22),
    Rectangle(0.4, 0.6, 0.42, 0.63),
    Rectangle(0.5, 0.3, 0.51, 0.32),
    Rectangle(0.85, 0.7, 0.87, 0.71),
    Rectangle(0.3, 0.8, 0.32, 0.81) });
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<Point2> points(static_cast<std::size_t>(pointCount));
  for (Point2& p : points)
  {
    p = { u(random), u(random) };
  }
  const TileSet tiles =
    ComputeTiles(DirichletTessellation(Window::Rectangle(-0.01, 1.01, -0.02, 1.03), points));
  ClippedRings all;
  for (std::size_t t = 0; t + 1 < tiles.Offsets.size(); ++t)
  {
    const std::vector<Point2> tile(
      tiles.Vertices.begin() + tiles.Offsets[t], tiles.Vertices.begin() + tiles.Offsets[t + 1]);
    const ClippedRings pieces = DisplayPieces(comb.Clip(tile).Rings);
    all.Vertices.insert(all.Vertices.end(), pieces.Vertices.begin(), pieces.Vertices.end());
    for (std::size_t r = 1; r < pieces.RingOffsets.size(); ++r)
    {
      all.RingOffsets.push_back(
        all.RingOffsets.back() + pieces.RingOffsets[r] - pieces.RingOffsets[r - 1]);
    }
  }
  return all;
}

// Each ring cut into steps (DensifyRingSymmetrically), then bent by a smooth map that turns
// straight lines into curves bulging by about 1e-4 over a step of 0.02.
ClippedRings DensifiedAndBent(const ClippedRings& rings)
{
  ClippedRings out;
  std::vector<Point2> dense;
  for (std::size_t r = 0; r + 1 < rings.RingOffsets.size(); ++r)
  {
    const std::size_t begin = rings.RingOffsets[r];
    DensifyRingSymmetrically(&rings.Vertices[begin], rings.RingOffsets[r + 1] - begin, 0.02, dense);
    for (const Point2& p : dense)
    {
      out.Vertices.push_back({ p.x + 0.5 * p.y * p.y, p.y + 0.5 * p.x * p.x });
    }
    out.RingOffsets.push_back(out.Vertices.size());
  }
  return out;
}

double Area(const ClippedRings& rings)
{
  double twice = 0.0;
  for (std::size_t r = 0; r + 1 < rings.RingOffsets.size(); ++r)
  {
    for (std::size_t k = rings.RingOffsets[r]; k < rings.RingOffsets[r + 1]; ++k)
    {
      const Point2& a = rings.Vertices[k];
      const Point2& b =
        rings.Vertices[k + 1 < rings.RingOffsets[r + 1] ? k + 1 : rings.RingOffsets[r]];
      twice += a.x * b.y - b.x * a.y;
    }
  }
  return twice / 2.0;
}

} // namespace

TEST(SharedBorders, PiecesMeetVertexForVertexOnceShared)
{
  std::mt19937 random(5);
  int junctionsBefore = 0, nearCopiesBefore = 0, bentJunctionsBefore = 0;
  for (int trial = 0; trial < 6; ++trial)
  {
    SCOPED_TRACE("trial " + std::to_string(trial));
    const ClippedRings pieces = PiecesOfAllTiles(random, 40 + 60 * trial);
    const ClippedRings shared = ShareBorderVertices(pieces);
    // The same pieces, in the same order, each with the vertices of its neighbours added: in the
    // plane, nothing moves (the same area to rounding).
    ASSERT_EQ(shared.RingOffsets.size(), pieces.RingOffsets.size());
    EXPECT_GE(shared.Vertices.size(), pieces.Vertices.size());
    EXPECT_NEAR(Area(shared), Area(pieces), 1e-14);
    junctionsBefore += CountTJunctions(pieces, 1e-12, 1e-12);
    EXPECT_EQ(CountTJunctions(shared, 1e-12, 1e-12), 0);
    EXPECT_EQ(CountNearCopies(shared, 1e-13), 0);
    nearCopiesBefore += CountNearCopies(pieces, 1e-13);
    // Bent, the shared pieces still meet vertex for vertex, where the unshared ones' T-junctions
    // lie off their neighbours' chords by up to some 1e-5.
    EXPECT_EQ(CountTJunctions(DensifiedAndBent(shared), 1e-6, 1e-12), 0);
    bentJunctionsBefore += CountTJunctions(DensifiedAndBent(pieces), 1e-6, 1e-12);
  }
  EXPECT_GT(bentJunctionsBefore, 0); // (those of the cuts round the hole, off by some 1e-5: 34)
  EXPECT_GT(junctionsBefore, 20);    // (the vertical cuts of tiles over the hole and the bay)
  EXPECT_GT(nearCopiesBefore, 20);   // (cut points and crossings both pieces computed: 296)
}

TEST(SharedBorders, EdgesAreCutAtTheSamePointsEitherWay)
{
  const std::vector<Point2> ring{ { 0.1, 0.3 }, { 7.3, 1.9 }, { 2.2, 5.7 } };
  const std::vector<Point2> reversed{ ring[2], ring[1], ring[0] };
  std::vector<Point2> forward, backward;
  DensifyRingSymmetrically(ring.data(), ring.size(), 0.37, forward);
  DensifyRingSymmetrically(reversed.data(), reversed.size(), 0.37, backward);
  ASSERT_EQ(forward.size(), backward.size());
  // The same points to the bit (backward runs the ring the other way).
  const auto byCoordinates = [](const Point2& a, const Point2& b)
  { return a.x != b.x ? a.x < b.x : a.y < b.y; };
  std::sort(forward.begin(), forward.end(), byCoordinates);
  std::sort(backward.begin(), backward.end(), byCoordinates);
  for (std::size_t k = 0; k < forward.size(); ++k)
  {
    EXPECT_EQ(backward[k].x, forward[k].x) << k;
    EXPECT_EQ(backward[k].y, forward[k].y) << k;
  }
  DensifyRingSymmetrically(ring.data(), ring.size(), 0.37, forward);
  // No step longer than 0.37, and every point on its edge.
  for (std::size_t k = 0; k < forward.size(); ++k)
  {
    const Point2& a = forward[k];
    const Point2& b = forward[(k + 1) % forward.size()];
    EXPECT_LE(std::hypot(b.x - a.x, b.y - a.y), 0.37 * (1 + 1e-12)) << k;
  }
}

// Two pieces' own copies of a corner an ulp or two apart are made one point, the smaller (each
// piece computed its own: in lon/lat they stayed apart, and a GIS's union kept zero-width slivers
// there); two vertices of one piece that close are left apart (made one they would fold it).
TEST(SharedBorders, CopiesOfACornerUlpsApartAreMadeOne)
{
  const double up = std::nextafter(1.0, 2.0), up2 = std::nextafter(up, 2.0);
  ClippedRings two;
  two.Vertices = {
    { 0, 0 }, { 1, 0 }, { 1, 1 }, { 0, 1 }, { up, 0 }, { 2, 0 }, { 2, 1 }, { up2, 1 }
  };
  two.RingOffsets = { 0, 4, 8 };
  EXPECT_EQ(CountNearCopies(two, 1e-12), 2);
  const ClippedRings shared = ShareBorderVertices(two);
  ASSERT_EQ(shared.RingOffsets, two.RingOffsets);
  EXPECT_EQ(CountNearCopies(shared, 1e-12), 0);
  EXPECT_EQ(shared.Vertices[4].x, 1.0);
  EXPECT_EQ(shared.Vertices[7].x, 1.0);
  EXPECT_EQ(shared.Vertices[1].x, 1.0);
  // One piece with two vertices an ulp apart beside another piece's copy: all left as they are.
  ClippedRings folded;
  folded.Vertices = {
    { 0, 0 }, { 1, 0 }, { up, 0.5 }, { 1, 1 }, { 0, 1 }, { up2, 0.5 }, { 2, 0 }, { 2, 1 }
  };
  folded.Vertices[2] = { 1, 0.5 };
  folded.Vertices.insert(folded.Vertices.begin() + 3, Point2{ up, 0.5 });
  folded.RingOffsets = { 0, 6, 9 };
  const ClippedRings kept = ShareBorderVertices(folded);
  EXPECT_EQ(kept.Vertices[2].x, 1.0);
  EXPECT_EQ(kept.Vertices[3].x, up);
  EXPECT_EQ(kept.Vertices[6].x, up2);
  // A sliver's apex 10 ulps above its base, a neighbour's copy of it 20 ulps below: moved there,
  // the apex would turn the other way and fold the sliver flat. Left as it is.
  const double ulp = std::nextafter(0.5, 1.0) - 0.5;
  ClippedRings sliver;
  sliver.Vertices = { { 0, 0 },
    { 1, 0 },
    { 0.5, 10 * ulp },
    { std::nextafter(0.5, 0.0), -20 * ulp },
    { 0.3, -1 },
    { 0.7, -1 } };
  sliver.RingOffsets = { 0, 3, 6 };
  const ClippedRings unfolded = ShareBorderVertices(sliver);
  const Point2 apex = sliver.Vertices[2];
  EXPECT_TRUE(std::find(unfolded.Vertices.begin(),
                unfolded.Vertices.begin() + unfolded.RingOffsets[1],
                apex) != unfolded.Vertices.begin() + unfolded.RingOffsets[1]);
  EXPECT_GT(Area(unfolded), Area(sliver) - 1e-9);
  // Five copies each 50 ulps from the next (a chain within the tolerance link by link, 200 ulps
  // end to end): none moved.
  ClippedRings chain;
  for (int k = 0; k < 5; ++k)
  {
    const double x = 0.5 + 50 * k * ulp;
    chain.Vertices.insert(
      chain.Vertices.end(), { { x, 0.5 }, { x + 3, 0.5 + k + 1 }, { x - 3, 0.5 + k + 1 } });
    chain.RingOffsets.push_back(chain.Vertices.size());
  }
  const ClippedRings unchained = ShareBorderVertices(chain);
  for (int k = 0; k < 5; ++k)
  {
    EXPECT_EQ(unchained.Vertices[unchained.RingOffsets[k]].x, 0.5 + 50 * k * ulp) << k;
  }
}

TEST(SharedBorders, NothingToShare)
{
  ClippedRings none;
  EXPECT_TRUE(ShareBorderVertices(none).Vertices.empty());
  ClippedRings one;
  one.Vertices = Rectangle(0, 0, 1, 1);
  one.RingOffsets.push_back(4);
  const ClippedRings same = ShareBorderVertices(one);
  EXPECT_EQ(same.Vertices.size(), 4U);
  // Two squares side by side, the right one's left side cut at y = 0.5: the left one takes it.
  ClippedRings two = one;
  for (const Point2& p : std::vector<Point2>{ { 1, 0 }, { 2, 0 }, { 2, 1 }, { 1, 1 }, { 1, 0.5 } })
  {
    two.Vertices.push_back(p);
  }
  two.RingOffsets.push_back(two.Vertices.size());
  const ClippedRings shared = ShareBorderVertices(two);
  ASSERT_EQ(shared.RingOffsets[1], 5U);
  EXPECT_EQ(shared.Vertices[2].x, 1.0);
  EXPECT_EQ(shared.Vertices[2].y, 0.5);
  // The same at any scale (1e308 overflowed the grid's box and crashed; beyond 1e154 nothing was
  // shared), and unshared, unchanged, with a coordinate that is not finite.
  for (const double scale : { 1e-300, 1e-150, 1e150, 1e300, 0x1p1020 })
  {
    ClippedRings scaled = two;
    for (Point2& p : scaled.Vertices)
    {
      p = { p.x * scale, p.y * scale };
    }
    const ClippedRings sharedScaled = ShareBorderVertices(scaled);
    ASSERT_EQ(sharedScaled.Vertices.size(), shared.Vertices.size()) << scale;
    EXPECT_EQ(sharedScaled.Vertices[2].y, 0.5 * scale) << scale;
  }
  for (const double bad : { HUGE_VAL, -HUGE_VAL, std::nan("") })
  {
    ClippedRings withBad = two;
    withBad.Vertices[6].x = bad;
    EXPECT_EQ(ShareBorderVertices(withBad).Vertices.size(), two.Vertices.size()) << bad;
  }
}

// A vertex of one piece on a steep edge of another near 0, where the grid's cells are as wide as
// coordinates near 1 (10^4 vertices over [-1, 1]^2): the grid once widened an edge by its own
// tolerance, some 1e-30 here, less than the rounding of its cells' sides (some 1e-16, and on a
// slope of 10^6 that much in x is 1e-10 in y), and did not list the edge in the vertex's cell, so
// that the T-junction stayed. Widened by the largest tolerance of the scaled coordinates, it is
// found: the vertex is inserted into the edge.
TEST(SharedBorders, AVertexOnASteepEdgeNearZeroAmongFarVerticesIsShared)
{
  ClippedRings pieces;
  const auto add = [&pieces](std::initializer_list<Point2> ring)
  {
    pieces.Vertices.insert(pieces.Vertices.end(), ring);
    pieces.RingOffsets.push_back(pieces.Vertices.size());
  };
  const double crossing = -1e-17; // where the edge meets y = 0
  const Point2 low{ crossing - 1e-10, -1e-4 }, high{ crossing + 1e-10, 1e-4 };
  add({ low, { 1e-3, -1e-4 }, { 1e-3, 1e-4 }, high }); // A: right of the edge high -> low
  const double x = -3e-17;
  const Point2 on{ x, low.y + (x - low.x) / (high.x - low.x) * (high.y - low.y) };
  add({ low, on, high, { -1e-3, 0.0 } }); // B: left of it, with a vertex on it
  std::mt19937_64 random(7);
  std::uniform_real_distribution<double> unit(-0.99, 0.99);
  add({ { -1, -1 }, { -0.999, -1 }, { -1, -0.999 } });
  add({ { 1, 1 }, { 0.999, 1 }, { 1, 0.999 } });
  while (pieces.Vertices.size() < 10000)
  {
    const double px = unit(random), py = unit(random);
    if (std::fabs(px) >= 0.05 || std::fabs(py) >= 0.05)
    {
      add({ { px, py }, { px + 1e-3, py }, { px, py + 1e-3 } });
    }
  }
  const ClippedRings shared = ShareBorderVertices(pieces);
  ASSERT_EQ(shared.Vertices.size(), pieces.Vertices.size() + 1);
  // A's ring: low, its two right corners, high, then the vertex inserted between high and low.
  ASSERT_EQ(shared.RingOffsets[1], 5u);
  EXPECT_EQ(shared.Vertices[4].x, on.x);
  EXPECT_EQ(shared.Vertices[4].y, on.y);
}
