// The Brassel-Reif sweep: against an exact brute force (each tile clipped from the window by all
// bisectors in rational arithmetic, GMP) on small sets, against the Green-Sibson engine on larger
// ones, and on properties: areas summing to the window's, no vertex repeated in a row, lattices
// whose half-neighbours are exactly the diagonals, rejected and duplicate points, errors.
#include "dirichlet_tessellation.h"
#include "errors.h"
#include "predicates.h"
#include "thiessen_sweep.h"
#include "tiles.h"
#include "window.h"

#include <gmpxx.h>
#include "test_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numeric>
#include <random>
#include <set>
#include <string>
#include <tuple>
#include <vector>

using namespace tessera;
using tessera_test::GraphPairs;
using tessera_test::PairKinds;

namespace
{

// ---------------------------------------------------------------------------------------------
// Exact brute force.

struct QPoint
{
  mpq_class x, y;
};

bool operator==(const QPoint& a, const QPoint& b)
{
  return a.x == b.x && a.y == b.y;
}

struct BruteForce
{
  PairKinds pairs;
  std::map<std::int32_t, mpq_class> areas;              // by point id
  std::map<std::int32_t, std::vector<QPoint>> polygons; // by point id
};

// The closed tile of point i: the window clipped by the closed half-planes nearer to i than to
// each other accepted point. Edge labels: the other point's id, or -1 - side for the window.
void clip_tile(const std::vector<Point2>& pts,
  const std::vector<std::int32_t>& accepted,
  std::int32_t i,
  double xmin,
  double xmax,
  double ymin,
  double ymax,
  std::vector<QPoint>& poly,
  std::vector<std::int32_t>& labels)
{
  poly = { { xmin, ymin }, { xmax, ymin }, { xmax, ymax }, { xmin, ymax } };
  labels = { -3, -2, -4, -1 }; // bottom, right, top, left
  const mpq_class px = pts[i].x, py = pts[i].y;
  for (const std::int32_t j : accepted)
  {
    if (j == i)
    {
      continue;
    }
    const mpq_class qx = pts[j].x, qy = pts[j].y;
    // Keep f(v) = 2 (q - p) . v - (|q|^2 - |p|^2) <= 0.
    const mpq_class ax = 2 * (qx - px), ay = 2 * (qy - py);
    const mpq_class c = qx * qx + qy * qy - px * px - py * py;
    std::vector<QPoint> out;
    std::vector<std::int32_t> outLabels;
    const std::size_t n = poly.size();
    std::vector<mpq_class> f(n);
    for (std::size_t k = 0; k < n; ++k)
    {
      f[k] = ax * poly[k].x + ay * poly[k].y - c;
    }
    for (std::size_t k = 0; k < n; ++k)
    {
      const std::size_t k1 = (k + 1) % n;
      if (f[k] <= 0)
      {
        out.push_back(poly[k]);
        outLabels.push_back(labels[k]);
      }
      if ((f[k] < 0 && f[k1] > 0) || (f[k] > 0 && f[k1] < 0))
      {
        const mpq_class t = f[k] / (f[k] - f[k1]);
        out.push_back(
          { poly[k].x + t * (poly[k1].x - poly[k].x), poly[k].y + t * (poly[k1].y - poly[k].y) });
        // Entering the kept side: the new edge continues the old one; leaving: along the bisector.
        outLabels.push_back(f[k] < 0 ? j : labels[k]);
      }
      else if (f[k] == 0 && f[k1] > 0)
      {
        outLabels.back() = j; // leave along the bisector from this vertex
      }
    }
    // Drop zero-length edges (repeated vertices).
    std::vector<QPoint> clean;
    std::vector<std::int32_t> cleanLabels;
    for (std::size_t k = 0; k < out.size(); ++k)
    {
      if (!(out[k] == out[(k + 1) % out.size()]))
      {
        clean.push_back(out[k]);
        cleanLabels.push_back(outLabels[k]);
      }
    }
    poly = clean;
    labels = cleanLabels;
  }
}

BruteForce brute_force(const std::vector<Point2>& pts,
  double xmin,
  double xmax,
  double ymin,
  double ymax)
{
  // Accepted points: strictly inside, first of each set of duplicates.
  std::vector<std::int32_t> accepted;
  std::set<std::pair<double, double>> seen;
  for (std::size_t i = 0; i < pts.size(); ++i)
  {
    const Point2& p = pts[i];
    if (xmin < p.x && p.x < xmax && ymin < p.y && p.y < ymax && seen.insert({ p.x, p.y }).second)
    {
      accepted.push_back(std::int32_t(i));
    }
  }
  BruteForce bf;
  std::map<std::int32_t, std::vector<std::int32_t>> labels;
  for (const std::int32_t i : accepted)
  {
    clip_tile(pts, accepted, i, xmin, xmax, ymin, ymax, bf.polygons[i], labels[i]);
    const auto& poly = bf.polygons[i];
    mpq_class area = 0;
    for (std::size_t k = 0; k < poly.size(); ++k)
    {
      const QPoint& a = poly[k];
      const QPoint& b = poly[(k + 1) % poly.size()];
      area += a.x * b.y - b.x * a.y;
    }
    bf.areas[i] = area / 2;
    for (const std::int32_t j : labels[i])
    {
      if (j >= 0)
      {
        bf.pairs[{ std::min(i, j), std::max(i, j) }] = 0;
      }
    }
  }
  // Half-neighbours: a common vertex strictly inside the window, no common edge.
  for (std::size_t a = 0; a < accepted.size(); ++a)
  {
    for (std::size_t b = a + 1; b < accepted.size(); ++b)
    {
      const std::int32_t i = accepted[a], j = accepted[b];
      if (bf.pairs.count({ i, j }))
      {
        continue;
      }
      for (const QPoint& v : bf.polygons[i])
      {
        const bool inside = v.x > xmin && v.x < xmax && v.y > ymin && v.y < ymax;
        if (inside &&
          std::find(bf.polygons[j].begin(), bf.polygons[j].end(), v) != bf.polygons[j].end())
        {
          bf.pairs[{ i, j }] = 1;
          break;
        }
      }
    }
  }
  return bf;
}

// ---------------------------------------------------------------------------------------------
// Checks.

// How closely a tile area can be known when its vertices are doubles: 1e-12 of the window's area,
// or, far from the origin (2^30-offset sets), the rounding of the vertex coordinates (an ulp of
// the largest coordinate) times the perimeter.
double area_tolerance(const Window& window)
{
  double largest = 0.0, perimeter = 0.0;
  const auto& v = window.Vertices();
  for (std::size_t k = 0; k < v.size(); ++k)
  {
    largest = std::max({ largest, std::fabs(v[k].x), std::fabs(v[k].y) });
    const Point2& w = v[(k + 1) % v.size()];
    perimeter += std::hypot(w.x - v[k].x, w.y - v[k].y);
  }
  const double ulp = std::nextafter(largest, 2 * largest + 1) - largest;
  return 1e-12 * window.Area() + 8 * ulp * perimeter;
}

// Whether tile k lists some vertex twice in a row, the last and the first included.
bool repeats_a_vertex(const TileSet& t, std::size_t k)
{
  const std::int64_t b = t.Offsets[k], e = t.Offsets[k + 1];
  for (std::int64_t v = b; v < e; ++v)
  {
    const Point2& next = t.Vertices[v + 1 < e ? v + 1 : b];
    if (t.Vertices[v].x == next.x && t.Vertices[v].y == next.y)
    {
      return true;
    }
  }
  return false;
}

// Structure every result must have: tiles anticlockwise and convex around their point, areas
// summing to the window's, contiguities sorted and symmetric in the tiles' neighbour lists.
void check_structure(const ThiessenSweepResult& r,
  const std::vector<Point2>& pts,
  double area,
  double tolerance)
{
  const TileSet& t = r.Tiles;
  ASSERT_EQ(t.Offsets.size(), t.PointIds.size() + 1);
  ASSERT_EQ(t.Areas.size(), t.PointIds.size());
  ASSERT_EQ(r.Counts.size(), t.PointIds.size());
  EXPECT_EQ(t.PointIds.size() + r.RejectedIds.size() + r.Duplicates.size(), pts.size());
  EXPECT_TRUE(std::is_sorted(t.PointIds.begin(), t.PointIds.end()));
  // Compensated sum of the tile areas.
  double sum = 0.0, compensation = 0.0;
  for (std::size_t k = 0; k < t.PointIds.size(); ++k)
  {
    const double a = t.Areas[k];
    const double s = sum + a;
    compensation += std::fabs(sum) >= std::fabs(a) ? (sum - s) + a : (a - s) + sum;
    sum = s;
    const Point2& p = pts[t.PointIds[k]];
    const std::int64_t b = t.Offsets[k], e = t.Offsets[k + 1];
    // (a tile narrower than 1e-150 can have an area below the doubles' range: 0 is its rounding)
    const Box2 box = BoundsOf(t.Vertices.data() + b, std::size_t(e - b));
    EXPECT_TRUE(a > 0.0 || (a == 0.0 && box.LargerSide() < 1e-150))
      << "tile of point " << t.PointIds[k];
    // NeighborCount is the exact number of sides; distinct vertices rounded to one point are
    // written once, so a tile can have fewer vertices, never more.
    EXPECT_GE(t.NeighborCounts[k], e - b);
    ASSERT_GE(e - b, 3);
    EXPECT_FALSE(repeats_a_vertex(t, k)) << "tile of point " << t.PointIds[k];
    for (std::int64_t v = b; v < e; ++v)
    {
      const Point2& u = t.Vertices[v];
      const Point2& w = t.Vertices[v + 1 < e ? v + 1 : b];
      // The point lies on the inner side of every side (up to the rounding of the vertices).
      const double cross = (w.x - u.x) * (p.y - u.y) - (w.y - u.y) * (p.x - u.x);
      EXPECT_GT(cross, -1e-9 * area) << "tile of point " << t.PointIds[k];
    }
    EXPECT_GE(r.Counts[k].Consulted, r.Counts[k].PassedTests);
    EXPECT_GE(r.Counts[k].PassedTests, r.Counts[k].InCircle);
  }
  if (!t.PointIds.empty())
  {
    EXPECT_NEAR(sum + compensation, area, tolerance);
  }
  const ContiguityGraph& g = r.Contiguities;
  ASSERT_EQ(g.Pairs.size(), 2 * g.Kinds.size());
  for (std::size_t k = 0; k < g.Kinds.size(); ++k)
  {
    EXPECT_LT(g.Pairs[2 * k], g.Pairs[2 * k + 1]);
    if (k > 0)
    {
      EXPECT_LT(std::make_pair(g.Pairs[2 * k - 2], g.Pairs[2 * k - 1]),
        std::make_pair(g.Pairs[2 * k], g.Pairs[2 * k + 1]));
    }
  }
}

// Each search finds one Thiessen vertex, which every centroid on its circle then knows, so a
// tile's searches are its vertices that no tile processed before it has. The sweep takes the
// centroid nearest the window's lower-left corner first, then the rest by (x, y); that corner is
// recorded for the first before any search when no other centroid is as near. Checked where no
// tile merged two vertices rounded to one point (its corners then name the sweep's vertices).
void expect_searches_are_first_finds(const ThiessenSweepResult& r,
  const std::vector<Point2>& pts,
  double xmin,
  double ymin)
{
  const TileSet& t = r.Tiles;
  for (std::size_t k = 0; k < t.PointIds.size(); ++k)
  {
    if (t.NeighborCounts[k] != t.Offsets[k + 1] - t.Offsets[k])
    {
      return;
    }
  }
  std::vector<std::size_t> order(t.PointIds.size());
  std::iota(order.begin(), order.end(), std::size_t(0));
  const auto place = [&](std::size_t k) { return pts[std::size_t(t.PointIds[k])]; };
  std::sort(order.begin(),
    order.end(),
    [&](std::size_t a, std::size_t b)
    { return std::make_pair(place(a).x, place(a).y) < std::make_pair(place(b).x, place(b).y); });
  const auto squaredDistance = [&](std::size_t k)
  {
    const mpq_class dx = mpq_class(place(k).x) - mpq_class(xmin);
    const mpq_class dy = mpq_class(place(k).y) - mpq_class(ymin);
    return mpq_class(dx * dx + dy * dy);
  };
  std::size_t first = order.empty() ? 0 : order[0];
  mpq_class nearest = order.empty() ? mpq_class(0) : squaredDistance(first);
  bool unique = true;
  for (std::size_t n = 1; n < order.size(); ++n)
  {
    const mpq_class distance = squaredDistance(order[n]);
    const int c = cmp(distance, nearest);
    unique = c < 0 || (unique && c > 0);
    if (c < 0)
    {
      first = order[n];
      nearest = distance;
    }
  }
  std::set<std::int32_t> known;
  const auto firstFinds = [&](std::size_t k)
  {
    std::uint32_t found = 0;
    for (std::int64_t v = t.Offsets[k]; v < t.Offsets[k + 1]; ++v)
    {
      found += known.insert(r.CornerVertexIds[std::size_t(v)]).second ? 1 : 0;
    }
    return found;
  };
  if (!order.empty())
  {
    EXPECT_EQ(r.Counts[first].Searches, firstFinds(first) - (unique ? 1 : 0)) << "first tile";
  }
  for (const std::size_t k : order)
  {
    if (k != first)
    {
      EXPECT_EQ(r.Counts[k].Searches, firstFinds(k)) << "tile of point " << t.PointIds[k];
    }
  }
}

void expect_matches_brute_force(const std::vector<Point2>& pts,
  double xmin,
  double xmax,
  double ymin,
  double ymax)
{
  const Window window = Window::Rectangle(xmin, xmax, ymin, ymax);
  const ThiessenSweepResult r = ComputeThiessenSweep(window, pts);
  const double area = (xmax - xmin) * (ymax - ymin);
  const double tolerance = area_tolerance(window);
  check_structure(r, pts, area, tolerance);
  expect_searches_are_first_finds(r, pts, xmin, ymin);
  const BruteForce bf = brute_force(pts, xmin, xmax, ymin, ymax);
  const PairKinds got = GraphPairs(r.Contiguities);
  EXPECT_EQ(got, bf.pairs);
  if (got != bf.pairs)
  {
    for (const auto& [pair, kind] : bf.pairs)
    {
      auto it = got.find(pair);
      if (it == got.end() || it->second != kind)
      {
        ADD_FAILURE() << "brute force has " << pair.first << "-" << pair.second << " kind " << kind
                      << (it == got.end() ? ", sweep has nothing" : ", sweep differs");
      }
    }
    for (const auto& [pair, kind] : got)
    {
      if (!bf.pairs.count(pair))
      {
        ADD_FAILURE() << "sweep has extra " << pair.first << "-" << pair.second << " kind " << kind;
      }
    }
  }
  ASSERT_EQ(r.Tiles.PointIds.size(), bf.areas.size());
  for (std::size_t k = 0; k < r.Tiles.PointIds.size(); ++k)
  {
    const std::int32_t id = r.Tiles.PointIds[k];
    EXPECT_NEAR(r.Tiles.Areas[k], bf.areas.at(id).get_d(), tolerance) << "point " << id;
    // As many sides as the exact tile has distinct vertices; as many written vertices, less
    // those that round to the point before them.
    const std::int64_t exactVertices = std::int64_t(bf.polygons.at(id).size());
    EXPECT_EQ(r.Tiles.NeighborCounts[k], exactVertices) << "point " << id;
    EXPECT_LE(r.Tiles.Offsets[k + 1] - r.Tiles.Offsets[k], exactVertices) << "point " << id;
  }
}

// Both engines: the same kind-0 and kind-1 pairs, the same (exact) numbers of sides, and areas
// within 1e-12 of the window's area. Returns the sweep's result, for further checks.
ThiessenSweepResult expect_engines_agree(const std::vector<Point2>& pts, const Window& window)
{
  const ThiessenSweepResult br = ComputeThiessenSweep(window, pts);
  const double tolerance = area_tolerance(window);
  check_structure(br, pts, window.Area(), tolerance);
  const DirichletTessellation gs(window, pts);
  // A point inside with a nonzero coordinate below 2^-200 of the window's reach (an ulp from a
  // side at 0) is beyond the Green-Sibson window decisions' exact range: its derivations refuse
  // it (window.h), and the sweep's tiles stand alone.
  const double tiny = std::ldexp(window.Reach(), -200);
  const auto below = [&](const Point2& p)
  {
    const auto small = [&](double v) { return v != 0.0 && std::fabs(v) < tiny; };
    return (small(p.x) || small(p.y)) && window.Contains(p);
  };
  if (std::any_of(pts.begin(), pts.end(), below))
  {
    EXPECT_THROW(TessellationDual(gs).Tiles(), InputError);
    return br;
  }
  const TessellationDual dual(gs);
  const TileSet gsTiles = dual.Tiles();
  const ContiguityGraph gsGraph = dual.Contiguities();
  EXPECT_EQ(GraphPairs(br.Contiguities), GraphPairs(gsGraph));
  std::map<std::int32_t, std::size_t> gsTile; // point id -> position in gsTiles
  for (std::size_t k = 0; k < gsTiles.PointIds.size(); ++k)
  {
    gsTile[gsTiles.PointIds[k]] = k;
  }
  EXPECT_EQ(gsTile.size(), br.Tiles.PointIds.size());
  if (gsTile.size() != br.Tiles.PointIds.size())
  {
    return br;
  }
  // Vertices inside the window come from the same three points by the same arithmetic in both
  // engines (FaceCentre, circumcentre.h): the same bits, tile by tile.
  const Box2 bounds = BoundsOf(window.Vertices().data(), window.Vertices().size());
  const auto interiorVertices = [&](const TileSet& tiles, std::size_t k)
  {
    std::vector<std::pair<double, double>> inside;
    for (std::int64_t v = tiles.Offsets[k]; v < tiles.Offsets[k + 1]; ++v)
    {
      const Point2& p = tiles.Vertices[std::size_t(v)];
      if (bounds.XMin < p.x && p.x < bounds.XMax && bounds.YMin < p.y && p.y < bounds.YMax)
      {
        inside.emplace_back(p.x, p.y);
      }
    }
    std::sort(inside.begin(), inside.end());
    return inside;
  };
  for (std::size_t k = 0; k < br.Tiles.PointIds.size(); ++k)
  {
    const std::size_t g = gsTile[br.Tiles.PointIds[k]];
    EXPECT_NEAR(br.Tiles.Areas[k], gsTiles.Areas[g], tolerance) << "point " << br.Tiles.PointIds[k];
    EXPECT_EQ(br.Tiles.NeighborCounts[k], gsTiles.NeighborCounts[g])
      << "point " << br.Tiles.PointIds[k];
    EXPECT_EQ(interiorVertices(br.Tiles, k), interiorVertices(gsTiles, g))
      << "point " << br.Tiles.PointIds[k];
  }
  EXPECT_EQ(br.RejectedIds, gs.RejectedIds());
  EXPECT_EQ(br.Duplicates, gs.Duplicates());
  return br;
}

std::vector<Point2> gaussian_clusters(std::size_t n, std::uint64_t seed)
{
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> g(0.0, 0.07);
  std::vector<Point2> p;
  while (p.size() < n)
  {
    const bool first = p.size() % 2 == 0;
    const Point2 q{ (first ? 0.3 : 0.7) + g(rng), (first ? 0.35 : 0.65) + g(rng) };
    if (q.x > 0 && q.x < 1 && q.y > 0 && q.y < 1)
    {
      p.push_back(q);
    }
  }
  return p;
}

std::vector<Point2> square_lattice(int n, double step = 1.0, double x0 = 0.0, double y0 = 0.0)
{
  std::vector<Point2> p;
  for (int j = 0; j < n; ++j)
  {
    for (int i = 0; i < n; ++i)
    {
      p.push_back({ x0 + i * step, y0 + j * step });
    }
  }
  return p;
}

// The 12 integer points on the circle of radius 5 about the origin (exactly co-circular).
const std::vector<std::pair<int, int>> RadiusFiveLatticePoints{ { 5, 0 },
  { 4, 3 },
  { 3, 4 },
  { 0, 5 },
  { -3, 4 },
  { -4, 3 },
  { -5, 0 },
  { -4, -3 },
  { -3, -4 },
  { 0, -5 },
  { 3, -4 },
  { 4, -3 } };

// An n x n lattice of step 0.1 from (0.2, 0.2) with every coordinate nudged by 0 or 1 ulp.
std::vector<Point2> nudged_square_lattice(int n, std::mt19937_64& rng)
{
  std::vector<Point2> pts = square_lattice(n, 0.1, 0.2, 0.2);
  for (Point2& p : pts)
  {
    if (rng() % 2)
    {
      p.x = std::nextafter(p.x, rng() % 2 ? 2.0 : -2.0);
    }
    if (rng() % 3 == 0)
    {
      p.y = std::nextafter(p.y, rng() % 2 ? 2.0 : -2.0);
    }
  }
  return pts;
}

} // namespace

