// ComputeTilesOf / ComputeFaceMatesOf against the full derivation: bit-identical tiles for any
// subset of points, on random, lattice (every face degenerate) and co-circular sets, after
// insertions and removals, and in the collinear case; face mates against the Delaunay faces; and
// the property the areal average relies on: a tile changes only if it belongs to a face mate of
// a removed point (before) or of an inserted point (after), or to an inserted point.

#include "areal_average.h"
#include "dirichlet_tessellation.h"
#include "tiles.h"

#include "test_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <map>
#include <random>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

using namespace tessera;
using tessera_test::Hexagon;
using tessera_test::UniformPoints;

namespace
{

struct Tile
{
  std::vector<Point2> Vertices;
  double Area = 0.0;
  std::int32_t Neighbors = 0;
};

std::map<std::int32_t, Tile> ByPoint(const TileSet& tiles)
{
  std::map<std::int32_t, Tile> out;
  for (std::size_t k = 0; k < tiles.PointIds.size(); ++k)
  {
    Tile& tile = out[tiles.PointIds[k]];
    tile.Vertices.assign(
      tiles.Vertices.begin() + tiles.Offsets[k], tiles.Vertices.begin() + tiles.Offsets[k + 1]);
    tile.Area = tiles.Areas[k];
    tile.Neighbors = tiles.NeighborCounts[k];
  }
  return out;
}

bool SameBits(const Tile& a, const Tile& b)
{
  if (a.Vertices.size() != b.Vertices.size() || a.Neighbors != b.Neighbors ||
    std::memcmp(&a.Area, &b.Area, sizeof(double)) != 0)
  {
    return false;
  }
  for (std::size_t k = 0; k < a.Vertices.size(); ++k)
  {
    if (std::memcmp(&a.Vertices[k], &b.Vertices[k], sizeof(Point2)) != 0)
    {
      return false;
    }
  }
  return true;
}

// Every accepted point in random subsets (and all at once, and repeated ids, and ids that are
// not accepted) gets the full derivation's tile, bit for bit, in the order asked. The subsets of
// 1, 3 and 12 points are few enough among thousands for the faces to be hashed, not tabled.
void ExpectLocalEqualsFull(const DirichletTessellation& t, unsigned seed)
{
  const std::size_t fewSizes[] = { 1, 3, 12 };
  const std::map<std::int32_t, Tile> full = ByPoint(ComputeTiles(t));
  std::vector<std::int32_t> ids = tessera_test::AcceptedIds(t);
  ASSERT_EQ(full.size(), ids.size());
  std::mt19937_64 rng(seed);
  for (int trial = 0; trial < 7; ++trial)
  {
    std::vector<std::int32_t> ask = ids;
    std::shuffle(ask.begin(), ask.end(), rng);
    ask.resize(trial == 0 ? ask.size()
        : trial < 4       ? std::max<std::size_t>(1, ask.size() / (2 * trial))
                          : std::min(ask.size(), fewSizes[trial - 4]));
    std::vector<std::int32_t> expectedOrder;
    std::set<std::int32_t> seen;
    for (const std::int32_t id : ask)
    {
      if (seen.insert(id).second)
      {
        expectedOrder.push_back(id);
      }
    }
    ask.push_back(ask.front());                  // a repeat
    ask.push_back(std::int32_t(t.PointCount())); // unknown
    FaceMateLists mates;
    const TileSet local = ComputeTilesOf(t, ask, &mates);
    ASSERT_EQ(local.PointIds, expectedOrder);
    ASSERT_EQ(mates.PointIds, expectedOrder);
    const std::map<std::int32_t, Tile> got = ByPoint(local);
    for (const std::int32_t id : expectedOrder)
    {
      EXPECT_TRUE(SameBits(got.at(id), full.at(id))) << "tile of point " << id;
    }
  }
}

// Face mates: every pair of points of one Delaunay face (degenerate faces whole), and nothing
// else. Only for two-dimensional sets (a collinear set has no faces to compare with).
void ExpectMatesFromFaces(const DirichletTessellation& t)
{
  ASSERT_TRUE(t.IsTwoDimensional());
  std::map<std::int32_t, std::set<std::int32_t>> expected;
  const DelaunayFaces faces = ComputeDelaunayFaces(t, false);
  for (std::size_t f = 0; f + 1 < faces.Offsets.size(); ++f)
  {
    for (std::int64_t x = faces.Offsets[f]; x < faces.Offsets[f + 1]; ++x)
    {
      for (std::int64_t y = faces.Offsets[f]; y < faces.Offsets[f + 1]; ++y)
      {
        if (x != y)
        {
          expected[faces.PointIds[x]].insert(faces.PointIds[y]);
        }
      }
    }
  }
  const FaceMateLists mates = ComputeFaceMatesOf(t, tessera_test::AcceptedIds(t));
  for (std::size_t k = 0; k < mates.PointIds.size(); ++k)
  {
    const std::set<std::int32_t> got(
      mates.Ids.begin() + mates.Offsets[k], mates.Ids.begin() + mates.Offsets[k + 1]);
    EXPECT_EQ(got, expected[mates.PointIds[k]]) << "mates of " << mates.PointIds[k];
  }
}

// Signed area of ring r of a set of rings (shoelace, vertices relative to the ring's first to
// keep the terms small).
double ShoelaceArea(const ClippedRings& rings, std::size_t r)
{
  const std::size_t begin = rings.RingOffsets[r], end = rings.RingOffsets[r + 1];
  const Point2& o = rings.Vertices[begin];
  double twice = 0.0;
  for (std::size_t k = begin; k < end; ++k)
  {
    const Point2& a = rings.Vertices[k];
    const Point2& b = rings.Vertices[k + 1 < end ? k + 1 : begin];
    twice += (a.x - o.x) * (b.y - o.y) - (b.x - o.x) * (a.y - o.y);
  }
  return 0.5 * twice;
}

std::vector<Point2> Lattice(int n, double spacing)
{
  std::vector<Point2> points;
  for (int i = 0; i < n; ++i)
  {
    for (int j = 0; j < n; ++j)
    {
      points.push_back({ spacing * (i + 1), spacing * (j + 1) });
    }
  }
  return points;
}

// Points on a few concentric circles with exact coordinates (Pythagorean triples): large
// degenerate faces.
std::vector<Point2> Circles()
{
  std::vector<Point2> points;
  const int triples[][2] = { { 3, 4 }, { 4, 3 }, { 5, 0 }, { 0, 5 } };
  for (const double scale : { 1.0, 2.0, 3.0 })
  {
    for (const auto& t : triples)
    {
      for (const int sx : { -1, 1 })
      {
        for (const int sy : { -1, 1 })
        {
          points.push_back({ 16 + scale * sx * t[0], 16 + scale * sy * t[1] });
        }
      }
    }
  }
  points.push_back({ 16, 16 });
  return points;
}

} // namespace

