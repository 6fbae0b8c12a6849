// Brassel-Reif sweep against the Green-Sibson engine: time against N (1e3 .. 1e6) for uniform,
// clustered (two Gaussian clusters, as in the paper's tests) and square-lattice points (all
// vertices degenerate: the exact predicates' slow tiers) in the unit square, and the
// paper's Fig. 11 counters per polygon: A (points consulted), B (passing the abscissa-range and
// half-plane tests), C (inside or on the circle), and searches per polygon.
//
// Both engines produce the same results here: tiles with areas and the contiguity graph
// (ComputeThiessenSweep against DirichletTessellation + ComputeTiles + ComputeContiguityGraph).
// Times are the best of a few runs, in CPU seconds (std::clock: less disturbed by other load on
// the machine than wall time) and wall seconds.
//
// Usage: bench_thiessen_sweep [max_n] [repeats]     (defaults 1000000, 3)
#include "dirichlet_tessellation.h"
#include "thiessen_sweep.h"
#include "tiles.h"
#include "window.h"

#include "test_support.h" // the lattice the tests use

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <functional>
#include <random>
#include <string>
#include <vector>

using namespace tessera;

namespace
{

enum class Input
{
  Uniform,
  Clustered,
  Lattice
};

std::vector<Point2> make_points(std::size_t n, Input input, std::uint64_t seed)
{
  if (input == Input::Lattice)
  {
    // A square lattice of about n points in the unit square.
    const int side = int(std::lround(std::sqrt(double(n))));
    return tessera_test::SquareLattice(side, double(side));
  }
  const bool clustered = input == Input::Clustered;
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::normal_distribution<double> g(0.0, 0.08);
  std::vector<Point2> points;
  points.reserve(n);
  while (points.size() < n)
  {
    if (!clustered)
    {
      points.push_back({ u(rng), u(rng) });
      continue;
    }
    const bool first = points.size() % 2 == 0;
    const Point2 p{ (first ? 0.3 : 0.7) + g(rng), (first ? 0.35 : 0.65) + g(rng) };
    if (p.x > 0.0 && p.x < 1.0 && p.y > 0.0 && p.y < 1.0)
    {
      points.push_back(p);
    }
  }
  return points;
}

struct Timing
{
  double cpu = 1e300;
  double wall = 1e300;
};

Timing best_of(int repeats, const std::function<void()>& run)
{
  Timing t;
  for (int r = 0; r < repeats; ++r)
  {
    const std::clock_t c0 = std::clock();
    const auto w0 = std::chrono::steady_clock::now();
    run();
    const auto w1 = std::chrono::steady_clock::now();
    const std::clock_t c1 = std::clock();
    t.cpu = std::min(t.cpu, double(c1 - c0) / CLOCKS_PER_SEC);
    t.wall = std::min(t.wall, std::chrono::duration<double>(w1 - w0).count());
  }
  return t;
}

} // namespace

int main(int argc, char** argv)
{
  if (argc > 1 && (std::string(argv[1]) == "--help" || std::string(argv[1]) == "-h"))
  {
    std::printf("usage: bench_thiessen_sweep [max_n] [repeats]   (defaults 1000000 and 3)\n"
                "Times the Brassel-Reif sweep against the Green-Sibson engine (tiles and the\n"
                "contiguity graph) on uniform, clustered and lattice points, 1e3 .. max_n, with\n"
                "the paper's Fig. 11 counters per polygon.\n");
    return 0;
  }
  const std::size_t maxN = argc > 1 ? std::strtoull(argv[1], nullptr, 10) : 1000000;
  const int repeats = argc > 2 ? std::atoi(argv[2]) : 3;
  const Window window = Window::Rectangle(0.0, 1.0, 0.0, 1.0);

  std::printf(
    "Brassel-Reif sweep (BR) vs Green-Sibson (GS): tiles + contiguity graph, best of %d\n",
    repeats);
  std::printf("%-10s %9s | %9s %9s | %9s %9s | %6s | %7s %7s %6s %6s | %s\n",
    "input",
    "N",
    "BR cpu s",
    "BR wall",
    "GS cpu s",
    "GS wall",
    "BR/GS",
    "A/poly",
    "B/poly",
    "C/poly",
    "srch",
    "agree");
  for (const Input input : { Input::Uniform, Input::Clustered, Input::Lattice })
  {
    for (std::size_t n = 1000; n <= maxN; n *= 10)
    {
      const std::vector<Point2> points = make_points(n, input, 42 + n);
      ThiessenSweepResult br;
      const Timing tb = best_of(repeats, [&] { br = ComputeThiessenSweep(window, points); });
      TileSet gsTiles;
      ContiguityGraph gsGraph;
      const Timing tg = best_of(repeats,
        [&]
        {
          DirichletTessellation gs(window, points);
          TessellationDual dual(gs);
          gsTiles = dual.Tiles();
          gsGraph = dual.Contiguities();
        });
      double a = 0, b = 0, c = 0, s = 0;
      for (const SweepSearchCounts& k : br.Counts)
      {
        a += k.Consulted;
        b += k.PassedTests;
        c += k.InCircle;
        s += k.Searches;
      }
      const double polygons = double(std::max<std::size_t>(1, br.Counts.size()));
      // Agreement: same contiguity pairs (as sets of (i, j, kind)) and areas within 1e-12.
      auto key = [](const ContiguityGraph& g)
      {
        std::vector<std::uint64_t> k(g.Kinds.size());
        for (std::size_t i = 0; i < k.size(); ++i)
        {
          k[i] = (std::uint64_t(std::uint32_t(g.Pairs[2 * i])) << 33) |
            (std::uint64_t(std::uint32_t(g.Pairs[2 * i + 1])) << 1) | g.Kinds[i];
        }
        std::sort(k.begin(), k.end());
        return k;
      };
      bool agree = key(br.Contiguities) == key(gsGraph);
      std::vector<double> gsArea(points.size(), -1.0);
      for (std::size_t i = 0; i < gsTiles.PointIds.size(); ++i)
      {
        gsArea[gsTiles.PointIds[i]] = gsTiles.Areas[i];
      }
      for (std::size_t i = 0; i < br.Tiles.PointIds.size(); ++i)
      {
        agree = agree && std::fabs(gsArea[br.Tiles.PointIds[i]] - br.Tiles.Areas[i]) <= 1e-12;
      }
      std::printf("%-10s %9zu | %9.3f %9.3f | %9.3f %9.3f | %6.2f | %7.2f %7.2f %6.2f %6.2f | %s\n",
        input == Input::Uniform ? "uniform" : (input == Input::Clustered ? "clustered" : "lattice"),
        points.size(),
        tb.cpu,
        tb.wall,
        tg.cpu,
        tg.wall,
        tb.cpu / tg.cpu,
        a / polygons,
        b / polygons,
        c / polygons,
        s / polygons,
        agree ? "yes" : "NO");
      std::fflush(stdout);
    }
  }
  return 0;
}