// ---------------------------------------------------------------------------------------------

TEST(ThiessenSweep, UniformMatchesBruteForce)
{
  for (std::uint64_t seed = 1; seed <= 6; ++seed)
  {
    expect_matches_brute_force(tessera_test::UniformPoints(20 + 15 * seed, seed), 0, 1, 0, 1);
  }
}

TEST(ThiessenSweep, TinySets)
{
  expect_matches_brute_force({}, 0, 1, 0, 1);
  expect_matches_brute_force({ { 0.3, 0.6 } }, 0, 1, 0, 1);
  expect_matches_brute_force({ { 0.3, 0.6 }, { 0.7, 0.2 } }, 0, 1, 0, 1);
  expect_matches_brute_force({ { 0.5, 0.2 }, { 0.5, 0.8 } }, 0, 1, 0, 1); // same abscissa
  expect_matches_brute_force({ { 0.2, 0.5 }, { 0.8, 0.5 } }, 0, 1, 0, 1); // same ordinate
  // Collinear points (no Delaunay triangle at all), diagonal, vertical and horizontal.
  std::vector<Point2> diagonal, vertical, horizontal;
  for (int k = 1; k < 10; ++k)
  {
    diagonal.push_back({ 0.1 * k, 0.1 * k });
    vertical.push_back({ 0.5, 0.1 * k });
    horizontal.push_back({ 0.1 * k, 0.25 });
  }
  expect_matches_brute_force(diagonal, 0, 1, 0, 1);
  expect_matches_brute_force(vertical, 0, 1, 0, 1);
  expect_matches_brute_force(horizontal, 0, 1, 0, 1);
  // Points on a circle centred on the left side: a vertex shared with their reflections.
  std::vector<Point2> onSide;
  for (const auto& [x, y] :
    std::vector<std::pair<int, int>>{ { 3, 4 }, { 4, 3 }, { 5, 0 }, { 4, -3 }, { 3, -4 } })
  {
    onSide.push_back({ x / 16.0, 0.5 + y / 16.0 });
  }
  expect_matches_brute_force(onSide, 0, 1, 0, 1);
  onSide.push_back({ 0.75, 0.5 });
  expect_matches_brute_force(onSide, 0, 1, 0, 1);
  // ... and on a circle centred on a corner (both at distance 5/16 from (0, 0)).
  expect_matches_brute_force(
    { { 3 / 16.0, 4 / 16.0 }, { 4 / 16.0, 3 / 16.0 }, { 0.6, 0.7 } }, 0, 1, 0, 1);
  expect_matches_brute_force(
    { { 1 - 3 / 16.0, 1 - 4 / 16.0 }, { 1 - 4 / 16.0, 1 - 3 / 16.0 }, { 0.2, 0.3 }, { 0.5, 0.5 } },
    0,
    1,
    0,
    1);
  // The one point nearest the lower-left corner is tied with another.
  expect_matches_brute_force({ { 0.2, 0.1 }, { 0.1, 0.2 }, { 0.6, 0.7 } }, 0, 1, 0, 1);
}

