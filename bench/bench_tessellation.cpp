// Benchmark of the Green-Sibson engine (programs, never timed tests): Delaunay construction,
// tiles with areas, and bytes of structure per point, for 1e4 .. 1e7 uniform points and a
// 1000 x 1000 lattice (every face degenerate); the construction also for 10^6 points on a parabola
// and on five lines (Shapes). When built with TESSERA_HAVE_CGAL, CGAL's
// Delaunay_triangulation_2 (Exact_predicates_inexact_constructions_kernel, range insert) runs in
// the same program on the same points, as the peer.
//
// The stages are also timed separately (FacesAfterBuild, DualOnly, TilesOnly,
// ContiguitiesOnly), BuildAndTiles times the build plus the tiles with areas, and
// BuildTilesAndGraph the build plus tiles and contiguity graph (what vtkDirichletTessellation
// asks of the core).
//
// Streamed inserts 10^5 points one by one (Insert; CGAL's insert(p) without a hint), sorted by x
// or in random order.
//
// Nearest-point queries (NearestPoint one by one, the batch NearestPoints, CGAL's hinted
// nearest_vertex) are timed per query (ns/q) for 10^4 queries among 10^4 .. 10^6 points.
//
// Columns: ns/pt = wall time per input point; B/pt = bytes held by the structure per point
// (coordinates included); each benchmark's counters are printed in Google Benchmark's table.

#include "dirichlet_tessellation.h"
#include "tiles.h"

#include "test_support.h" // the point sets the tests use

#include "benchmark_main.h"

#include <benchmark/benchmark.h>

#include <cmath>
#include <random>
#include <vector>

#ifdef TESSERA_HAVE_CGAL
#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/spatial_sort.h>
#endif