TEST(LocalTiles, RandomSetsMatchTheFullDerivation)
{
  for (unsigned seed = 1; seed <= 4; ++seed)
  {
    const DirichletTessellation square(
      Window::Rectangle(0, 1, 0, 1), UniformPoints(200 * seed, seed));
    ExpectLocalEqualsFull(square, seed);
    ExpectMatesFromFaces(square);
    const DirichletTessellation hexagon(Hexagon(), UniformPoints(150 * seed, seed + 10));
    ExpectLocalEqualsFull(hexagon, seed);
    ExpectMatesFromFaces(hexagon);
  }
}

// Thousands of points: the request is split across threads (on a machine with more than one
// core) and the joined result must still be the full derivation's, in the asked order.
TEST(LocalTiles, LargeRequestsMatchTheFullDerivation)
{
  const DirichletTessellation uniform(Window::Rectangle(0, 1, 0, 1), UniformPoints(6000, 21));
  ExpectLocalEqualsFull(uniform, 21);
  ExpectMatesFromFaces(uniform);
  const DirichletTessellation lattice(Window::Rectangle(0, 1, 0, 1), Lattice(70, 1.0 / 71));
  ExpectLocalEqualsFull(lattice, 22);
  ExpectMatesFromFaces(lattice);
}

TEST(LocalTiles, DegenerateSetsMatchTheFullDerivation)
{
  const DirichletTessellation lattice(Window::Rectangle(0, 1, 0, 1), Lattice(15, 1.0 / 16));
  ExpectLocalEqualsFull(lattice, 3);
  ExpectMatesFromFaces(lattice);
  // The window's sides through lattice vertices (face centres on the boundary).
  const DirichletTessellation touching(
    Window::Rectangle(0.09375, 0.90625, 0.03125, 1), Lattice(15, 1.0 / 16));
  ExpectLocalEqualsFull(touching, 4);
  ExpectMatesFromFaces(touching);
  const DirichletTessellation circles(Window::Rectangle(0, 32, 0, 32), Circles());
  ExpectLocalEqualsFull(circles, 5);
  ExpectMatesFromFaces(circles);
  // Collinear points: no faces.
  std::vector<Point2> line;
  for (int k = 0; k < 9; ++k)
  {
    line.push_back({ (k + 1) / 16.0, (k + 1) / 32.0 });
  }
  const DirichletTessellation collinear(Window::Rectangle(0, 1, 0, 1), line);
  ASSERT_FALSE(collinear.IsTwoDimensional());
  ExpectLocalEqualsFull(collinear, 6);
}