TEST(ThiessenSweep, SquareLatticeHalfNeighboursAreTheDiagonals)
{
  const int n = 12;
  const std::vector<Point2> pts = square_lattice(n);
  // Border through the Voronoi vertices of the outer row, and off them.
  for (const auto& [lo, hi] : { std::pair<double, double>{ -0.5, n - 0.5 }, { -0.3, n - 0.8 } })
  {
    const ThiessenSweepResult r = ComputeThiessenSweep(Window::Rectangle(lo, hi, lo, hi), pts);
    check_structure(r, pts, (hi - lo) * (hi - lo), 1e-12 * (hi - lo) * (hi - lo));
    PairKinds expected;
    for (int j = 0; j < n; ++j)
    {
      for (int i = 0; i < n; ++i)
      {
        const int id = j * n + i;
        if (i + 1 < n)
        {
          expected[{ id, id + 1 }] = 0;
        }
        if (j + 1 < n)
        {
          expected[{ id, id + n }] = 0;
        }
        if (i + 1 < n && j + 1 < n)
        {
          expected[{ id, id + n + 1 }] = 1;
          expected[{ id + 1, id + n }] = 1;
        }
      }
    }
    EXPECT_EQ(GraphPairs(r.Contiguities), expected);
    EXPECT_EQ(r.DegenerateVertexCount >= std::size_t((n - 1) * (n - 1)), true);
    // Interior tiles are unit squares centred on their points.
    for (std::size_t k = 0; k < r.Tiles.PointIds.size(); ++k)
    {
      const Point2& p = pts[r.Tiles.PointIds[k]];
      if (p.x > 0 && p.x < n - 1 && p.y > 0 && p.y < n - 1)
      {
        ASSERT_EQ(r.Tiles.Offsets[k + 1] - r.Tiles.Offsets[k], 4);
        EXPECT_EQ(r.Tiles.Areas[k], 1.0);
        for (std::int64_t v = r.Tiles.Offsets[k]; v < r.Tiles.Offsets[k + 1]; ++v)
        {
          EXPECT_EQ(std::fabs(r.Tiles.Vertices[v].x - p.x), 0.5);
          EXPECT_EQ(std::fabs(r.Tiles.Vertices[v].y - p.y), 0.5);
        }
      }
    }
  }
  expect_matches_brute_force(square_lattice(7), -0.5, 6.5, -0.5, 6.5);
  expect_matches_brute_force(square_lattice(7), -0.25, 6.75, -0.6, 6.1);
}

