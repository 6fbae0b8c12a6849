// Ridge grouping speed: the FFT field alone and the whole pipeline (field, ridges, contours,
// partition, RaG curves), against the number of points and the image size. The target
// is 1M points on a 1024 x 1024 image in at most 2 s. Run a Release build; the table printed by
// Google Benchmark has one row per (points, image size).
#include "radial_field.h"
#include "ridge_grouping.h"

#include "benchmark_main.h"

#include <benchmark/benchmark.h>

#include <cmath>
#include <random>
#include <vector>

namespace
{

using tessera::Point2;

// Noisy samples along three circles and a sine wave, spread over a 200 x 200 square.
std::vector<Point2> CurvePoints(int count)
{
  std::mt19937 rng(42);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::normal_distribution<double> noise(0.0, 1.0);
  const double pi = std::acos(-1.0);
  std::vector<Point2> points(static_cast<std::size_t>(count));
  for (int k = 0; k < count; ++k)
  {
    const double t = unit(rng);
    Point2 p;
    switch (k % 4)
    {
      case 0:
        p = { 50 + 30 * std::cos(2 * pi * t), 50 + 30 * std::sin(2 * pi * t) };
        break;
      case 1:
        p = { 150 + 35 * std::cos(2 * pi * t), 60 + 35 * std::sin(2 * pi * t) };
        break;
      case 2:
        p = { 100 + 60 * std::cos(2 * pi * t), 120 + 25 * std::sin(2 * pi * t) };
        break;
      default:
        p = { 200 * t, 185 + 10 * std::sin(12 * t) };
        break;
    }
    points[static_cast<std::size_t>(k)] = { p.x + noise(rng), p.y + noise(rng) };
  }
  return points;
}

void BM_FastField(benchmark::State& state)
{
  const int count = static_cast<int>(state.range(0));
  const int size = static_cast<int>(state.range(1));
  const std::vector<Point2> points = CurvePoints(count);
  tessera::RidgeGroupingSettings settings;
  settings.ImageSize = size;
  const tessera::RidgeGrouping grouping(settings);
  const tessera::PixelGrid grid = grouping.MakeGrid(points, size);
  std::vector<Point2> pixelPoints;
  for (const Point2& p : points)
  {
    pixelPoints.push_back(grid.ToPixelUnits(p));
  }
  for (auto _ : state)
  {
    benchmark::DoNotOptimize(tessera::FastField(pixelPoints,
      grid.Width,
      grid.Height,
      tessera::RadialBasis::InverseMultiquadric,
      settings.Width));
  }
  state.counters["pixels"] = static_cast<double>(grid.PixelCount());
}

void BM_RidgeGroupingTotal(benchmark::State& state)
{
  const int count = static_cast<int>(state.range(0));
  const int size = static_cast<int>(state.range(1));
  const std::vector<Point2> points = CurvePoints(count);
  tessera::RidgeGroupingSettings settings;
  settings.ImageSize = size;
  const tessera::RidgeGrouping grouping(settings);
  int contours = 0;
  for (auto _ : state)
  {
    const tessera::RidgeGroupingResult result = grouping.Run(points);
    contours = result.Contours.Count();
    benchmark::DoNotOptimize(result.GroupId.data());
  }
  state.counters["contours"] = contours;
}

void Sizes(benchmark::internal::Benchmark* b)
{
  for (int size : { 256, 512, 1024 })
  {
    for (int count : { 10000, 100000, 1000000 })
    {
      b->Args({ count, size });
    }
  }
}

} // namespace

BENCHMARK(BM_FastField)->Apply(Sizes)->Unit(benchmark::kMillisecond)->Iterations(3);
BENCHMARK(BM_RidgeGroupingTotal)->Apply(Sizes)->Unit(benchmark::kMillisecond)->Iterations(3);
int main(int argc, char** argv)
{
  return RunBenchmarks(argc,
    argv,
    "Ridge grouping speed: the FFT field alone and the whole pipeline (field, ridges, "
    "contours,\npartition, RaG curves) against the number of points and the image size "
    "(target: 1M points on\n1024 x 1024 in at most 2 s). Run a Release build. Google "
    "Benchmark's options follow.");
}