// VisitTilesOf hands over ComputeTilesOf's tiles, bit for bit and in order within each chunk,
// each once, with chunks contiguous and in order, on 1, 2, 3 and 7 threads (lattice: every face
// degenerate; collinear: no faces), with and without a workspace kept between calls. The error
// rethrown is the first failing tile's.
TEST(LocalTiles, VisitedTilesAreComputeTilesOfsInChunks)
{
  std::vector<Point2> line;
  for (int k = 0; k < 900; ++k)
  {
    line.push_back({ (k + 1) / 1024.0, (k + 1) / 2048.0 });
  }
  const DirichletTessellation sets[] = {
    DirichletTessellation(Window::Rectangle(0, 1, 0, 1), UniformPoints(3000, 41)),
    DirichletTessellation(Window::Rectangle(0, 1, 0, 1), Lattice(40, 1.0 / 41)),
    DirichletTessellation(Window::Rectangle(0, 1, 0, 1), line),
  };
  for (const DirichletTessellation& t : sets)
  {
    std::vector<std::int32_t> ask = tessera_test::AcceptedIds(t);
    std::shuffle(ask.begin(), ask.end(), std::mt19937_64(7));
    ask.resize(ask.size() * 2 / 3);
    ask.push_back(ask.front()); // a repeat, skipped
    const TileSet expected = ComputeTilesOf(t, ask);
    // A workspace kept over the calls (as the areal average keeps one) must leave no trace: its
    // tables are all unlisted after each call, and the next call gives the same tiles.
    LocalTilesWorkspace workspace;
    const auto allUnlisted = [&workspace]()
    {
      for (const std::vector<std::int32_t>& table : workspace.FaceTables)
      {
        if (std::any_of(table.begin(), table.end(), [](std::int32_t e) { return e != -1; }))
        {
          return false;
        }
      }
      return true;
    };
    for (const int threads : { 1, 2, 3, 7, 3 })
    {
      const tessera_test::ThreadLimitOverride limit(threads);
      std::vector<std::vector<std::pair<std::int32_t, std::vector<Point2>>>> byChunk(threads);
      const std::size_t visited = VisitTilesOf(
        t,
        ask,
        std::size_t(threads),
        100,
        [&](std::size_t chunk, std::int32_t id, const Point2* tile, std::size_t count)
        { byChunk.at(chunk).emplace_back(id, std::vector<Point2>(tile, tile + count)); },
        threads == 2 ? nullptr : &workspace);
      EXPECT_TRUE(allUnlisted());
      EXPECT_EQ(visited, expected.PointIds.size());
      std::size_t k = 0;
      std::size_t chunksUsed = 0;
      for (const auto& chunk : byChunk)
      {
        chunksUsed += chunk.empty() ? 0 : 1;
        for (const auto& [id, tile] : chunk)
        {
          ASSERT_LT(k, expected.PointIds.size());
          EXPECT_EQ(id, expected.PointIds[k]);
          const std::vector<Point2> want(expected.Vertices.begin() + expected.Offsets[k],
            expected.Vertices.begin() + expected.Offsets[k + 1]);
          EXPECT_TRUE(tile.size() == want.size() &&
            std::memcmp(tile.data(), want.data(), tile.size() * sizeof(Point2)) == 0)
            << "tile of " << id << ", " << threads << " threads";
          ++k;
        }
      }
      EXPECT_EQ(k, expected.PointIds.size());
      if (t.IsTwoDimensional())
      {
        EXPECT_EQ(chunksUsed, std::size_t(threads)) << threads << " threads"; // >= 100 tiles each
      }
    }
    // Errors: tiles fail from a point on; on any number of threads, that point's error arrives.
    const std::int32_t firstFailing = expected.PointIds[expected.PointIds.size() / 3];
    std::vector<char> failing(t.PointCount(), 0);
    for (std::size_t k = expected.PointIds.size() / 3; k < expected.PointIds.size(); ++k)
    {
      failing[expected.PointIds[k]] = 1;
    }
    for (const int threads : { 1, 3 })
    {
      const tessera_test::ThreadLimitOverride limit(threads);
      try
      {
        VisitTilesOf(
          t,
          ask,
          std::size_t(threads),
          100,
          [&](std::size_t, std::int32_t id, const Point2*, std::size_t)
          {
            if (failing[id])
            {
              throw std::runtime_error(std::to_string(id));
            }
          },
          &workspace);
        ADD_FAILURE() << "no error";
      }
      catch (const std::runtime_error& error)
      {
        EXPECT_EQ(std::string(error.what()), std::to_string(firstFailing));
      }
      EXPECT_TRUE(allUnlisted()) << "after an error, " << threads << " threads";
    }
  }
}