TEST(ThiessenSweep, RotatedLattices)
{
  // Exactly rotated (by the Pythagorean angle with cos 3/5, sin 4/5): still exactly degenerate.
  std::vector<Point2> exact;
  for (int j = 0; j < 8; ++j)
  {
    for (int i = 0; i < 8; ++i)
    {
      exact.push_back({ double(3 * i - 4 * j), double(4 * i + 3 * j) });
    }
  }
  expect_matches_brute_force(exact, -28.5, 21.5, 0.5, 49.5);
  const ThiessenSweepResult r =
    ComputeThiessenSweep(Window::Rectangle(-28.5, 21.5, 0.5, 49.5), exact);
  int diagonals = 0;
  for (std::size_t k = 0; k < r.Contiguities.Kinds.size(); ++k)
  {
    if (r.Contiguities.Kinds[k] == 1)
    {
      const Point2& a = exact[r.Contiguities.Pairs[2 * k]];
      const Point2& b = exact[r.Contiguities.Pairs[2 * k + 1]];
      EXPECT_EQ((a.x - b.x) * (a.x - b.x) + (a.y - b.y) * (a.y - b.y), 50.0); // a diagonal
      ++diagonals;
    }
  }
  EXPECT_GT(diagonals, 40);
  // Rotated in floating point by an arbitrary angle: nearly degenerate everywhere.
  for (const double angle : { 0.3, 0.785398163397, 1.1 })
  {
    std::vector<Point2> rotated;
    for (int j = 0; j < 9; ++j)
    {
      for (int i = 0; i < 9; ++i)
      {
        rotated.push_back({ 20 + std::cos(angle) * i - std::sin(angle) * j,
          20 + std::sin(angle) * i + std::cos(angle) * j });
      }
    }
    expect_matches_brute_force(rotated, 5, 35, 5, 35);
  }
}

TEST(ThiessenSweep, NearDegenerateSets)
{
  // A lattice with every coordinate nudged by 0 or 1 ulp, and points on a common circle.
  std::mt19937_64 rng(9);
  for (int trial = 0; trial < 4; ++trial)
  {
    std::vector<Point2> pts = nudged_square_lattice(7, rng);
    expect_matches_brute_force(pts, 0.1, 0.85, 0.12, 0.9);
  }
  std::vector<Point2> circle;
  for (const auto& [x, y] : RadiusFiveLatticePoints)
  {
    circle.push_back({ double(x), double(y) });
  }
  circle.push_back({ 0.0, 0.0 });
  circle.push_back({ 1.0, 0.5 });
  expect_matches_brute_force(circle, -6.5, 6.25, -6.1, 7.0);
}

TEST(ThiessenSweep, Offset2To30Sets)
{
  // Coordinates 2^30 + small multiples of 2^-20: degenerate and nearly degenerate configurations
  // where the floating-point circle test is meaningless.
  const double base = std::ldexp(1.0, 30);
  std::mt19937_64 rng(11);
  for (int trial = 0; trial < 4; ++trial)
  {
    std::vector<Point2> pts;
    for (int k = 0; k < 60; ++k)
    {
      pts.push_back(
        { base + std::ldexp(double(rng() % 16), -20), base + std::ldexp(double(rng() % 16), -20) });
    }
    expect_matches_brute_force(pts,
      base - std::ldexp(1.0, -21),
      base + std::ldexp(17.0, -20),
      base - std::ldexp(3.0, -22),
      base + std::ldexp(16.5, -20));
  }
}

