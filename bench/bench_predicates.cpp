// Cost of the exact predicates per call: the out-of-line functions, the inline fast paths, and the
// exact tiers alone, on random (filter decides) and degenerate (exact tier decides) inputs.
// A plain program (std::chrono), so it builds with or without Google Benchmark.
#include "predicates.h"
#include "predicates_inline.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <functional>
#include <random>
#include <string>
#include <vector>

using tessera::Point2;

namespace
{

double seconds_per_call(const std::vector<Point2>& pts, const std::function<int(const Point2*)>& f)
{
  const std::size_t quads = pts.size() - 3;
  long long sink = 0;
  double best = 1e300;
  for (int rep = 0; rep < 3; ++rep)
  {
    const auto t0 = std::chrono::steady_clock::now();
    for (std::size_t i = 0; i < quads; ++i)
    {
      sink += f(&pts[i]);
    }
    const auto t1 = std::chrono::steady_clock::now();
    best = std::min(best, std::chrono::duration<double>(t1 - t0).count() / double(quads));
  }
  if (sink == 42)
  {
    std::puts("");
  }
  return best;
}

} // namespace

int main(int argc, char** argv)
{
  if (argc > 1 && (std::string(argv[1]) == "--help" || std::string(argv[1]) == "-h"))
  {
    std::printf("usage: bench_predicates\n"
                "Nanoseconds per call of the exact predicates (orient2d, incircle): the\n"
                "out-of-line functions, the inline fast paths and the exact tiers alone, on\n"
                "random and degenerate inputs.\n");
    return 0;
  }
  const std::size_t n = 2000000;
  std::mt19937_64 rng(1);
  std::uniform_real_distribution<double> u(0, 1);
  std::vector<Point2> random(n);
  for (Point2& p : random)
  {
    p = { u(rng), u(rng) };
  }
  // Lattice points offset by 2^30: consecutive quadruples are often collinear or co-circular.
  std::vector<Point2> lattice(n);
  std::uniform_int_distribution<int> cell(0, 3);
  for (Point2& p : lattice)
  {
    p = { std::ldexp(1.0, 30) + cell(rng), std::ldexp(1.0, 30) + cell(rng) };
  }
  // Random points near 2^30 with non-integer offsets: differences exact, filter often fails.
  std::vector<Point2> offset(n);
  for (Point2& p : offset)
  {
    p = { std::ldexp(1.0, 30) + u(rng) * 1e-6, std::ldexp(1.0, 30) + u(rng) * 1e-6 };
  }

  struct Case
  {
    const char* name;
    std::function<int(const Point2*)> f;
  };
  const std::vector<Case> cases = {
    { "orient2d", [](const Point2* p) { return tessera::orient2d(p[0], p[1], p[2]); } },
    { "orient2d_fast", [](const Point2* p) { return tessera::orient2d_fast(p[0], p[1], p[2]); } },
    { "orient2d_exact",
      [](const Point2* p) { return tessera::detail::orient2d_exact(p[0], p[1], p[2]); } },
    { "incircle", [](const Point2* p) { return tessera::incircle(p[0], p[1], p[2], p[3]); } },
    { "incircle_fast",
      [](const Point2* p) { return tessera::incircle_fast(p[0], p[1], p[2], p[3]); } },
    { "incircle_exact",
      [](const Point2* p) { return tessera::detail::incircle_exact(p[0], p[1], p[2], p[3]); } },
    { "compare_distance",
      [](const Point2* p) { return tessera::compare_distance(p[0], p[1], p[2]); } },
  };
  std::printf("%-18s %14s %14s %14s\n", "ns per call", "random", "lattice+2^30", "2^30+1e-6*u");
  for (const Case& c : cases)
  {
    std::printf("%-18s %14.1f %14.1f %14.1f\n",
      c.name,
      1e9 * seconds_per_call(random, c.f),
      1e9 * seconds_per_call(lattice, c.f),
      1e9 * seconds_per_call(offset, c.f));
  }
  return 0;
}