// With a workspace, the calling thread's chunk takes CallerWeight tiles per tile of the other's,
// the weight moving after each call a quarter of the way to what would have ended the chunks
// together (within 1/2 .. 2), and staying where a chunk is too small to time (under 64 tiles). The
// tiles are ComputeTilesOf's whatever the split.
TEST(LocalTiles, TheCallingThreadsShareOfTheTilesAdaptsToTheChunksTimes)
{
  const DirichletTessellation t(Window::Rectangle(0, 1, 0, 1), UniformPoints(3000, 43));
  const std::vector<std::int32_t> all = tessera_test::AcceptedIds(t);
  const tessera_test::ThreadLimitOverride limit(2);
  LocalTilesWorkspace workspace;
  const auto visitChunks = [&](const std::vector<std::int32_t>& ask)
  {
    const TileSet expected = ComputeTilesOf(t, ask);
    std::size_t firstChunk = 0, k = 0;
    VisitTilesOf(
      t,
      ask,
      2,
      10,
      [&](std::size_t chunk, std::int32_t id, const Point2* tile, std::size_t count)
      {
        // (chunk 0 runs on this thread; the other chunk's tiles are checked by their count)
        if (chunk == 0)
        {
          ++firstChunk;
          EXPECT_EQ(id, expected.PointIds[k]);
          EXPECT_EQ(std::memcmp(
                      tile, expected.Vertices.data() + expected.Offsets[k], count * sizeof(Point2)),
            0);
          ++k;
        }
      },
      &workspace);
    return firstChunk;
  };
  // Too few to time: 100 tiles, two chunks of 50.
  const std::vector<std::int32_t> few(all.begin(), all.begin() + 100);
  EXPECT_EQ(visitChunks(few), 50u);
  EXPECT_EQ(workspace.CallerWeight, 1.0);
  // A weight of 1.5: 1500 of 2500 tiles on the calling thread, then a weight in
  // 0.75 * 1.5 + 0.25 * [0.5, 2].
  const std::vector<std::int32_t> many(all.begin(), all.begin() + 2500);
  workspace.CallerWeight = 1.5;
  EXPECT_EQ(visitChunks(many), 1500u);
  EXPECT_GE(workspace.CallerWeight, 1.25);
  EXPECT_LE(workspace.CallerWeight, 1.625);
  for (int call = 0; call < 20; ++call)
  {
    const double weight = workspace.CallerWeight;
    EXPECT_EQ(visitChunks(many), std::size_t(std::round(2500 * weight / (weight + 1))));
    EXPECT_GE(workspace.CallerWeight, 0.5);
    EXPECT_LE(workspace.CallerWeight, 2.0);
  }
}