TEST(ThiessenSweep, LatticeSubsetsMatchBruteForce)
{
  // Random subsets of a small lattice in random windows whose sides often pass through lattice
  // lines, Voronoi vertices or points' bisectors: ties everywhere, including on the border.
  std::mt19937_64 rng(41);
  for (int trial = 0; trial < 300; ++trial)
  {
    std::vector<Point2> pts;
    const int count = 3 + int(rng() % 25);
    for (int k = 0; k < count; ++k)
    {
      pts.push_back({ double(rng() % 7), double(rng() % 7) });
    }
    auto side = [&](double base) { return base + 0.25 * double(rng() % 4); };
    const double xmin = side(-1.0), xmax = side(6.25), ymin = side(-1.0), ymax = side(6.25);
    expect_matches_brute_force(pts, xmin, xmax, ymin, ymax);
    if (HasFailure())
    {
      ADD_FAILURE() << "trial " << trial;
      return;
    }
  }
}

TEST(ThiessenSweep, TinyAndHugeScales)
{
  // The same configuration (random points and a lattice) scaled by powers of ten: decisions stay
  // exact; with tiny scales the floating-point ranges give up and the scans widen.
  for (const double scale : { 1e-100, 1e-20, 1e20, 1e100 })
  {
    std::vector<Point2> pts = tessera_test::UniformPoints(40, 31);
    const std::vector<Point2> lattice = square_lattice(5, 0.2, 0.05, 0.05);
    pts.insert(pts.end(), lattice.begin(), lattice.end());
    for (Point2& p : pts)
    {
      p = { p.x * scale, p.y * scale };
    }
    expect_matches_brute_force(pts, 0.0, scale, 0.0, scale);
  }
}

TEST(ThiessenSweep, PowerOfTwoScalingIsExact)
{
  // Scaling everything by a power of two changes no decision and no rounding: the same pairs, and
  // vertices and areas scaled exactly (2000 points: also checks that tiny and huge windows keep
  // their search ranges).
  const std::vector<Point2> pts = gaussian_clusters(2000, 51);
  const ThiessenSweepResult r = ComputeThiessenSweep(Window::Rectangle(0, 1, 0, 1), pts);
  for (const int e : { -900, -300, 300, 900 })
  {
    std::vector<Point2> scaled = pts;
    for (Point2& p : scaled)
    {
      p = { std::ldexp(p.x, e), std::ldexp(p.y, e) };
    }
    const double one = std::ldexp(1.0, e);
    const ThiessenSweepResult s = ComputeThiessenSweep(Window::Rectangle(0, one, 0, one), scaled);
    EXPECT_EQ(GraphPairs(s.Contiguities), GraphPairs(r.Contiguities));
    ASSERT_EQ(s.Tiles.Vertices.size(), r.Tiles.Vertices.size());
    for (std::size_t k = 0; k < r.Tiles.Vertices.size(); ++k)
    {
      ASSERT_EQ(s.Tiles.Vertices[k].x, std::ldexp(r.Tiles.Vertices[k].x, e)) << e;
      ASSERT_EQ(s.Tiles.Vertices[k].y, std::ldexp(r.Tiles.Vertices[k].y, e)) << e;
    }
    if (e > -500)
    {
      for (std::size_t k = 0; k < r.Tiles.Areas.size(); ++k)
      {
        ASSERT_EQ(s.Tiles.Areas[k], std::ldexp(r.Tiles.Areas[k], 2 * e)) << e;
      }
    }
    // The search stayed local: about as many points consulted as at unit scale.
    double a = 0, b = 0;
    for (std::size_t k = 0; k < r.Counts.size(); ++k)
    {
      a += r.Counts[k].Consulted;
      b += s.Counts[k].Consulted;
    }
    EXPECT_EQ(a, b);
  }
}

// Points consulted per point, on average, in a sweep.
double consulted_per_point(const ThiessenSweepResult& r)
{
  double consulted = 0.0;
  for (const auto& counts : r.Counts)
  {
    consulted += counts.Consulted;
  }
  return r.Counts.empty() ? 0.0 : consulted / double(r.Counts.size());
}

TEST(ThiessenSweep, ClustersTinyBesideTheirWindowMatchBruteForceAndStayLocal)
{
  // A cluster some 1e-200 wide in a window of 1: the squared distance to the nearest centroid
  // underflowed, a wrong first neighbour was taken, and the sweep threw a logic_error (sets 31 and
  // 164 of this stream). Clusters 1e-80 wide were right but slow: the search ranges gave up below
  // 1e-70, and each search scanned every point.
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int t = 0; t <= 164; ++t)
  {
    std::vector<Point2> pts;
    for (int k = 0; k < 60; ++k)
    {
      const double x = u(rng) * 1e-200;
      pts.push_back({ x, u(rng) * 1e-200 });
    }
    if (t == 31 || t == 164 || t % 40 == 0)
    {
      SCOPED_TRACE("set " + std::to_string(t));
      expect_matches_brute_force(pts, -1.0, 1.0, -1.0, 1.0);
    }
  }
  // At 1e-80 the search circles' boxes are computed scaled to unit size and their disks used:
  // against the exact brute force; at 1e-55, against the Green-Sibson engine too (its window
  // decisions take coordinates above 2^-200 of the window's reach), on random points and on a
  // lattice, whose vertices are degenerate.
  for (const double width : { 1e-80, 1e-55 })
  {
    std::vector<Point2> pts = tessera_test::UniformPoints(60, 29);
    const std::vector<Point2> lattice = square_lattice(4, 0.25, 0.1, 0.1);
    pts.insert(pts.end(), lattice.begin(), lattice.end());
    for (Point2& p : pts)
    {
      p = { (p.x - 0.5) * width, (p.y - 0.5) * width };
    }
    SCOPED_TRACE(width);
    expect_matches_brute_force(pts, -1.0, 1.0, -1.0, 1.0);
    if (width > 1e-60)
    {
      expect_engines_agree(pts, Window::Rectangle(-1, 1, -1, 1));
    }
  }
  for (const double width : { 1e-80, 1e-200 })
  {
    std::vector<Point2> pts = tessera_test::UniformPoints(3000, 17);
    for (Point2& p : pts)
    {
      p = { (p.x - 0.5) * width, (p.y - 0.5) * width };
    }
    const ThiessenSweepResult r = ComputeThiessenSweep(Window::Rectangle(-1, 1, -1, 1), pts);
    check_structure(r, pts, 4.0, area_tolerance(Window::Rectangle(-1, 1, -1, 1)));
    // Local searches: a handful of points each, not a scan of the 3000 (it was 10,005 at 5000).
    EXPECT_LT(consulted_per_point(r), 300.0) << width;
  }
}

