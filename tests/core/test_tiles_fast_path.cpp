// TessellationDual's shortcuts against the general path, bit for bit: Tiles() builds the polygon
// of a point whose ring has only distinct, real faces with centres inside the window straight
// from the face centres (no ClipEdge / AssemblePolygon), Contiguities() keeps such edges without
// clipping, ComputeDelaunayFaces writes the triangles in parallel chunks, and large inputs are
// split over threads. The references are RingTileEdges + AssemblePolygon for every point (no
// shortcut), ComputeTilesOf (the local derivation, with its own face labelling), a ring walk with
// ClipEdge for every edge, and TessellationDual::Faces.

#include "dirichlet_tessellation.h"
#include "tile_edges.h"
#include "tiles.h"

#include "test_support.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <random>
#include <string>
#include <vector>

using namespace tessera;
using tessera_test::Hexagon;
using tessera_test::UniformPoints;

namespace
{

template<class T>
bool SameBits(const std::vector<T>& a, const std::vector<T>& b)
{
  return a.size() == b.size() &&
    (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0);
}

// Kind-0 contiguities by the general rule: every ring edge to a larger id between two distinct
// faces, clipped to the window.
tessera_test::PairKinds ClippedContiguities(const DirichletTessellation& t,
  const TessellationDual& dual)
{
  tessera_test::PairKinds pairs;
  const auto& org = t.Origin();
  const auto& twin = t.Twin();
  std::vector<char> seen(t.PointCount(), 0);
  tiles_detail::TileEdge edge;
  for (std::int32_t start = 0; start < std::int32_t(org.size()); ++start)
  {
    const std::int32_t v = org[start];
    if (v < 0 || seen[v])
    {
      continue;
    }
    seen[v] = 1;
    std::int32_t e = start;
    do
    {
      const std::int32_t j = org[DirichletTessellation::Next(e)];
      const std::int32_t left = dual.Label(e / 3);
      const std::int32_t right = dual.Label(twin[e] / 3);
      if (j > v && left != right &&
        tiles_detail::ClipEdge(t, v, j, dual.View(right), dual.View(left), edge))
      {
        pairs[{ v, j }] = 0;
      }
      e = t.RingNext(e);
    } while (e != start);
  }
  return pairs;
}

// The tiles of the given points by the general rule alone: every ring edge clipped
// (RingTileEdges), the polygon assembled with the window's corners (AssemblePolygon).
TileSet GeneralPathTiles(const DirichletTessellation& t,
  const TessellationDual& dual,
  const std::vector<std::int32_t>& ids)
{
  std::vector<std::int32_t> leaving(t.PointCount(), -1);
  const auto& org = t.Origin();
  for (std::int32_t e = 0; e < std::int32_t(org.size()); ++e)
  {
    if (org[e] >= 0 && leaving[org[e]] < 0)
    {
      leaving[org[e]] = e;
    }
  }
  TileSet tiles;
  tiles.Offsets.push_back(0);
  std::vector<std::int32_t> ring;
  std::vector<tiles_detail::TileEdge> edges;
  std::vector<Point2> polygon;
  for (const std::int32_t v : ids)
  {
    tiles_detail::CollectRing(t, leaving[v], ring);
    tiles_detail::RingTileEdges(t, dual, v, ring, edges);
    const std::int32_t sides = tiles_detail::AssemblePolygon(t, edges, polygon);
    tiles_detail::AppendTile(tiles, v, polygon, sides);
  }
  return tiles;
}

void ExpectSameTiles(const TileSet& tiles, const TileSet& general)
{
  EXPECT_EQ(tiles.PointIds, general.PointIds);
  EXPECT_EQ(tiles.Offsets, general.Offsets);
  EXPECT_TRUE(SameBits(tiles.Vertices, general.Vertices));
  EXPECT_TRUE(SameBits(tiles.Areas, general.Areas));
  EXPECT_EQ(tiles.NeighborCounts, general.NeighborCounts);
}

void ExpectSameAsGeneralPath(const DirichletTessellation& t, const std::string& name)
{
  SCOPED_TRACE(name);
  const TessellationDual dual(t);
  const TileSet tiles = dual.Tiles();
  ExpectSameTiles(tiles, ComputeTilesOf(t, tiles.PointIds));
  if (t.IsTwoDimensional()) // collinear points have no rings to walk
  {
    ExpectSameTiles(tiles, GeneralPathTiles(t, dual, tiles.PointIds));
  }
  EXPECT_EQ(tiles.PointIds.size(), t.AcceptedCount());

  const ContiguityGraph graph = dual.Contiguities();
  tessera_test::PairKinds kind0;
  for (const auto& [pair, kind] : tessera_test::GraphPairs(graph))
  {
    if (kind == 0)
    {
      kind0[pair] = kind;
    }
  }
  if (t.IsTwoDimensional()) // collinear points have no rings to walk
  {
    EXPECT_EQ(kind0, ClippedContiguities(t, dual));
  }
  // Grouped by i in the tiles' order, ascending j within a group.
  std::vector<std::int32_t> rank(t.PointCount(), -1);
  for (std::size_t k = 0; k < tiles.PointIds.size(); ++k)
  {
    rank[tiles.PointIds[k]] = std::int32_t(k);
  }
  for (std::size_t k = 1; k < graph.Kinds.size(); ++k)
  {
    const std::int32_t i0 = graph.Pairs[2 * k - 2], j0 = graph.Pairs[2 * k - 1];
    const std::int32_t i1 = graph.Pairs[2 * k], j1 = graph.Pairs[2 * k + 1];
    ASSERT_TRUE(rank[i0] < rank[i1] || (i0 == i1 && j0 < j1)) << "pair " << k;
  }

  for (const bool split : { false, true })
  {
    const DelaunayFaces fast = ComputeDelaunayFaces(t, split);
    const DelaunayFaces reference = dual.Faces(split);
    EXPECT_EQ(fast.Offsets, reference.Offsets);
    EXPECT_EQ(fast.PointIds, reference.PointIds);
  }
}

std::vector<Point2> Lattice(int n, double jitter, std::uint64_t seed)
{
  std::vector<Point2> points = tessera_test::SquareLattice(n);
  std::mt19937_64 random(seed);
  std::uniform_int_distribution<int> ulps(-2, 2);
  for (Point2& p : points)
  {
    if (jitter > 0.0)
    {
      // A few ulps: centres that round to the same point (repeated vertices to drop).
      p.x += jitter * ulps(random);
      p.y += jitter * ulps(random);
    }
  }
  return points;
}

} // namespace

