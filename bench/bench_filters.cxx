// The tessellation filters measured through Update(), beside their peers in the same run:
// CGAL's Delaunay_triangulation_2 (exact predicates, inexact constructions, range insert),
// vtkDelaunay2D and vtkVoronoi2D (where they finish within a minute).
//
//   bench_filters [max_points] [repeats]   (defaults 1000000 and 5) prints four Markdown tables:
//   seconds and ratios (of medians), microseconds per point with each column's flatness over the
//   sizes, each filter's time over CGAL's run by run (median, range, and the runs that meet the
//   issue's target: 0.5 for the Delaunay filter, 1.0 for the tiles), and microseconds per point
//   again with every run in the same memory condition, back to back and after a pause
//
// Tessera's filters and CGAL run `repeats` times each (ten times as often at 10^4 points), in
// turn, on the same input, and the table shows the median run: this VM's single runs vary by
// 15-25%. vtkDelaunay2D and vtkVoronoi2D run once (they take seconds to minutes). From 10^6
// points on, a run's time also depends on how long ago the memory it maps afresh was freed: a
// guest that reports free memory to its host pays the host's faults on it (README, Benchmarks).
//
// A fourth table times each engine at each size in one memory condition at a time, so that the
// sizes compare like with like: back to back (a run straight after a run of the same engine, the
// first one unrecorded, so the memory the last run freed is taken again at once) and after a pause
// of PauseSeconds before each run (memory freed by the last run has been handed back to the host
// by then, where the guest reports free memory). In the first table the runs at 10^7 points take
// seconds each and come after other engines' runs: most of their fresh memory was freed long
// enough before to have gone to the host, while up to 10^6 points it mostly comes back from the
// heap, which keeps blocks below glibc's 32 MiB mmap threshold.
//
// vtkDirichletTessellation is timed twice: "tiles+areas" with ComputeContiguityGraph off (output
// 0 only: the tiles with their areas, which the tiles target names) and
// "tiles+areas+graph", the default, which also derives and writes the contiguity graph.
#include "vtkDelaunay2D.h"
#include "vtkDelaunayTriangulation.h"
#include "vtkDirichletTessellation.h"
#include "vtkDoubleArray.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkVoronoi2D.h"

#ifdef TESSERA_HAVE_CGAL
#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#endif

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <string>
#include <thread>
#include <vector>

