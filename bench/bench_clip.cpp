// Catchment clipping speed. Usage: bench_clip [outline.geojson [vertex to drop ...]]
//
// The R maps outline of Colorado has a tiny self-intersection at its north-west corner (segment 19
// crosses segment 21), which the catchment rejects; `bench_clip colorado_boundary.geojson 21`
// drops vertex 21 to remove it.
//
// 1. Building the catchment (validation, grid) from the Colorado outline densified to ~2000
//    vertices, 100 times.
// 2. The Colorado workload: Thiessen tiles of 376 random gauges in the data's lon/lat box (computed
//    here by brute-force half-plane clipping), clipped 1236 times (one per month), areas only (from
//    the outline's crossings with the tiles) and with rings (clipping); then 100 times each over
//    the outline densified to 3 10^4 and 3 10^5 vertices.
// 3. 100k convex tiles (a jittered, triangulated grid) over the outline's box.
// Without a file, a synthetic outline of the same extent with jagged edges is used.

#include "clip.h"
#include "test_support.h" // the jittered tiling the clip tests use

#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

using tessera::Point2;

namespace
{

double Seconds(std::chrono::steady_clock::time_point since)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - since).count();
}

// The first ring of a GeoJSON Polygon: the numbers between "coordinates":[[[ and the next ]]].
std::vector<Point2> ReadOutline(const std::string& path)
{
  std::ifstream file(path);
  std::stringstream text;
  text << file.rdbuf();
  const std::string json = text.str();
  std::vector<Point2> ring;
  const std::size_t start = json.find("\"coordinates\"");
  if (start == std::string::npos)
  {
    return ring;
  }
  const std::size_t end = json.find("]]", start);
  std::vector<double> numbers;
  std::string token;
  for (std::size_t i = start + 13; i < end; ++i)
  {
    const char c = json[i];
    if ((c >= '0' && c <= '9') || c == '-' || c == '.' || c == 'e' || c == 'E' || c == '+')
    {
      token += c;
    }
    else if (!token.empty())
    {
      numbers.push_back(std::stod(token));
      token.clear();
    }
  }
  if (!token.empty())
  {
    numbers.push_back(std::stod(token));
  }
  for (std::size_t i = 0; i + 1 < numbers.size(); i += 2)
  {
    ring.push_back({ numbers[i], numbers[i + 1] });
  }
  return ring;
}

std::vector<Point2> SyntheticOutline()
{
  std::vector<Point2> ring;
  std::mt19937 random(7);
  std::uniform_real_distribution<double> wiggle(-0.02, 0.02);
  const Point2 corners[] = {
    { -109.05, 37.0 }, { -102.04, 37.0 }, { -102.04, 41.0 }, { -109.05, 41.0 }
  };
  for (int side = 0; side < 4; ++side)
  {
    const Point2 a = corners[side];
    const Point2 b = corners[(side + 1) % 4];
    for (int k = 0; k < 20; ++k)
    {
      const double t = k / 20.0;
      ring.push_back({ a.x + t * (b.x - a.x) + (k ? wiggle(random) : 0.0),
        a.y + t * (b.y - a.y) + (k ? wiggle(random) : 0.0) });
    }
  }
  return ring;
}

// Splits every edge so that the ring has about `target` vertices.
std::vector<Point2> Densify(const std::vector<Point2>& ring, std::size_t target)
{
  double perimeter = 0.0;
  for (std::size_t i = 0; i < ring.size(); ++i)
  {
    const Point2& a = ring[i];
    const Point2& b = ring[(i + 1) % ring.size()];
    perimeter += std::hypot(b.x - a.x, b.y - a.y);
  }
  const double step = perimeter / static_cast<double>(target);
  std::vector<Point2> dense;
  for (std::size_t i = 0; i < ring.size(); ++i)
  {
    const Point2& a = ring[i];
    const Point2& b = ring[(i + 1) % ring.size()];
    if (a == b)
    {
      continue;
    }
    const int pieces = std::max(1, static_cast<int>(std::hypot(b.x - a.x, b.y - a.y) / step));
    for (int k = 0; k < pieces; ++k)
    {
      const double t = static_cast<double>(k) / pieces;
      dense.push_back({ a.x + t * (b.x - a.x), a.y + t * (b.y - a.y) });
    }
  }
  return dense;
}