// The areal average's update rule: after removals and insertions, the tiles that differ from
// before are among the face mates (before) of the removed points, the face mates (after) of the
// inserted points and the inserted points themselves; and the local tiles of those equal a full
// derivation of the updated tessellation.
TEST(LocalTiles, ChangedTilesAreFaceMatesOfTheChangedPoints)
{
  for (const bool lattice : { false, true })
  {
    std::vector<Point2> points = lattice ? Lattice(20, 1.0 / 21) : UniformPoints(600, 7);
    DirichletTessellation t(Window::Rectangle(0, 1, 0, 1), points);
    std::mt19937_64 rng(lattice ? 11 : 12);
    std::vector<char> active(points.size(), 1);
    std::map<std::int32_t, std::int32_t> idOf; // point index -> current tessellation id
    for (std::int32_t k = 0; k < std::int32_t(points.size()); ++k)
    {
      idOf[k] = k;
    }
    for (int step = 0; step < 12; ++step)
    {
      const std::map<std::int32_t, Tile> before = ByPoint(ComputeTiles(t));
      std::vector<std::int32_t> removed, insertedIds;
      for (std::size_t k = 0; k < points.size(); ++k)
      {
        if (rng() % 20 == 0)
        {
          if (active[k])
          {
            removed.push_back(idOf[std::int32_t(k)]);
          }
          active[k] = !active[k];
        }
      }
      std::set<std::int32_t> affected;
      const FaceMateLists old = ComputeFaceMatesOf(t, removed);
      affected.insert(old.Ids.begin(), old.Ids.end());
      for (const std::int32_t id : removed)
      {
        t.Remove(id);
      }
      for (std::size_t k = 0; k < points.size(); ++k)
      {
        if (active[k] && t.Status(idOf[std::int32_t(k)]) == PointStatus::Removed)
        {
          idOf[std::int32_t(k)] = t.Insert(points[k]);
          insertedIds.push_back(idOf[std::int32_t(k)]);
        }
      }
      const FaceMateLists fresh = ComputeFaceMatesOf(t, insertedIds);
      affected.insert(fresh.Ids.begin(), fresh.Ids.end());
      affected.insert(insertedIds.begin(), insertedIds.end());
      const std::map<std::int32_t, Tile> after = ByPoint(ComputeTiles(t));
      std::vector<std::int32_t> ask;
      for (const auto& [id, tile] : after)
      {
        const auto previous = before.find(id);
        const bool changed = previous == before.end() || !SameBits(previous->second, tile);
        if (changed)
        {
          EXPECT_TRUE(affected.count(id)) << "tile of " << id << " changed unannounced";
        }
        if (affected.count(id))
        {
          ask.push_back(id);
        }
      }
      const std::map<std::int32_t, Tile> local = ByPoint(ComputeTilesOf(t, ask));
      ASSERT_EQ(local.size(), ask.size());
      for (const std::int32_t id : ask)
      {
        EXPECT_TRUE(SameBits(local.at(id), after.at(id))) << "tile of " << id;
      }
    }
  }
}