namespace
{
using Clock = std::chrono::steady_clock;

double Seconds(Clock::time_point since)
{
  return std::chrono::duration<double>(Clock::now() - since).count();
}

vtkNew<vtkPolyData> UniformPoints(vtkIdType n, unsigned seed)
{
  std::mt19937_64 random(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(n);
  for (vtkIdType i = 0; i < n; ++i)
  {
    points->SetPoint(i, u(random), u(random), 0.0);
  }
  vtkNew<vtkPolyData> data;
  data->SetPoints(points);
  return data;
}

double Median(std::vector<double> seconds)
{
  std::sort(seconds.begin(), seconds.end());
  return seconds[seconds.size() / 2];
}

template<typename Filter>
double TimeFilter(vtkPolyData* input, vtkIdType& cells)
{
  vtkNew<Filter> filter;
  filter->SetInputData(input);
  const auto start = Clock::now();
  filter->Update();
  const double seconds = Seconds(start);
  cells = filter->GetOutput()->GetNumberOfCells();
  return seconds;
}

/// vtkDirichletTessellation with ComputeContiguityGraph off: the tiles with their areas only.
double TimeTilesOnly(vtkPolyData* input, vtkIdType& cells)
{
  vtkNew<vtkDirichletTessellation> filter;
  filter->SetInputData(input);
  filter->ComputeContiguityGraphOff();
  const auto start = Clock::now();
  filter->Update();
  const double seconds = Seconds(start);
  cells = filter->GetOutput()->GetNumberOfCells();
  return seconds;
}

#ifdef TESSERA_HAVE_CGAL
double TimeCgal(vtkPolyData* input, std::size_t& faces)
{
  using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
  using Triangulation = CGAL::Delaunay_triangulation_2<Kernel>;
  std::vector<Kernel::Point_2> points;
  points.reserve(input->GetNumberOfPoints());
  for (vtkIdType i = 0; i < input->GetNumberOfPoints(); ++i)
  {
    double p[3];
    input->GetPoint(i, p);
    points.emplace_back(p[0], p[1]);
  }
  const auto start = Clock::now();
  Triangulation triangulation(points.begin(), points.end()); // range insert: spatial sort inside
  const double seconds = Seconds(start);
  faces = triangulation.number_of_faces();
  return seconds;
}
#endif

std::string Cell(double seconds)
{
  char text[32];
  if (seconds < 0)
    return "      -";
  std::snprintf(text, sizeof text, "%7.4g", seconds); // 4 digits: 10^4 points take milliseconds
  return text;
}

/// One filter's time over CGAL's, run by run (each pair ran seconds apart, so the VM's swings in
/// speed, up to 2x within minutes, mostly cancel): the median, the range, and in how many runs the
/// ratio was at most `target`.
std::string PairedRatios(const std::vector<double>& ours,
  const std::vector<double>& cgal,
  double target)
{
  if (cgal.size() != ours.size() || cgal.empty())
  {
    return "-";
  }
  std::vector<double> ratios;
  for (std::size_t k = 0; k < ours.size(); ++k)
  {
    ratios.push_back(ours[k] / cgal[k]);
  }
  const std::size_t met = static_cast<std::size_t>(
    std::count_if(ratios.begin(), ratios.end(), [&](double r) { return r <= target; }));
  const auto [low, high] = std::minmax_element(ratios.begin(), ratios.end());
  char text[96];
  std::snprintf(text,
    sizeof text,
    "%.3g (%.3g-%.3g), %zu of %zu at most %.2g",
    Median(ratios),
    *low,
    *high,
    met,
    ratios.size(),
    target);
  return text;
}

/// A per-point table's rows after its header: one per size (us: per column, per size), then each
/// column's flatness over the sizes (largest over smallest per-point time; the target is
/// at most 1.3 from 10^4 to 10^7).
void PrintPerPointRows(const std::vector<vtkIdType>& sizes,
  const std::vector<std::vector<double>>& us)
{
  for (std::size_t k = 0; k < sizes.size(); ++k)
  {
    std::printf("| %lld |", static_cast<long long>(sizes[k]));
    for (const std::vector<double>& column : us)
    {
      std::printf(" %s |", Cell(column[k]).c_str());
    }
    std::printf("\n");
  }
  std::printf("| largest / smallest |");
  for (const std::vector<double>& column : us)
  {
    const auto [low, high] = std::minmax_element(column.begin(), column.end());
    std::printf(" %s |", Cell(*low > 0 ? *high / *low : -1.0).c_str());
  }
  std::printf("\n");
}

/// The medians again in microseconds per point, with each column's flatness over the sizes.
void PrintPerPoint(const std::vector<vtkIdType>& sizes, const std::vector<std::vector<double>>& us)
{
  std::printf("\n| microseconds per point | Tessera Delaunay | Tessera tiles+areas | "
              "Tessera tiles+areas+graph | CGAL DT2 |\n|---|---|---|---|---|\n");
  PrintPerPointRows(sizes, us);
}

/// The memory conditions of the fourth table (see the header).
enum class Condition
{
  BackToBack,
  AfterPause
};

/// How long the pause before each run is in the AfterPause condition: free page reporting hands
/// freed memory to the host about two seconds after it was freed.
constexpr int PauseSeconds = 3;

/// Median seconds of `runs` runs of `timeOnce` (one engine on one input) in `condition`.
template<typename TimeOnce>
double MedianInCondition(Condition condition, int runs, TimeOnce timeOnce)
{
  std::vector<double> seconds;
  if (condition == Condition::BackToBack)
  {
    timeOnce(); // unrecorded: it takes its memory after whatever ran before
  }
  for (int run = 0; run < runs; ++run)
  {
    if (condition == Condition::AfterPause)
    {
      std::this_thread::sleep_for(std::chrono::seconds(PauseSeconds));
    }
    seconds.push_back(timeOnce());
  }
  return Median(seconds);
}

/// The fourth table: microseconds per point of the Delaunay filter, the tiles and CGAL at each size
/// in each memory condition, with each column's flatness (largest over smallest) over the sizes.
void PrintPerPointByCondition(vtkIdType maxPoints, int repeats)
{
  const char* const names[2] = { "back to back", "after a pause" };
  std::vector<vtkIdType> sizes;
  std::vector<std::vector<double>> us(6); // [condition * 3 + engine]
  for (vtkIdType n = 10000; n <= maxPoints; n *= 10)
  {
    auto input = UniformPoints(n, 7);
    sizes.push_back(n);
    vtkIdType cells = 0;
    for (int c = 0; c < 2; ++c)
    {
      const Condition condition = c == 0 ? Condition::BackToBack : Condition::AfterPause;
      // As in the first table, ten times the runs at 10^4 points back to back; three after pauses.
      const int runs =
        condition == Condition::AfterPause ? 3 : repeats * int(std::max<vtkIdType>(1, 100000 / n));
      const double seconds[3] = {
        MedianInCondition(
          condition, runs, [&]() { return TimeFilter<vtkDelaunayTriangulation>(input, cells); }),
        MedianInCondition(condition, runs, [&]() { return TimeTilesOnly(input, cells); }),
#ifdef TESSERA_HAVE_CGAL
        MedianInCondition(condition,
          runs,
          [&]()
          {
            std::size_t faces = 0;
            return TimeCgal(input, faces);
          }),
#else
        -1.0,
#endif
      };
      for (int e = 0; e < 3; ++e)
      {
        us[3 * c + e].push_back(seconds[e] > 0 ? 1e6 * seconds[e] / double(n) : -1.0);
      }
    }
  }
  std::printf("\n| microseconds per point | Delaunay, %s | tiles+areas, %s | CGAL DT2, %s | "
              "Delaunay, %s | tiles+areas, %s | CGAL DT2, %s |\n|---|---|---|---|---|---|---|\n",
    names[0],
    names[0],
    names[0],
    names[1],
    names[1],
    names[1]);
  PrintPerPointRows(sizes, us);
}

} // namespace

int main(int argc, char** argv)
{
  if (argc > 1 && (std::string(argv[1]) == "--help" || std::string(argv[1]) == "-h"))
  {
    std::printf(
      "usage: bench_filters [max_points] [repeats]   (defaults 1000000 and 5)\n"
      "Times vtkDelaunayTriangulation and vtkDirichletTessellation (without and with its\n"
      "contiguity graph) through Update()\n"
      "beside CGAL, vtkDelaunay2D and vtkVoronoi2D on 1e4 .. max_points uniform points,\n"
      "then per point with every run back to back, and with a 3 s pause before each run.\n");
    return 0;
  }
  const vtkIdType maxPoints = argc > 1 ? std::atoll(argv[1]) : 1000000;
  const int repeats = argc > 2 ? std::max(1, std::atoi(argv[2])) : 5;
  std::printf("| points | Tessera Delaunay | Tessera tiles+areas | Tessera tiles+areas+graph | "
              "CGAL DT2 | vtkDelaunay2D | vtkVoronoi2D | Delaunay / CGAL | tiles / CGAL | "
              "tiles+graph / CGAL | vtkVoronoi2D / tiles+graph |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|---|---|\n");
  // Microseconds per point of each column of the second table, per size, for its flatness row.
  std::vector<vtkIdType> sizes;
  std::vector<std::vector<double>> perPoint(4);
  std::vector<std::string> pairedRows; // the third table's rows
  for (vtkIdType n = 10000; n <= maxPoints; n *= 10)
  {
    auto input = UniformPoints(n, 7);
    vtkIdType triangles = 0, tiles = 0, tilesOnly = 0, peerCells = 0;
    std::vector<double> delaunayRuns, tilesOnlyRuns, tessellationRuns, cgalRuns;
    // Ten times the runs at 10^4 points (milliseconds each): their medians move less.
    const int runs = repeats * int(std::max<vtkIdType>(1, 100000 / n));
    for (int run = 0; run < runs; ++run)
    {
      delaunayRuns.push_back(TimeFilter<vtkDelaunayTriangulation>(input, triangles));
      tilesOnlyRuns.push_back(TimeTilesOnly(input, tilesOnly));
      tessellationRuns.push_back(TimeFilter<vtkDirichletTessellation>(input, tiles));
      if (tilesOnly != tiles)
        std::fprintf(stderr,
          "warning: %lld tiles without the graph, %lld with it\n",
          static_cast<long long>(tilesOnly),
          static_cast<long long>(tiles));
#ifdef TESSERA_HAVE_CGAL
      std::size_t cgalFaces = 0;
      cgalRuns.push_back(TimeCgal(input, cgalFaces));
      if (static_cast<vtkIdType>(cgalFaces) != triangles)
        std::fprintf(stderr,
          "warning: %lld points: CGAL has %zu faces, Tessera %lld\n",
          static_cast<long long>(n),
          cgalFaces,
          static_cast<long long>(triangles));
#endif
    }
    const double delaunay = Median(delaunayRuns);
    const double tilesAlone = Median(tilesOnlyRuns);
    const double tessellation = Median(tessellationRuns);
    const double cgal = cgalRuns.empty() ? -1.0 : Median(cgalRuns);
    pairedRows.push_back("| " + std::to_string(n) + " | " +
      PairedRatios(delaunayRuns, cgalRuns, 0.5) + " | " +
      PairedRatios(tilesOnlyRuns, cgalRuns, 1.0) + " | " +
      PairedRatios(tessellationRuns, cgalRuns, 1.0) + " |");
    // vtkDelaunay2D takes ~28 s at 100k points here: run it up to 100k only.
    const double delaunay2d = n <= 100000 ? TimeFilter<vtkDelaunay2D>(input, peerCells) : -1.0;
    // vtkVoronoi2D takes ~22 s at 10^6 points and ~250 s at 10^7: run it up to 10^6 only.
    const double voronoi2d = n <= 1000000 ? TimeFilter<vtkVoronoi2D>(input, peerCells) : -1.0;
    auto ratio = [](double a, double b) { return b > 0 && a > 0 ? a / b : -1.0; };
    std::printf("| %lld | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s |\n",
      static_cast<long long>(n),
      Cell(delaunay).c_str(),
      Cell(tilesAlone).c_str(),
      Cell(tessellation).c_str(),
      Cell(cgal).c_str(),
      Cell(delaunay2d).c_str(),
      Cell(voronoi2d).c_str(),
      Cell(ratio(delaunay, cgal)).c_str(),
      Cell(ratio(tilesAlone, cgal)).c_str(),
      Cell(ratio(tessellation, cgal)).c_str(),
      Cell(ratio(voronoi2d, tessellation)).c_str());
    std::fflush(stdout);
    sizes.push_back(n);
    const double columns[4] = { delaunay, tilesAlone, tessellation, cgal };
    for (int c = 0; c < 4; ++c)
    {
      perPoint[c].push_back(columns[c] > 0 ? 1e6 * columns[c] / double(n) : -1.0);
    }
  }
  PrintPerPoint(sizes, perPoint);
  std::printf("\n| points | Delaunay / CGAL, run by run | tiles / CGAL, run by run | "
              "tiles+graph / CGAL, run by run |\n|---|---|---|---|\n");
  for (const std::string& row : pairedRows)
  {
    std::printf("%s\n", row.c_str());
  }
  std::fflush(stdout);
  PrintPerPointByCondition(maxPoints, repeats);
  return 0;
}