TEST(ThiessenSweep, RejectedPointsChangeNothingElse)
{
  // Points outside the window are not used, so they must not decide how the window is scaled: a
  // rejected 1e-320 beside a window of 1e100 kept it unscaled, and the search ranges gave up
  // (1500 times slower); a rejected 1e300 beside a window of 1e-200 made the sweep fail.
  for (const auto& [side, outside] : { std::pair<double, Point2>{ 1e100, { 1e-320, 3e100 } },
         std::pair<double, Point2>{ 1e-100, { 1e300, 0.0 } },
         std::pair<double, Point2>{ 1e-200, { 1e300, 0.0 } } })
  {
    std::vector<Point2> pts = tessera_test::UniformPoints(2000, 23);
    for (Point2& p : pts)
    {
      p = { (2.0 * p.x - 1.0) * side, (2.0 * p.y - 1.0) * side };
    }
    const Window window = Window::Rectangle(-side, side, -side, side);
    const ThiessenSweepResult alone = ComputeThiessenSweep(window, pts);
    pts.push_back(outside);
    const ThiessenSweepResult with = ComputeThiessenSweep(window, pts);
    EXPECT_EQ(with.RejectedIds, std::vector<std::int32_t>{ 2000 }) << side;
    EXPECT_EQ(GraphPairs(with.Contiguities), GraphPairs(alone.Contiguities)) << side;
    EXPECT_EQ(with.Tiles.Vertices, alone.Tiles.Vertices) << side;
    EXPECT_EQ(consulted_per_point(with), consulted_per_point(alone)) << side;
  }
  // A window reaching 9e307 is scaled down by 4 for the reflections: a rejected 5e-324 made that
  // inexact, and the sweep refused the window.
  const Window far = Window::Rectangle(-9e307, 9e307, -1.0, 1.0);
  std::vector<Point2> pts = { { 0.5, 0.3 }, { -0.5, 0.7 } };
  const ThiessenSweepResult alone = ComputeThiessenSweep(far, pts);
  pts.push_back({ 5e-324, 5.0 });
  const ThiessenSweepResult with = ComputeThiessenSweep(far, pts);
  EXPECT_EQ(with.RejectedIds, std::vector<std::int32_t>{ 2 });
  EXPECT_EQ(with.Tiles.Vertices, alone.Tiles.Vertices);
}

TEST(ThiessenSweep, RejectedAndDuplicatePoints)
{
  const std::vector<Point2> pts = { { 0.5, 0.5 },
    { 1.0, 0.5 },
    { 0.2, 0.3 },
    { 0.5, 0.5 },
    { -1, 2 },
    { 0.2, 0.3 },
    { 0.5, 0.0 },
    { 0.7, 0.9 },
    { 0.5, 0.5 } };
  const ThiessenSweepResult r = ComputeThiessenSweep(Window::Rectangle(0, 1, 0, 1), pts);
  EXPECT_EQ(r.RejectedIds, (std::vector<std::int32_t>{ 1, 4, 6 }));
  EXPECT_EQ(r.Duplicates,
    (std::vector<std::pair<std::int32_t, std::int32_t>>{ { 3, 0 }, { 5, 2 }, { 8, 0 } }));
  EXPECT_EQ(r.Tiles.PointIds, (std::vector<std::int32_t>{ 0, 2, 7 }));
  check_structure(r, pts, 1.0, 1e-12);
  expect_matches_brute_force(pts, 0, 1, 0, 1);
}

TEST(ThiessenSweep, Errors)
{
  const std::vector<Point2> pts = { { 0.5, 0.5 }, { 0.2, std::nan("") } };
  try
  {
    ComputeThiessenSweep(Window::Rectangle(0, 1, 0, 1), pts);
    ADD_FAILURE() << "no error for a NaN coordinate";
  }
  catch (const InputError& e)
  {
    EXPECT_NE(std::string(e.what()).find("point 1 has a NaN coordinate"), std::string::npos)
      << e.what();
  }
  const double infinity = std::numeric_limits<double>::infinity();
  for (const Point2& bad : { Point2{ infinity, 0.5 }, Point2{ 0.5, -infinity } })
  {
    try
    {
      ComputeThiessenSweep(Window::Rectangle(0, 1, 0, 1), { { 0.5, 0.5 }, { 0.1, 0.2 }, bad });
      ADD_FAILURE() << "no error for an infinite coordinate";
    }
    catch (const InputError& e)
    {
      EXPECT_NE(std::string(e.what()).find("point 2 has an infinite coordinate"), std::string::npos)
        << e.what();
    }
  }
  // A window of slanted sides: the message names the first.
  const Window triangle({ { -1, 0, 0 }, { 0, -1, 0 }, { 1, 1, -1 } });
  try
  {
    ComputeThiessenSweep(triangle, { { 0.2, 0.2 } });
    ADD_FAILURE() << "no error for a triangle";
  }
  catch (const InputError& e)
  {
    EXPECT_NE(
      std::string(e.what()).find("window constraint 2 gives a slanted side"), std::string::npos)
      << e.what();
  }
  // Windows whose points reflected across a side overflow: wider than the doubles reach (scaled
  // down exactly, a quarter, then swept: as a window 4 times smaller, the same tiles and
  // neighbours), or reaching 1.7e308 with a height of 1e-308, which cannot be scaled down exactly
  // (an InputError). Both threw a logic_error, no dummy point being found.
  const std::vector<Point2> pair{ { 0.5, 0.3 }, { -0.5, 0.7 } };
  const ThiessenSweepResult wide =
    ComputeThiessenSweep(Window::Rectangle(-9e307, 9e307, -1, 1), pair);
  const ThiessenSweepResult narrower =
    ComputeThiessenSweep(Window::Rectangle(-2e307, 2e307, -1, 1), pair);
  ASSERT_EQ(wide.Tiles.PointIds.size(), 2U);
  EXPECT_EQ(wide.Contiguities.Kinds.size(), 1U);
  EXPECT_EQ(wide.Tiles.NeighborCounts, narrower.Tiles.NeighborCounts);
  EXPECT_THROW(
    ComputeThiessenSweep(Window::Rectangle(0, 1.7e308, 0, 1e-308), { { 1e300, 5e-309 } }),
    InputError);
}

// A window whose side lies at no double (3x - 1 < 0: x < 1/3) is refused, naming the constraint:
// the sweep's border at the rounded corner rejected a point the window holds (x the double below
// 1/3: 3x - 1 < 0 exactly), where the Green-Sibson engine keeps it. A side at a double given by
// a coefficient other than 1 (2x - 1 < 0, scaled 3x - 1.5 < 0) is a rectangle like any other, and
// the engines agree on it, the point just inside its side included.
TEST(ThiessenSweep, SidesAtNoDoubleAreRefusedAndSidesAtDoublesAgree)
{
  const double third = 1.0 / 3.0;
  ASSERT_LT(mpq_class(3) * mpq_class(third) - 1, 0); // strictly inside x < 1/3
  const std::vector<Point2> pts = { { 0.1, 0.2 }, { 0.2, 0.7 }, { third, 0.5 } };
  const Window atThird({ { -1, 0, 0 }, { 0, -1, 0 }, { 0, 1, -1 }, { 3, 0, -1 } },
    ConstraintNames{ { "x > 0", "y > 0", "y < 1", "3x - 1 < 0" }, "" });
  ASSERT_TRUE(atThird.Contains(pts[2]));
  try
  {
    ComputeThiessenSweep(atThird, pts);
    ADD_FAILURE() << "no error for a side at x = 1/3";
  }
  catch (const InputError& e)
  {
    const std::string message = e.what();
    EXPECT_NE(message.find("3x - 1 < 0 puts one at x = 0.3333333333333333"), std::string::npos)
      << message;
  }
  const double half = std::nextafter(0.5, 0.0);
  for (const double a : { 2.0, 3.0, 6.0 })
  {
    const Window window({ { -1, 0, 0 }, { 0, -1, 0 }, { 0, 1, -1 }, { a, 0, -a / 2 } });
    const std::vector<Point2> near = { { 0.1, 0.2 }, { 0.2, 0.7 }, { half, 0.5 } };
    const ThiessenSweepResult r = ComputeThiessenSweep(window, near);
    EXPECT_TRUE(r.RejectedIds.empty()) << a;
    EXPECT_EQ(r.Tiles.PointIds.size(), 3u) << a;
    expect_engines_agree(near, window);
  }
  // Sides at subnormal coordinates are told exactly too (products there lose bits): x < c with c
  // the double 1e-320 is a side at a double, 1.1 x < 1.73e-322 (-c / 1.1 rounded) is not.
  EXPECT_NO_THROW(
    CheckSidesAreDoubles(Window({ { -1, 0, 0 }, { 0, -1, 0 }, { 0, 1, -1 }, { 1, 0, -1e-320 } })));
  EXPECT_THROW(CheckSidesAreDoubles(
                 Window({ { -1, 0, 0 }, { 0, -1, 0 }, { 0, 1, -1 }, { 1.1, 0, -1.73e-322 } })),
    InputError);
  // And at huge ones: 3x < 3 2^1000 lies at 2^1000, a double; 3x < 2^1000 at no double.
  EXPECT_NO_THROW(CheckSidesAreDoubles(
    Window({ { -1, 0, 0 }, { 0, -1, 0 }, { 0, 1, -1 }, { 3, 0, -3 * std::ldexp(1.0, 1000) } })));
  EXPECT_THROW(CheckSidesAreDoubles(Window(
                 { { -1, 0, 0 }, { 0, -1, 0 }, { 0, 1, -1 }, { 3, 0, -std::ldexp(1.0, 1000) } })),
    InputError);
}