// Equirectangular metres about 39N: enough to give tiles realistic shapes for timing.
Point2 Project(const Point2& lonLat)
{
  const double metresPerDegree = 111320.0;
  return { lonLat.x * metresPerDegree * std::cos(39.0 * M_PI / 180.0), lonLat.y * metresPerDegree };
}

// Keeps the part of a convex polygon where (p - m) . d <= 0.
std::vector<Point2> CutHalfPlane(const std::vector<Point2>& polygon, Point2 m, Point2 d)
{
  std::vector<Point2> out;
  for (std::size_t i = 0; i < polygon.size(); ++i)
  {
    const Point2& p = polygon[i];
    const Point2& q = polygon[(i + 1) % polygon.size()];
    const double sp = (p.x - m.x) * d.x + (p.y - m.y) * d.y;
    const double sq = (q.x - m.x) * d.x + (q.y - m.y) * d.y;
    if (sp <= 0)
    {
      out.push_back(p);
    }
    if ((sp < 0 && sq > 0) || (sp > 0 && sq < 0))
    {
      const double t = sp / (sp - sq);
      out.push_back({ p.x + t * (q.x - p.x), p.y + t * (q.y - p.y) });
    }
  }
  return out;
}

void ThiessenTiles(const std::vector<Point2>& gauges,
  const std::vector<Point2>& window,
  std::vector<std::size_t>& offsets,
  std::vector<Point2>& vertices)
{
  offsets.assign(1, 0);
  vertices.clear();
  for (std::size_t i = 0; i < gauges.size(); ++i)
  {
    std::vector<Point2> tile = window;
    for (std::size_t j = 0; j < gauges.size() && tile.size() >= 3; ++j)
    {
      if (j != i)
      {
        const Point2 m{ 0.5 * (gauges[i].x + gauges[j].x), 0.5 * (gauges[i].y + gauges[j].y) };
        tile = CutHalfPlane(tile, m, { gauges[j].x - gauges[i].x, gauges[j].y - gauges[i].y });
      }
    }
    if (tile.size() >= 3)
    {
      vertices.insert(vertices.end(), tile.begin(), tile.end());
      offsets.push_back(vertices.size());
    }
  }
}

// The Colorado workload's tiles measured `months` times: areas only (from the outline's crossings
// with each tile's boundary where its box spans 64 grid cells or more, else by clipping; the count
// says how many) or with rings (clipping).
void TimeColorado(const tessera::Catchment& catchment,
  const std::vector<std::size_t>& tileOffsets,
  const std::vector<Point2>& tileVertices,
  int months,
  bool withRings)
{
  const std::size_t tiles = tileOffsets.size() - 1;
  tessera::Catchment::Workspace work;
  tessera::ClippedRings rings;
  const auto start = std::chrono::steady_clock::now();
  double sum = 0.0;
  for (int month = 0; month < months; ++month)
  {
    sum = 0.0;
    rings = tessera::ClippedRings();
    for (std::size_t t = 0; t < tiles; ++t)
    {
      sum += catchment.ClipInto(&tileVertices[tileOffsets[t]],
        tileOffsets[t + 1] - tileOffsets[t],
        t,
        work,
        withRings ? &rings : nullptr);
    }
  }
  const double seconds = Seconds(start);
  std::printf("Colorado, outline of %zu vertices: %zu tiles x %d months, %s: %.3f s "
              "(%.2f us/tile); sum/catchment - 1 = %.2e\n",
    catchment.Vertices().size(),
    tiles,
    months,
    withRings ? "areas + rings (clipping)" : "areas only",
    seconds,
    seconds / (static_cast<double>(tiles) * months) * 1e6,
    sum / catchment.Area() - 1.0);
  if (!withRings)
  {
    std::printf(
      "  (%zu of the %zu tiles measured by crossings)\n", work.AreasByCrossings / months, tiles);
  }
}

} // namespace