TEST(TilesFastPath, UniformPointsLargeEnoughForThreads)
{
  // 150k points: every pass is split into chunks (results must not depend on it).
  const DirichletTessellation t(
    Window::Rectangle(-0.05, 1.05, -0.05, 1.05), UniformPoints(150000, 3));
  ExpectSameAsGeneralPath(t, "uniform");
}

TEST(TilesFastPath, TightWindowsClipManyTiles)
{
  ExpectSameAsGeneralPath(
    DirichletTessellation(Window::Rectangle(0.1, 0.9, 0.2, 0.85), UniformPoints(120000, 4)),
    "tight rectangle");
  ExpectSameAsGeneralPath(
    DirichletTessellation(Window::Rectangle(0.1, 0.9, 0.2, 0.85), UniformPoints(500, 5)),
    "tight rectangle, few points");
  ExpectSameAsGeneralPath(DirichletTessellation(Hexagon(), UniformPoints(110000, 6)), "hexagon");
  ExpectSameAsGeneralPath(DirichletTessellation(Hexagon(), UniformPoints(300, 7)), "hexagon, few");
}

TEST(TilesFastPath, DegenerateAndNearlyDegenerateFaces)
{
  // Exact lattice: every face degenerate; centres exactly on the window's edges where it cuts
  // through the lattice at half-integers.
  ExpectSameAsGeneralPath(
    DirichletTessellation(Window::Rectangle(0, 260, 0, 260), Lattice(260, 0.0, 1)), "lattice");
  ExpectSameAsGeneralPath(
    DirichletTessellation(Window::Rectangle(10, 200.5, 7, 150), Lattice(260, 0.0, 1)),
    "lattice, clipped");
  // A lattice moved by a few ulps: distinct faces whose centres may round to one point.
  ExpectSameAsGeneralPath(
    DirichletTessellation(Window::Rectangle(0, 240, 0, 240), Lattice(240, 0x1p-46, 2)),
    "jittered lattice");
  // Integer grid subsets: degenerate faces mixed with ordinary ones, duplicates.
  std::mt19937_64 random(8);
  std::vector<Point2> grid;
  for (int k = 0; k < 120000; ++k)
  {
    grid.push_back({ double(random() % 400), double(random() % 400) });
  }
  ExpectSameAsGeneralPath(
    DirichletTessellation(Window::Rectangle(-0.5, 399.5, -0.5, 399.5), grid), "grid subset");
}

TEST(TilesFastPath, AfterRemovals)
{
  // Removals leave free triangles in the arrays.
  DirichletTessellation t(Window::Rectangle(-0.1, 1.1, -0.1, 1.1), UniformPoints(100000, 9));
  for (std::int32_t id = 0; id < 100000; id += 7)
  {
    t.Remove(id);
  }
  ExpectSameAsGeneralPath(t, "after removals");
}

TEST(TilesFastPath, SmallInputs)
{
  ExpectSameAsGeneralPath(DirichletTessellation(Window::Rectangle(0, 1, 0, 1),
                            { { 0.1, 0.1 }, { 0.9, 0.2 }, { 0.5, 0.8 } }),
    "three points");
  ExpectSameAsGeneralPath(DirichletTessellation(Window::Rectangle(-1, 2, -1, 3),
                            { { 0.0, 0.0 }, { 0.1, 0.2 }, { 0.2, 0.4 }, { 0.3, 0.6 } }),
    "collinear");
  for (std::uint64_t seed = 20; seed < 30; ++seed)
  {
    ExpectSameAsGeneralPath(
      DirichletTessellation(Window::Rectangle(0.0, 1.0, 0.0, 1.0), UniformPoints(40, seed)),
      "small " + std::to_string(seed));
  }
}