TEST(ThiessenSweep, LargerSetsAreaAndSymmetry)
{
  const std::vector<Point2> pts = gaussian_clusters(20000, 3);
  const ThiessenSweepResult r = ComputeThiessenSweep(Window::Rectangle(0, 1, 0, 1), pts);
  check_structure(r, pts, 1.0, 1e-12);
  // Every side of a tile is either shared with one kind-0 neighbour (which counts it too) or lies
  // on the window boundary; kind-1 half-neighbours share only a vertex and add no side. So the sum
  // of sides = 2 * kind-0 pairs + tile edges on the boundary, counted here from the polygons: an
  // edge whose two ends lie on one side of the window rectangle (boundary crossings and corners
  // carry the side's coordinate exactly, and no bisector runs along a side).
  std::size_t sides = 0;
  for (const std::int32_t c : r.Tiles.NeighborCounts)
  {
    sides += std::size_t(c);
  }
  std::size_t kind0 = 0;
  for (const std::uint8_t k : r.Contiguities.Kinds)
  {
    kind0 += k == 0;
  }
  const TileSet& t = r.Tiles;
  std::size_t boundaryEdges = 0;
  double boundaryLength = 0.0;
  for (std::size_t k = 0; k < t.PointIds.size(); ++k)
  {
    const std::int64_t b = t.Offsets[k], e = t.Offsets[k + 1];
    for (std::int64_t v = b; v < e; ++v)
    {
      const Point2& u = t.Vertices[v];
      const Point2& w = t.Vertices[v + 1 < e ? v + 1 : b];
      if ((u.x == 0 && w.x == 0) || (u.x == 1 && w.x == 1) || (u.y == 0 && w.y == 0) ||
        (u.y == 1 && w.y == 1))
      {
        ++boundaryEdges;
        boundaryLength += std::hypot(w.x - u.x, w.y - u.y);
      }
    }
  }
  EXPECT_EQ(sides, 2 * kind0 + boundaryEdges);
  // The boundary edges found tile the window's perimeter exactly once.
  EXPECT_NEAR(boundaryLength, 4.0, 1e-12);
}

TEST(ThiessenSweep, EnginesAgree)
{
  expect_engines_agree(tessera_test::UniformPoints(5000, 21), Window::Rectangle(0, 1, 0, 1));
  expect_engines_agree(gaussian_clusters(5000, 22), Window::Rectangle(0, 1, 0, 1));
  expect_engines_agree(square_lattice(40), Window::Rectangle(-0.3, 39.6, -0.45, 39.7));
  expect_engines_agree(
    square_lattice(30, 0.25, 3.0, -2.0), Window::Rectangle(2.9, 10.3, -2.2, 5.4));
  std::vector<Point2> rotated;
  for (int j = 0; j < 40; ++j)
  {
    for (int i = 0; i < 40; ++i)
    {
      rotated.push_back({ double(3 * i - 4 * j), double(4 * i + 3 * j) });
    }
  }
  expect_engines_agree(rotated, Window::Rectangle(-160, 120, -1, 200));
  const double base = std::ldexp(1.0, 30);
  std::mt19937_64 rng(23);
  std::vector<Point2> offset;
  for (int k = 0; k < 3000; ++k)
  {
    offset.push_back(
      { base + std::ldexp(double(rng() % 64), -20), base + std::ldexp(double(rng() % 64), -20) });
  }
  expect_engines_agree(
    offset, Window::Rectangle(base - 1e-7, base + std::ldexp(64.0, -20), base - 2e-7, base + 7e-5));
}

namespace
{

// Inputs whose exact tiles have distinct vertices that round to one point, and other degenerate
// ones: each with its window.
struct Case
{
  std::string Name;
  std::vector<Point2> Points;
  Window Region;
};

Point2 nudged_up(Point2 p, int ulpsX, int ulpsY)
{
  for (int k = 0; k < ulpsX; ++k)
  {
    p.x = std::nextafter(p.x, 2.0 * std::fabs(p.x) + 1.0);
  }
  for (int k = 0; k < ulpsY; ++k)
  {
    p.y = std::nextafter(p.y, 2.0 * std::fabs(p.y) + 1.0);
  }
  return p;
}

// Two points almost mirrored in the diagonal through a corner of the unit square: their bisector
// crosses a side within rounding of the corner (the crossing is computed as the corner itself),
// beside the corner that one of their tiles keeps.
std::vector<Case> near_corner_cases(std::mt19937_64& rng)
{
  std::vector<Case> cases;
  std::uniform_real_distribution<double> u(0.01, 0.5);
  for (int trial = 0; trial < 200; ++trial)
  {
    const double a = u(rng), b = u(rng);
    std::vector<Point2> pts = { { a, b }, nudged_up({ b, a }, 1 + trial % 3, 0) };
    pts.push_back({ 0.4 + u(rng), 0.4 + u(rng) });
    const bool flipX = trial % 4 >= 2, flipY = trial % 2 == 1; // each corner in turn
    for (Point2& p : pts)
    {
      p = { flipX ? 1.0 - p.x : p.x, flipY ? 1.0 - p.y : p.y };
    }
    cases.push_back({ "near corner " + std::to_string(trial), pts, Window::Rectangle(0, 1, 0, 1) });
  }
  return cases;
}

// A lattice with coordinates nudged by an ulp: the two circumcentres of a nudged square are
// distinct and often round to one point.
std::vector<Case> nudged_lattice_cases(std::mt19937_64& rng)
{
  std::vector<Case> cases;
  for (int trial = 0; trial < 60; ++trial)
  {
    std::vector<Point2> pts = nudged_square_lattice(6, rng);
    cases.push_back(
      { "nudged lattice " + std::to_string(trial), pts, Window::Rectangle(0.1, 0.85, 0.12, 0.9) });
  }
  return cases;
}

// Small random sets, lattice subsets with sides through lattice lines and Voronoi vertices,
// co-circular points (exact and nudged), collinear points and points an ulp from the border.
std::vector<Case> degenerate_cases(std::mt19937_64& rng)
{
  std::vector<Case> cases;
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int trial = 0; trial < 300; ++trial)
  {
    std::vector<Point2> pts(2 + rng() % 13);
    for (Point2& p : pts)
    {
      p = { u(rng), u(rng) };
    }
    cases.push_back({ "random " + std::to_string(trial), pts, Window::Rectangle(0, 1, 0, 1) });
  }
  for (int trial = 0; trial < 200; ++trial)
  {
    std::vector<Point2> pts(3 + rng() % 20);
    for (Point2& p : pts)
    {
      p = { double(rng() % 7), double(rng() % 7) };
    }
    auto side = [&](double base) { return base + 0.25 * double(rng() % 4); };
    const double xmin = side(-1.0), xmax = side(6.25), ymin = side(-1.0), ymax = side(6.25);
    cases.push_back({ "lattice subset " + std::to_string(trial),
      pts,
      Window::Rectangle(xmin, xmax, ymin, ymax) });
  }
  for (int trial = 0; trial < 40; ++trial)
  {
    std::vector<Point2> pts = { { 0.0, 0.0 } };
    for (const auto& [x, y] : RadiusFiveLatticePoints)
    {
      pts.push_back(trial == 0
          ? Point2{ double(x), double(y) }
          : nudged_up({ double(x), double(y) }, int(rng() % 2), int(rng() % 2)));
    }
    cases.push_back(
      { "co-circular " + std::to_string(trial), pts, Window::Rectangle(-6.5, 6.25, -6.1, 7.0) });
  }
  std::vector<Point2> diagonal, nearSides;
  for (int k = 1; k < 10; ++k)
  {
    diagonal.push_back({ 0.1 * k, 0.1 * k });
    const double inside = std::nextafter(0.0, 1.0), below = std::nextafter(1.0, 0.0);
    nearSides.push_back({ inside, 0.1 * k });
    nearSides.push_back({ 0.1 * k, below });
    nearSides.push_back({ below, std::nextafter(0.1 * k, 1.0) });
  }
  cases.push_back({ "diagonal", diagonal, Window::Rectangle(0, 1, 0, 1) });
  cases.push_back({ "an ulp from the sides", nearSides, Window::Rectangle(0, 1, 0, 1) });
  return cases;
}

} // namespace