namespace
{

using tessera::Point2;

const std::vector<Point2>& UniformPoints(std::size_t n)
{
  static std::vector<Point2> points;
  if (points.size() != n)
  {
    points = tessera_test::UniformPoints(n, 12345);
  }
  return points;
}

const std::vector<Point2>& LatticePoints()
{
  static const std::vector<Point2> points = tessera_test::SquareLattice(1000);
  return points;
}

// Arguments below 0 are the points of other shapes, 10^6 of each (Input).
constexpr std::int64_t Parabola = -1;
constexpr std::int64_t FiveLines = -2;

const std::vector<Point2>& ParabolaPoints()
{
  // (a seed whose failed walks once took the two-region build 4 times CGAL's whole build)
  static const std::vector<Point2> points = tessera_test::PointsOnAParabola(1000000, 3);
  return points;
}

const std::vector<Point2>& FiveLinesPoints()
{
  static const std::vector<Point2> points = tessera_test::PointsOnFiveLines(1000000, 1);
  return points;
}

// The window of the uniform points in [0, 1)^2.
tessera::Window UnitSquareWindow()
{
  return tessera::Window::Rectangle(-0.1, 1.1, -0.1, 1.1);
}

tessera::Window WindowFor(std::int64_t arg)
{
  return arg == 0 ? tessera::Window::Rectangle(0.0, 1000.0, 0.0, 1000.0)
    : arg < 0     ? tessera::Window::Rectangle(-0.5, 1.5, -0.5, 1.5) // (the lines reach -0.2)
                  : UnitSquareWindow();
}

void SetPerPoint(benchmark::State& state, std::size_t n)
{
  // A rate of (points / 1e9) per second, inverted: nanoseconds per point.
  state.counters["ns/pt"] = benchmark::Counter(double(state.iterations()) * double(n) * 1e-9,
    benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
  state.SetItemsProcessed(std::int64_t(state.iterations()) * std::int64_t(n));
}

// Argument 0 = the lattice, Parabola or FiveLines those shapes, otherwise the number of uniform
// points.
const std::vector<Point2>& Input(std::int64_t arg)
{
  return arg == 0      ? LatticePoints()
    : arg == Parabola  ? ParabolaPoints()
    : arg == FiveLines ? FiveLinesPoints()
                       : UniformPoints(std::size_t(arg));
}

void TesseraDelaunay(benchmark::State& state)
{
  const std::vector<Point2>& points = Input(state.range(0));
  std::size_t bytes = 0;
  for (auto _ : state)
  {
    tessera::DirichletTessellation t(WindowFor(state.range(0)), points);
    benchmark::DoNotOptimize(t.Origin().data());
    bytes = t.StructureBytes();
  }
  SetPerPoint(state, points.size());
  state.counters["B/pt"] = double(bytes) / double(points.size());
}

void TesseraDelaunayFaces(benchmark::State& state)
{
  const std::vector<Point2>& points = Input(state.range(0));
  for (auto _ : state)
  {
    tessera::DirichletTessellation t(WindowFor(state.range(0)), points);
    const tessera::DelaunayFaces faces = tessera::ComputeDelaunayFaces(t, false);
    benchmark::DoNotOptimize(faces.PointIds.data());
  }
  SetPerPoint(state, points.size());
}

void TesseraTilesAndAreas(benchmark::State& state)
{
  const std::vector<Point2>& points = Input(state.range(0));
  const tessera::DirichletTessellation t(WindowFor(state.range(0)), points);
  for (auto _ : state)
  {
    const tessera::TileSet tiles = tessera::ComputeTiles(t);
    benchmark::DoNotOptimize(tiles.Areas.data());
  }
  SetPerPoint(state, points.size());
}

// The stages separately, on a tessellation built once: ComputeDelaunayFaces after the build, the
// TessellationDual constructor, and Tiles() / Contiguities() on a dual built once.
void TesseraFacesAfterBuild(benchmark::State& state)
{
  const std::vector<Point2>& points = Input(state.range(0));
  const tessera::DirichletTessellation t(WindowFor(state.range(0)), points);
  for (auto _ : state)
  {
    const tessera::DelaunayFaces faces = tessera::ComputeDelaunayFaces(t, false);
    benchmark::DoNotOptimize(faces.PointIds.data());
  }
  SetPerPoint(state, points.size());
}

void TesseraDualOnly(benchmark::State& state)
{
  const std::vector<Point2>& points = Input(state.range(0));
  const tessera::DirichletTessellation t(WindowFor(state.range(0)), points);
  for (auto _ : state)
  {
    const tessera::TessellationDual dual(t);
    benchmark::DoNotOptimize(dual.DegenerateFaceCount());
  }
  SetPerPoint(state, points.size());
}

void TesseraTilesOnly(benchmark::State& state)
{
  const std::vector<Point2>& points = Input(state.range(0));
  const tessera::DirichletTessellation t(WindowFor(state.range(0)), points);
  const tessera::TessellationDual dual(t);
  for (auto _ : state)
  {
    const tessera::TileSet tiles = dual.Tiles();
    benchmark::DoNotOptimize(tiles.Areas.data());
  }
  SetPerPoint(state, points.size());
}

void TesseraContiguitiesOnly(benchmark::State& state)
{
  const std::vector<Point2>& points = Input(state.range(0));
  const tessera::DirichletTessellation t(WindowFor(state.range(0)), points);
  const tessera::TessellationDual dual(t);
  for (auto _ : state)
  {
    const tessera::ContiguityGraph graph = dual.Contiguities();
    benchmark::DoNotOptimize(graph.Pairs.data());
  }
  SetPerPoint(state, points.size());
}

// Issue 3's target (b): the build, the dual and the tiles with areas, from the points.
void TesseraBuildAndTiles(benchmark::State& state)
{
  const std::vector<Point2>& points = Input(state.range(0));
  for (auto _ : state)
  {
    const tessera::DirichletTessellation t(WindowFor(state.range(0)), points);
    const tessera::TileSet tiles = tessera::ComputeTiles(t);
    benchmark::DoNotOptimize(tiles.Areas.data());
  }
  SetPerPoint(state, points.size());
}

// What vtkDirichletTessellation asks of the core: the build, then the tiles with areas (as a
// mesh with shared corners) and the contiguity graph in one pass over the rings.
void TesseraBuildTilesAndGraph(benchmark::State& state)
{
  const std::vector<Point2>& points = Input(state.range(0));
  for (auto _ : state)
  {
    const tessera::DirichletTessellation t(WindowFor(state.range(0)), points);
    tessera::TessellationDual dual(t);
    const tessera::TileMeshAndGraph both = dual.TileMeshAndContiguities();
    benchmark::DoNotOptimize(both.Tiles.Areas.data());
    benchmark::DoNotOptimize(both.Graph.Pairs.data());
  }
  SetPerPoint(state, points.size());
}

// Nearest points of 10^4 uniform queries among n uniform points (the tessellation built outside
// the timing): one NearestPoint call per query in random order (each walk from the last triangle
// made), the batch NearestPoints (queries along a Hilbert curve, each descent from the point found
// before), and the peer, CGAL's nearest_vertex with the queries spatially sorted, each hinted by
// the face of the vertex found before. ns/q: wall time per query.
const std::vector<Point2>& NearestQueries()
{
  static const std::vector<Point2> queries = tessera_test::UniformPoints(10000, 777);
  return queries;
}

void SetPerQuery(benchmark::State& state, std::size_t queries)
{
  state.counters["ns/q"] = benchmark::Counter(double(state.iterations()) * double(queries) * 1e-9,
    benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

void TesseraNearestPointEach(benchmark::State& state)
{
  const tessera::DirichletTessellation t(UnitSquareWindow(), Input(state.range(0)));
  for (auto _ : state)
  {
    std::int64_t sum = 0;
    for (const Point2& q : NearestQueries())
    {
      sum += t.NearestPoint(q);
    }
    benchmark::DoNotOptimize(sum);
  }
  SetPerQuery(state, NearestQueries().size());
}

void TesseraNearestPoints(benchmark::State& state)
{
  const tessera::DirichletTessellation t(UnitSquareWindow(), Input(state.range(0)));
  for (auto _ : state)
  {
    const std::vector<std::int32_t> nearest = t.NearestPoints(NearestQueries());
    benchmark::DoNotOptimize(nearest.data());
  }
  SetPerQuery(state, NearestQueries().size());
}

// Points inserted one by one, as a stream: 10^5 uniform points sorted by x (a table's rows; each
// point beyond all before it, placed at the hull beside the very last, far from it in y), or in
// the random order they were drawn in.
constexpr std::int64_t SortedByX = 1;
constexpr std::int64_t RandomOrder = 2;

const std::vector<Point2>& StreamedPoints(std::int64_t order)
{
  static const std::vector<Point2> drawn = tessera_test::UniformPoints(100000, 4242);
  static const std::vector<Point2> sorted = tessera_test::SortedByX(drawn);
  return order == SortedByX ? sorted : drawn;
}

void TesseraStreamed(benchmark::State& state)
{
  const std::vector<Point2>& points = StreamedPoints(state.range(0));
  for (auto _ : state)
  {
    tessera::DirichletTessellation t(UnitSquareWindow());
    for (const Point2& p : points)
    {
      t.Insert(p);
    }
    benchmark::DoNotOptimize(t.Origin().data());
  }
  SetPerPoint(state, points.size());
}

#ifdef TESSERA_HAVE_CGAL
void CgalStreamed(benchmark::State& state)
{
  using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
  const std::vector<Point2>& points = StreamedPoints(state.range(0));
  for (auto _ : state)
  {
    CGAL::Delaunay_triangulation_2<Kernel> dt;
    for (const Point2& p : points)
    {
      dt.insert(Kernel::Point_2(p.x, p.y));
    }
    benchmark::DoNotOptimize(dt.number_of_faces());
  }
  SetPerPoint(state, points.size());
}

void CgalDelaunay(benchmark::State& state)
{
  using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
  const std::vector<Point2>& points = Input(state.range(0));
  std::vector<Kernel::Point_2> input;
  input.reserve(points.size());
  for (const Point2& p : points)
  {
    input.emplace_back(p.x, p.y);
  }
  for (auto _ : state)
  {
    CGAL::Delaunay_triangulation_2<Kernel> dt;
    dt.insert(input.begin(), input.end());
    benchmark::DoNotOptimize(dt.number_of_faces());
  }
  SetPerPoint(state, points.size());
}
void CgalNearestVertex(benchmark::State& state)
{
  using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
  using Delaunay = CGAL::Delaunay_triangulation_2<Kernel>;
  std::vector<Kernel::Point_2> input;
  for (const Point2& p : Input(state.range(0)))
  {
    input.emplace_back(p.x, p.y);
  }
  Delaunay dt;
  dt.insert(input.begin(), input.end());
  for (auto _ : state)
  {
    std::vector<Kernel::Point_2> queries;
    for (const Point2& q : NearestQueries())
    {
      queries.emplace_back(q.x, q.y);
    }
    CGAL::spatial_sort(queries.begin(), queries.end());
    Delaunay::Face_handle hint;
    double sum = 0.0;
    for (const Kernel::Point_2& q : queries)
    {
      const Delaunay::Vertex_handle v = dt.nearest_vertex(q, hint);
      hint = v->face();
      sum += v->point().x();
    }
    benchmark::DoNotOptimize(sum);
  }
  SetPerQuery(state, NearestQueries().size());
}
#endif

// Removing a vertex of degree d: the centre of d points on an ellipse, joined to all of them (the
// time of the removal alone; the build is paused out). Its link is cut into Delaunay ears, each
// checked against the whole link: O(d^2) incircle tests when the scan resumes where it last cut.
void TesseraRemoveHighDegreeVertex(benchmark::State& state)
{
  const std::size_t d = std::size_t(state.range(0));
  std::vector<Point2> points;
  for (std::size_t k = 0; k < d; ++k)
  {
    const double a = 2.0 * M_PI * double(k) / double(d);
    points.push_back({ 0.5 + 0.4 * std::cos(a), 0.5 + 0.3 * std::sin(a) });
  }
  points.push_back({ 0.5, 0.5 });
  for (auto _ : state)
  {
    state.PauseTiming();
    tessera::DirichletTessellation t(UnitSquareWindow(), points);
    state.ResumeTiming();
    t.Remove(std::int32_t(d));
    benchmark::DoNotOptimize(t.AcceptedCount());
  }
}

// Argument 0 is the 1000 x 1000 lattice.
void Sizes(benchmark::internal::Benchmark* b)
{
  b->Unit(benchmark::kMillisecond)->UseRealTime()->Arg(10000)->Arg(100000)->Arg(1000000)->Arg(0);
}

// 10^6 points on a parabola (in convex position but for rounding) and on five lines: the regions
// of the two-region build defer most of their first tries and give the rest up
// (two_region_build.cpp: GivesUp).
void Shapes(benchmark::internal::Benchmark* b)
{
  b->Unit(benchmark::kMillisecond)->UseRealTime()->Arg(Parabola)->Arg(FiveLines);
}

void StreamOrders(benchmark::internal::Benchmark* b)
{
  b->Unit(benchmark::kMillisecond)->UseRealTime()->Arg(SortedByX)->Arg(RandomOrder);
}

void UniformSizes(benchmark::internal::Benchmark* b)
{
  b->Unit(benchmark::kMillisecond)->UseRealTime()->Arg(10000)->Arg(100000)->Arg(1000000);
}

void Large(benchmark::internal::Benchmark* b)
{
  b->Unit(benchmark::kMillisecond)->UseRealTime()->Arg(10000000)->Iterations(1);
}

} // namespace

BENCHMARK(TesseraDelaunay)->Apply(Sizes);
BENCHMARK(TesseraDelaunay)->Apply(Large);
BENCHMARK(TesseraDelaunay)->Apply(Shapes);
BENCHMARK(TesseraDelaunayFaces)->Apply(Sizes);
BENCHMARK(TesseraDelaunayFaces)->Apply(Large);
BENCHMARK(TesseraTilesAndAreas)->Apply(Sizes);
BENCHMARK(TesseraTilesAndAreas)->Apply(Large);
BENCHMARK(TesseraFacesAfterBuild)->Apply(Sizes);
BENCHMARK(TesseraDualOnly)->Apply(Sizes);
BENCHMARK(TesseraTilesOnly)->Apply(Sizes);
BENCHMARK(TesseraContiguitiesOnly)->Apply(Sizes);
BENCHMARK(TesseraBuildAndTiles)->Apply(Sizes);
BENCHMARK(TesseraBuildAndTiles)->Apply(Large);
BENCHMARK(TesseraBuildTilesAndGraph)->Apply(Sizes);
BENCHMARK(TesseraBuildTilesAndGraph)->Apply(Large);
BENCHMARK(TesseraRemoveHighDegreeVertex)
  ->Unit(benchmark::kMillisecond)
  ->UseRealTime()
  ->Arg(1000)
  ->Arg(2000)
  ->Arg(4000)
  ->Arg(8000);
BENCHMARK(TesseraStreamed)->Apply(StreamOrders);
BENCHMARK(TesseraNearestPointEach)->Apply(UniformSizes);
BENCHMARK(TesseraNearestPoints)->Apply(UniformSizes);
#ifdef TESSERA_HAVE_CGAL
BENCHMARK(CgalDelaunay)->Apply(Sizes);
BENCHMARK(CgalDelaunay)->Apply(Large);
BENCHMARK(CgalDelaunay)->Apply(Shapes);
BENCHMARK(CgalStreamed)->Apply(StreamOrders);
BENCHMARK(CgalNearestVertex)->Apply(UniformSizes);
#endif

int main(int argc, char** argv)
{
  return RunBenchmarks(argc,
    argv,
    "The Green-Sibson core against CGAL's Delaunay_triangulation_2 in one run: "
    "Delaunay\nconstruction, tiles with areas, contiguity graph and bytes per point, for 1e4 "
    ".. 1e7 uniform\npoints and a 1000 x 1000 lattice, the construction also for 10^6 points on "
    "a parabola (/-1)\nand on five lines (/-2), and Streamed: 10^5 points inserted one by one, "
    "sorted by x (/1)\nor in random order (/2) (ns/pt: wall time per point; B/pt: bytes "
    "of structure).\nRun a Release build. Google Benchmark's options follow "
    "(--benchmark_filter=Cgal|Tessera ...).");
}