int main(int argc, char** argv)
{
  if (argc > 1 && (std::string(argv[1]) == "--help" || std::string(argv[1]) == "-h"))
  {
    std::printf("usage: bench_clip [outline.geojson [vertex to drop ...]]\n"
                "Times building a catchment and clipping Thiessen tiles by it (the Colorado\n"
                "workload: 376 tiles x 1236 months, areas only and with rings, then 100 months\n"
                "over the outline densified to 3 10^4 and 3 10^5 vertices) and 100k triangles;\n"
                "without a file, a synthetic outline. `bench_clip colorado_boundary.geojson 21`\n"
                "drops vertex 21, which makes the R maps outline self-intersect.\n");
    return 0;
  }
  std::vector<Point2> outline = argc > 1 ? ReadOutline(argv[1]) : std::vector<Point2>();
  const bool real = !outline.empty();
  for (int i = argc - 1; i >= 2; --i)
  {
    const long drop = std::stol(argv[i]);
    if (drop >= 0 && static_cast<std::size_t>(drop) < outline.size())
    {
      outline.erase(outline.begin() + drop);
    }
  }
  if (!real)
  {
    outline = SyntheticOutline();
  }
  std::vector<Point2> ring = Densify(outline, 2000);
  for (Point2& p : ring)
  {
    p = Project(p);
  }
  const std::vector<std::size_t> ringOffsets{ 0, ring.size() };
  std::printf(
    "outline: %s, %zu vertices after densifying\n", real ? argv[1] : "synthetic", ring.size());

  auto start = std::chrono::steady_clock::now();
  double area = 0.0;
  for (int i = 0; i < 100; ++i)
  {
    const tessera::Catchment catchment(ringOffsets, ring);
    area += catchment.Area();
  }
  std::printf("construct (validate + grid) x100: %.3f s (area %.6g km^2)\n",
    Seconds(start),
    area / 100 / 1e6);
  const tessera::Catchment catchment(ringOffsets, ring);

  // 376 gauges in the data's lon/lat box, tiles in a window padded around it.
  std::mt19937 random(42);
  std::uniform_real_distribution<double> lon(-109.5, -101.0);
  std::uniform_real_distribution<double> lat(36.5, 41.5);
  std::vector<Point2> gauges;
  for (int i = 0; i < 376; ++i)
  {
    gauges.push_back(Project({ lon(random), lat(random) }));
  }
  const Point2 low = Project({ -110.5, 35.5 });
  const Point2 high = Project({ -100.0, 42.5 });
  const std::vector<Point2> window{ low, { high.x, low.y }, high, { low.x, high.y } };
  std::vector<std::size_t> tileOffsets;
  std::vector<Point2> tileVertices;
  ThiessenTiles(gauges, window, tileOffsets, tileVertices);

  // The tiles over this outline, then over the outline densified further (areas only, from the
  // crossings; with rings, by clipping).
  for (const bool withRings : { false, true })
  {
    TimeColorado(catchment, tileOffsets, tileVertices, 1236, withRings);
  }
  for (const std::size_t detail : { std::size_t(30000), std::size_t(300000) })
  {
    std::vector<Point2> denser = Densify(outline, detail);
    for (Point2& p : denser)
    {
      p = Project(p);
    }
    const tessera::Catchment detailed({ 0, denser.size() }, denser);
    for (const bool withRings : { false, true })
    {
      TimeColorado(detailed, tileOffsets, tileVertices, 100, withRings);
    }
  }

  // 100k convex tiles: a jittered grid over the outline's box (padded), quads split in two.
  const tessera::Box2 box = catchment.Bounds();
  const int cells = 224; // 2 * 224^2 ~ 100k triangles
  const double dx = (box.XMax - box.XMin) * 1.1 / cells;
  const double dy = (box.YMax - box.YMin) * 1.1 / cells;
  const double x0 = box.XMin - 0.05 * (box.XMax - box.XMin);
  const double y0 = box.YMin - 0.05 * (box.YMax - box.YMin);
  tessera_test::JitteredTriangleTiling(x0, y0, dx, dy, cells, random, tileOffsets, tileVertices);
  for (const bool withRings : { false, true })
  {
    start = std::chrono::steady_clock::now();
    const tessera::ClippedTiles clipped = catchment.ClipAll(tileOffsets, tileVertices, withRings);
    const double seconds = Seconds(start);
    double sum = 0.0;
    for (double a : clipped.Areas)
    {
      sum += a;
    }
    std::printf("synthetic: %zu tiles, %s: %.3f s (%.3f us/tile); sum/catchment - 1 = %.2e\n",
      clipped.Areas.size(),
      withRings ? "areas + rings" : "areas only",
      seconds,
      seconds / static_cast<double>(clipped.Areas.size()) * 1e6,
      sum / catchment.Area() - 1.0);
  }
  return 0;
}