TEST(ThiessenSweep, NoTileRepeatsAVertex)
{
  // No polygon lists a vertex twice in a row (the last and the first included), with areas and
  // contiguities unchanged: summing to the window's area (check_structure, through
  // expect_engines_agree, which also checks the repeats), matching the Green-Sibson engine, and
  // each the area of the polygon written. Some tiles must list fewer vertices than they have
  // sides, or these inputs did not reach the case.
  std::mt19937_64 rng(61);
  std::vector<Case> cases = near_corner_cases(rng);
  for (const std::vector<Case>& more : { nudged_lattice_cases(rng), degenerate_cases(rng) })
  {
    cases.insert(cases.end(), more.begin(), more.end());
  }
  std::size_t merged = 0;
  for (const Case& c : cases)
  {
    SCOPED_TRACE(c.Name);
    const ThiessenSweepResult r = expect_engines_agree(c.Points, c.Region);
    const TileSet& t = r.Tiles;
    // The corners' vertex numbers (the mesh the filter writes): from 0 in first-use order, one
    // number for one place, and every tile's corners numbered apart (merged vertices are one).
    ASSERT_EQ(r.CornerVertexIds.size(), t.Vertices.size());
    std::vector<Point2> placeOf;
    for (std::size_t k = 0; k < t.Vertices.size(); ++k)
    {
      const std::size_t id = std::size_t(r.CornerVertexIds[k]);
      ASSERT_LE(id, placeOf.size()) << "corner " << k;
      if (id == placeOf.size())
      {
        placeOf.push_back(t.Vertices[k]);
      }
      EXPECT_TRUE(placeOf[id] == t.Vertices[k]) << "corner " << k << " of vertex " << id;
    }
    for (std::size_t k = 0; k < t.PointIds.size(); ++k)
    {
      std::set<std::int32_t> ids(
        r.CornerVertexIds.begin() + t.Offsets[k], r.CornerVertexIds.begin() + t.Offsets[k + 1]);
      EXPECT_EQ(std::int64_t(ids.size()), t.Offsets[k + 1] - t.Offsets[k]) << "tile " << k;
    }
    for (std::size_t k = 0; k < t.PointIds.size(); ++k)
    {
      const std::vector<Point2> polygon(
        t.Vertices.begin() + t.Offsets[k], t.Vertices.begin() + t.Offsets[k + 1]);
      EXPECT_NEAR(tessera_test::ShoelaceArea(polygon), t.Areas[k], area_tolerance(c.Region))
        << "tile of point " << t.PointIds[k];
      merged += std::int64_t(t.NeighborCounts[k]) > std::int64_t(polygon.size()) ? 1 : 0;
    }
    if (HasFailure())
    {
      return;
    }
  }
  EXPECT_GT(merged, 0u);
}

// Where a steep bisector crosses a side of the window, both engines give the crossing to an ulp or
// two of the exact point (exact rationals): two points 2e-9 apart across the side x = 1 and 2^-54
// along it. The Green-Sibson engine took the distance to the side from the rounded midpoint, and
// that rounding, times the bisector's slope (3.6e7), put its crossing 2^26 ulps off.
TEST(ThiessenSweep, SteepBisectorsCrossTheWindowWithinUlpsOfExact)
{
  const std::vector<Point2> points{ { 1.0 - 3e-9, 0.25 }, { 1.0 - 1e-9, 0.25 + 0x1p-54 } };
  const Window window = Window::Rectangle(0.0, 1.0, 0.0, 1.0);
  // The bisector's y on x = 1, exactly: |(1, y) - a|^2 = |(1, y) - b|^2.
  const mpq_class ax = points[0].x, ay = points[0].y, bx = points[1].x, by = points[1].y;
  const mpq_class exact =
    ((1 - bx) * (1 - bx) - (1 - ax) * (1 - ax) + by * by - ay * ay) / (2 * (by - ay));
  const double y = exact.get_d();
  const double ulp = std::nextafter(y, 1.0) - y;
  const TileSet engines[] = { ComputeTiles(DirichletTessellation(window, points)),
    ComputeThiessenSweep(window, points).Tiles };
  for (const TileSet& tiles : engines)
  {
    int found = 0;
    for (const Point2& v : tiles.Vertices)
    {
      if (v.x == 1.0 && v.y > 0.0 && v.y < 1.0)
      {
        ++found;
        EXPECT_LE(std::fabs(v.y - y), 2 * ulp) << "crossing at y = " << v.y << ", exactly " << y;
      }
    }
    EXPECT_EQ(found, 2); // one corner of each tile
  }
}

// The sweep reports the fraction of points swept every 64 points, rising, and stops with
// Cancelled when its callback says so; it stops at the next report, and the result of a run
// whose callback never says so is that of a run without one.
TEST(ThiessenSweep, ProgressRisesAndCanStopTheSweep)
{
  std::mt19937 random(6);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<Point2> points(1000);
  for (Point2& p : points)
  {
    p = { u(random), u(random) };
  }
  const Window window = Window::Rectangle(0, 1, 0, 1);
  std::vector<double> seen;
  const ThiessenSweepResult watched = ComputeThiessenSweep(window,
    points,
    [&](double fraction)
    {
      seen.push_back(fraction);
      return true;
    });
  EXPECT_EQ(seen.size(), 16U); // (points 0, 64, ..., 960)
  EXPECT_TRUE(std::is_sorted(seen.begin(), seen.end()));
  EXPECT_EQ(watched.Tiles.Areas, ComputeThiessenSweep(window, points).Tiles.Areas);
  int calls = 0;
  EXPECT_THROW(
    ComputeThiessenSweep(window, points, [&](double) { return ++calls < 3; }), Cancelled);
  EXPECT_EQ(calls, 3);
}
