#pragma once
// Small helpers shared by the core test programs (not part of the library).

#include "clip.h"
#include "dirichlet_tessellation.h"
#include "errors.h"
#include "predicates.h"
#include "tiles.h"
#include "window.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <map>
#include <random>
#include <string>
#include <utility>
#include <vector>

namespace tessera_test
{

// Sets TESSERA_THREADS (parallel_chunks.h) for its lifetime, then puts back what was there.
class ThreadLimitOverride
{
public:
  explicit ThreadLimitOverride(int threads)
  {
    if (const char* old = std::getenv("TESSERA_THREADS"))
    {
      this->Old = old;
      this->HadOld = true;
    }
    setenv("TESSERA_THREADS", std::to_string(threads).c_str(), 1);
  }
  ~ThreadLimitOverride()
  {
    if (this->HadOld)
    {
      setenv("TESSERA_THREADS", this->Old.c_str(), 1);
    }
    else
    {
      unsetenv("TESSERA_THREADS");
    }
  }

private:
  std::string Old;
  bool HadOld = false;
};

/// The message of the InputError that function throws, or "" when it throws none.
template<typename Function>
std::string ErrorOf(Function&& function)
{
  try
  {
    function();
  }
  catch (const tessera::InputError& error)
  {
    return error.what();
  }
  return "";
}

/// The axis-aligned rectangle from (x0, y0) to (x1, y1), anticlockwise when x0 < x1 and y0 < y1.
inline std::vector<tessera::Point2> Rectangle(double x0, double y0, double x1, double y1)
{
  return { { x0, y0 }, { x1, y0 }, { x1, y1 }, { x0, y1 } };
}

/// Rings of a region as the core takes them: flat vertices, ring r from Offsets[r] to
/// Offsets[r + 1].
struct Rings
{
  std::vector<std::size_t> Offsets{ 0 };
  std::vector<tessera::Point2> Vertices;
  Rings() = default;
  explicit Rings(const std::vector<std::vector<tessera::Point2>>& rings)
  {
    for (const auto& ring : rings)
    {
      this->Add(ring);
    }
  }
  void Add(const std::vector<tessera::Point2>& ring)
  {
    this->Vertices.insert(this->Vertices.end(), ring.begin(), ring.end());
    this->Offsets.push_back(this->Vertices.size());
  }
  std::vector<tessera::Point2> Ring(std::size_t r) const
  {
    return { this->Vertices.begin() + static_cast<std::ptrdiff_t>(this->Offsets[r]),
      this->Vertices.begin() + static_cast<std::ptrdiff_t>(this->Offsets[r + 1]) };
  }
  std::size_t Count() const { return this->Offsets.size() - 1; }
};

/// The catchment of the given rings.
inline tessera::Catchment MakeCatchment(const std::vector<std::vector<tessera::Point2>>& rings)
{
  const Rings flat(rings);
  return tessera::Catchment(flat.Offsets, flat.Vertices);
}

/// Ids of the accepted points of a tessellation, ascending.
inline std::vector<std::int32_t> AcceptedIds(const tessera::DirichletTessellation& t)
{
  std::vector<std::int32_t> ids;
  for (std::int32_t id = 0; id < std::int32_t(t.PointCount()); ++id)
  {
    if (t.Status(id) == tessera::PointStatus::Accepted)
    {
      ids.push_back(id);
    }
  }
  return ids;
}

/// Delaunay faces by point ids (mapped by idMap where one is given), each from its smallest id,
/// sorted: the same for any insertion order.
inline std::vector<std::vector<std::int32_t>> SortedFaces(const tessera::DelaunayFaces& faces,
  const std::vector<std::int32_t>& idMap = {})
{
  std::vector<std::vector<std::int32_t>> sorted;
  for (std::size_t f = 0; f + 1 < faces.Offsets.size(); ++f)
  {
    std::vector<std::int32_t> face;
    for (std::int64_t k = faces.Offsets[f]; k < faces.Offsets[f + 1]; ++k)
    {
      face.push_back(idMap.empty() ? faces.PointIds[k] : idMap[faces.PointIds[k]]);
    }
    std::rotate(face.begin(), std::min_element(face.begin(), face.end()), face.end());
    sorted.push_back(face);
  }
  std::sort(sorted.begin(), sorted.end());
  return sorted;
}

/// The side x side square lattice ((i + 0.5) / divisor, (j + 0.5) / divisor), row by row: every
/// Delaunay face degenerate (4 co-circular points).
inline std::vector<tessera::Point2> SquareLattice(int side, double divisor = 1.0)
{
  std::vector<tessera::Point2> points;
  points.reserve(std::size_t(side) * std::size_t(side));
  for (int j = 0; j < side; ++j)
  {
    for (int i = 0; i < side; ++i)
    {
      points.push_back({ (i + 0.5) / divisor, (j + 0.5) / divisor });
    }
  }
  return points;
}

/// n points uniform in [lo, hi)^2, reproducible from the seed.
inline std::vector<tessera::Point2> UniformPoints(std::size_t n,
  std::uint64_t seed,
  double lo = 0.0,
  double hi = 1.0)
{
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(lo, hi);
  std::vector<tessera::Point2> points(n);
  for (tessera::Point2& p : points)
  {
    p = { u(rng), u(rng) };
  }
  return points;
}

/// The points sorted by x (a table's rows, streamed in that order).
inline std::vector<tessera::Point2> SortedByX(std::vector<tessera::Point2> points)
{
  std::sort(points.begin(),
    points.end(),
    [](const tessera::Point2& a, const tessera::Point2& b) { return a.x < b.x; });
  return points;
}

/// n points on the parabola y = (2x - 1)^2 with x uniform in [0, 1), reproducible from the seed:
/// in convex position but for rounding (of 10^6, 34 fall inside the hull).
inline std::vector<tessera::Point2> PointsOnAParabola(std::size_t n, std::uint64_t seed)
{
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<tessera::Point2> points(n);
  for (tessera::Point2& p : points)
  {
    const double x = u(rng);
    p = { x, (2.0 * x - 1.0) * (2.0 * x - 1.0) };
  }
  return points;
}

/// n points on five lines of slopes with no exact binary form (0.1, 0.7, ...), taken in turn, x
/// uniform in [0, 1), reproducible from the seed; y stays within [-0.2, 1.1].
inline std::vector<tessera::Point2> PointsOnFiveLines(std::size_t n, std::uint64_t seed)
{
  static const double slopes[5] = { 0.1, 0.7, -0.3, 1.3, 0.01 };
  static const double atZero[5] = { 0.3, 0.1, 0.7, -0.2, 0.45 };
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<tessera::Point2> points(n);
  for (std::size_t k = 0; k < n; ++k)
  {
    const double x = u(rng);
    points[k] = { x, slopes[k % 5] * x + atZero[k % 5] };
  }
  return points;
}

/// A slanted hexagonal window around (0.5, 0.5): a window that is not a rectangle.
inline tessera::Window Hexagon()
{
  std::vector<tessera::HalfPlane> constraints;
  for (int k = 0; k < 6; ++k)
  {
    const double angle = 1.0471975511965976 * k + 0.2;
    const double a = std::cos(angle), b = std::sin(angle);
    constraints.push_back({ a, b, -(0.8 + 0.5 * a + 0.5 * b) });
  }
  return tessera::Window(constraints);
}

/// Contiguity pairs (i < j) and their kinds, as a map for comparisons.
using PairKinds = std::map<std::pair<std::int32_t, std::int32_t>, int>;

inline PairKinds GraphPairs(const tessera::ContiguityGraph& graph)
{
  PairKinds pairs;
  for (std::size_t k = 0; k < graph.Kinds.size(); ++k)
  {
    pairs[{ graph.Pairs[2 * k], graph.Pairs[2 * k + 1] }] = graph.Kinds[k];
  }
  return pairs;
}

/// Plain shoelace area (positive anticlockwise), relative to the first vertex: the tests' own
/// computation, independent of the core's compensated sum.
inline double ShoelaceArea(const std::vector<tessera::Point2>& polygon)
{
  double sum = 0.0;
  for (std::size_t k = 0; k < polygon.size(); ++k)
  {
    const tessera::Point2& a = polygon[k];
    const tessera::Point2& b = polygon[(k + 1) % polygon.size()];
    sum +=
      (a.x - polygon[0].x) * (b.y - polygon[0].y) - (a.y - polygon[0].y) * (b.x - polygon[0].x);
  }
  return 0.5 * sum;
}

/// A jittered (cells x cells) grid from (x0, y0) with steps dx, dy, each quad split into two
/// anticlockwise triangles: a tiling of convex tiles (flat offsets into vertices). Border nodes
/// are not jittered, so the tiles exactly cover the rectangle.
inline void JitteredTriangleTiling(double x0,
  double y0,
  double dx,
  double dy,
  int cells,
  std::mt19937& random,
  std::vector<std::size_t>& offsets,
  std::vector<tessera::Point2>& vertices)
{
  std::uniform_real_distribution<double> jitter(-0.1, 0.1);
  std::vector<tessera::Point2> nodes;
  for (int j = 0; j <= cells; ++j)
  {
    for (int i = 0; i <= cells; ++i)
    {
      const bool border = i == 0 || j == 0 || i == cells || j == cells;
      nodes.push_back({ x0 + (i + (border ? 0.0 : jitter(random))) * dx,
        y0 + (j + (border ? 0.0 : jitter(random))) * dy });
    }
  }
  offsets.assign(1, 0);
  vertices.clear();
  const auto node = [&](int i, int j)
  { return nodes[static_cast<std::size_t>(i + j * (cells + 1))]; };
  for (int j = 0; j < cells; ++j)
  {
    for (int i = 0; i < cells; ++i)
    {
      vertices.insert(vertices.end(), { node(i, j), node(i + 1, j), node(i + 1, j + 1) });
      offsets.push_back(vertices.size());
      vertices.insert(vertices.end(), { node(i, j), node(i + 1, j + 1), node(i, j + 1) });
      offsets.push_back(vertices.size());
    }
  }
}

/// Crossing-number membership of p in ring r of rings (p is never on a boundary where used).
inline bool InRing(const tessera::ClippedRings& rings, std::size_t r, const tessera::Point2& p)
{
  bool inside = false;
  const std::size_t begin = rings.RingOffsets[r], end = rings.RingOffsets[r + 1];
  for (std::size_t i = begin, j = end - 1; i < end; j = i++)
  {
    const tessera::Point2& a = rings.Vertices[i];
    const tessera::Point2& b = rings.Vertices[j];
    if ((a.y > p.y) != (b.y > p.y) && p.x < a.x + (p.y - a.y) / (b.y - a.y) * (b.x - a.x))
    {
      inside = !inside;
    }
  }
  return inside;
}

/// A convex tile: 3 to 8 points at random angles on the circle of radius about centre,
/// anticlockwise.
inline std::vector<tessera::Point2> RandomInscribedTile(std::mt19937& random,
  const tessera::Point2& centre,
  double radius)
{
  std::uniform_real_distribution<double> angle(0.0, 2 * M_PI);
  std::vector<double> angles(3 + random() % 6);
  for (double& a : angles)
  {
    a = angle(random);
  }
  std::sort(angles.begin(), angles.end());
  angles.erase(std::unique(angles.begin(), angles.end()), angles.end());
  std::vector<tessera::Point2> tile;
  for (const double a : angles)
  {
    tile.push_back({ centre.x + radius * std::cos(a), centre.y + radius * std::sin(a) });
  }
  return tile;
}

/// A comb (a 20 x 10 rectangle with bays from the top) with two holes, an island in one of them,
/// and a triangular lake: a catchment of every kind of boundary a tile can meet.
inline tessera::Catchment Comb()
{
  return MakeCatchment({ { { 0, 0 },
                           { 20, 0 },
                           { 20, 10 },
                           { 16, 10 },
                           { 16, 4 },
                           { 14, 4 },
                           { 14, 10 },
                           { 9, 10 },
                           { 8.5, 5 },
                           { 8, 10 },
                           { 0, 10 } },
    Rectangle(2, 2, 6, 7),
    Rectangle(3, 3, 4, 4),
    { { 10, 1 }, { 12, 1.5 }, { 11, 3 } } });
}

/// Points of an n x n grid over box, offset by irrational fractions of a cell so that none lies
/// on an edge of the rings tested against it.
inline std::vector<tessera::Point2> SampleGrid(const tessera::Box2& box, int n)
{
  std::vector<tessera::Point2> samples;
  for (int i = 0; i < n; ++i)
  {
    for (int j = 0; j < n; ++j)
    {
      samples.push_back({ box.XMin + (i + 0.5 * std::sqrt(2.0) - 0.2) / n * (box.XMax - box.XMin),
        box.YMin + (j + 0.5 * std::sqrt(3.0) - 0.4) / n * (box.YMax - box.YMin) });
    }
  }
  return samples;
}

/// The number of rings of rings that hold p (InRing).
inline int RingsHolding(const tessera::ClippedRings& rings, const tessera::Point2& p)
{
  int holding = 0;
  for (std::size_t r = 0; r + 1 < rings.RingOffsets.size(); ++r)
  {
    holding += InRing(rings, r, p);
  }
  return holding;
}

/// A catchment of about one degree in lon/lat, as flat rings: the unit square round a pentagonal
/// lake (withLake), or the square with a bay from the top and a square hole in one lobe.
inline Rings LakeOrBay(bool withLake)
{
  const std::vector<tessera::Point2> square{ { 0, 0 }, { 1, 0 }, { 1, 1 }, { 0, 1 } };
  const std::vector<tessera::Point2> lake{
    { 0.35, 0.35 }, { 0.35, 0.65 }, { 0.5, 0.7 }, { 0.65, 0.65 }, { 0.65, 0.35 }
  };
  const std::vector<tessera::Point2> bay{
    { 0, 0 }, { 1, 0 }, { 1, 1 }, { 0.6, 1 }, { 0.6, 0.3 }, { 0.4, 0.3 }, { 0.4, 1 }, { 0, 1 }
  };
  const std::vector<tessera::Point2> hole{ { 0.1, 0.1 }, { 0.1, 0.2 }, { 0.2, 0.2 }, { 0.2, 0.1 } };
  return Rings({ withLake ? square : bay, withLake ? lake : hole });
}

/// Ring r of rings, as its own vector.
inline std::vector<tessera::Point2> RingOf(const tessera::ClippedRings& rings, std::size_t r)
{
  return { rings.Vertices.begin() + static_cast<std::ptrdiff_t>(rings.RingOffsets[r]),
    rings.Vertices.begin() + static_cast<std::ptrdiff_t>(rings.RingOffsets[r + 1]) };
}

/// Whether p, on the line through a and b, lies on the closed segment a-b (comparisons: exact).
inline bool WithinSegment(const tessera::Point2& a,
  const tessera::Point2& b,
  const tessera::Point2& p)
{
  return std::min(a.x, b.x) <= p.x && p.x <= std::max(a.x, b.x) && std::min(a.y, b.y) <= p.y &&
    p.y <= std::max(a.y, b.y);
}

/// Whether the closed segments a-b and c-d have a point in common, exactly (orient2d's signs).
inline bool SegmentsMeet(const tessera::Point2& a,
  const tessera::Point2& b,
  const tessera::Point2& c,
  const tessera::Point2& d)
{
  const int abc = tessera::orient2d(a, b, c), abd = tessera::orient2d(a, b, d);
  const int cda = tessera::orient2d(c, d, a), cdb = tessera::orient2d(c, d, b);
  if (abc * abd < 0 && cda * cdb < 0)
  {
    return true;
  }
  return (abc == 0 && WithinSegment(a, b, c)) || (abd == 0 && WithinSegment(a, b, d)) ||
    (cda == 0 && WithinSegment(c, d, a)) || (cdb == 0 && WithinSegment(c, d, b));
}

/// What is wrong with a ring as a simple polygon, or "" for a simple one: at least 3 distinct
/// vertices (repeats of the vertex before, the last's of the first included, are dropped first),
/// edges that meet only where consecutive ones share their vertex, no spike back along an edge.
/// Every pair of edges is tested, exactly (orient2d, which test_predicates checks against GMP, and
/// comparisons of coordinates), in O(n^2): an oracle apart from ValidateRings
/// (polygon_validation.h), with which tests had checked the library's own rings.
inline std::string RingDefect(const std::vector<tessera::Point2>& ring)
{
  std::vector<tessera::Point2> q;
  for (std::size_t k = 0; k < ring.size(); ++k)
  {
    if (ring.size() == 1 || ring[k] != ring[(k + ring.size() - 1) % ring.size()])
    {
      q.push_back(ring[k]);
    }
  }
  const std::size_t n = q.size();
  if (n < 3)
  {
    return std::to_string(n) + " distinct vertices";
  }
  // Going on from b along the line it came: no spike (c back towards a) where a, b, c are on one.
  const auto onwards = [](double a, double b, double c) { return (a < b) == (b < c); };
  for (std::size_t i = 0; i < n; ++i)
  {
    const tessera::Point2 &a = q[i], &b = q[(i + 1) % n], &c = q[(i + 2) % n];
    if (tessera::orient2d(a, b, c) == 0 &&
      !(a.x != b.x ? onwards(a.x, b.x, c.x) && c.x != b.x : onwards(a.y, b.y, c.y) && c.y != b.y))
    {
      return "a spike at vertex " + std::to_string((i + 1) % n);
    }
    for (std::size_t j = i + 2; j < n; ++j)
    {
      if (!(i == 0 && j == n - 1) && SegmentsMeet(a, b, q[j], q[(j + 1) % n]))
      {
        return "edges " + std::to_string(i) + " and " + std::to_string(j) + " meet";
      }
    }
  }
  return std::string();
}

} // namespace tessera_test