// The areal average's local path (few gauges toggling per step) against rebuilding every step:
// same weighted gauges, weights and means, and the same clipped tiles for display.
TEST(LocalTiles, ArealAverageUpdatesEqualRebuildsWhenFewGaugesToggle)
{
  // (Uniform gauges only: with a lon/lat lattice of gauges the rebuild and the update already
  // disagreed before the local derivation, through core/clip on tiles whose bits differ.)
  {
    std::mt19937_64 random(22);
    std::uniform_real_distribution<double> lon(-109.0, -102.0), lat(37.0, 41.0), value(0, 10);
    std::vector<Point2> gauges;
    for (int k = 0; k < 600; ++k)
    {
      gauges.push_back({ lon(random), lat(random) });
    }
    const std::vector<std::size_t> offsets{ 0, 5 };
    const std::vector<Point2> ring{
      { -108.0, 37.5 }, { -103.0, 37.5 }, { -103.0, 40.5 }, { -105.5, 41.2 }, { -108.0, 40.5 }
    };
    ArealAverageSettings incremental, rebuild;
    rebuild.Incremental = false;
    ThiessenArealAverage a(gauges, offsets, ring, incremental);
    ThiessenArealAverage b(gauges, offsets, ring, rebuild);
    std::vector<double> values(gauges.size());
    std::vector<char> reporting(gauges.size(), 1);
    for (int t = 0; t < 30; ++t)
    {
      for (std::size_t g = 0; g < gauges.size(); ++g)
      {
        // 3% toggle per step (under the 20% limit of the local path), except a burst at step 10.
        if (random() % 100 < (t == 10 ? 40U : 3U))
        {
          reporting[g] = !reporting[g];
        }
        values[g] = reporting[g] ? value(random) : std::nan("");
      }
      const ArealStep x = a.Step(values);
      const ArealStep y = b.Step(values);
      ASSERT_EQ(x.Gauges, y.Gauges) << "step " << t;
      for (std::size_t k = 0; k < x.Weights.size(); ++k)
      {
        EXPECT_NEAR(x.Weights[k], y.Weights[k], 1e-13) << "step " << t << " gauge " << x.Gauges[k];
      }
      EXPECT_NEAR(x.Mean, y.Mean, 1e-12) << "step " << t;
      EXPECT_EQ(x.StationsWeighted, y.StationsWeighted);
      const ClippedTilesLonLat ca = a.CurrentClippedTiles(5000.0);
      const ClippedTilesLonLat cb = b.CurrentClippedTiles(5000.0);
      EXPECT_EQ(ca.Gauges, cb.Gauges) << "step " << t;
      // (Vertex counts may differ: the engines' ids differ, so centres round differently.)
      EXPECT_EQ(ca.TilePieceOffsets, cb.TilePieceOffsets) << "step " << t;
      ASSERT_EQ(ca.Pieces.RingOffsets.size(), cb.Pieces.RingOffsets.size()) << "step " << t;
      // Each ring's area (shoelace in lon/lat degrees) agrees: the vertices differ only by
      // rounding (of the face centres, then of the unprojection), which moves a ring's area by
      // about 1e-13 of itself (the largest difference seen here is 1.1e-13); checked at 1e-11.
      for (std::size_t r = 0; r + 1 < ca.Pieces.RingOffsets.size(); ++r)
      {
        const double areaA = ShoelaceArea(ca.Pieces, r), areaB = ShoelaceArea(cb.Pieces, r);
        EXPECT_NEAR(areaA, areaB, 1e-11 * std::fabs(areaB)) << "step " << t << " ring " << r;
      }
    }
  }
}
