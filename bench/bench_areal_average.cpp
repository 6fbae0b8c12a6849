// Thiessen areal averages: the Colorado record (1236 months) and a synthetic stream of 100k
// gauges with 1% toggling per step, incremental updates against rebuilds in the same run.
// A rebuild reuses nothing from the previous step: it builds the tessellation of the reporting
// gauges, derives every tile and clips every tile. An update removes and inserts the gauges that
// changed, then re-derives and re-clips only the tiles whose areas may have changed (the
// neighbours of the removed and inserted gauges), except those whose boxes show them clear of
// the catchment.
//
// The peer, where CGAL is found: the synthetic stream's topology alone in CGAL's
// Delaunay_triangulation_2 (exact predicates, inexact constructions), updated (removals, then
// insertions spatially sorted, each hinted by the one before) against rebuilt (range insert)
// per step, with no tiles, clipping or areas: the ratio a peer's incremental Delaunay reaches.
//
// Detailed outlines: 376 gauges (60% reporting at random each step) under a catchment of 10^3 to
// 3 10^5 vertices (a wavy oval some 6 degrees across): what a step costs when the tiles on the
// boundary hold thousands of its segments; and what the tiles for display cost at a step
// (CurrentClippedTiles: clipped with their rings, cut into display pieces, their borders' vertices
// shared, densified to 2 km and taken to lon/lat, as the filter's output 0 at each time step).
//
//   bench_areal_average [examples/data] [--synthetic]   prints the Colorado table and the detailed
//                                                       outlines' (not with --synthetic), the
//                                                       synthetic table and the CGAL peer's
#include "areal_average.h"

#ifdef TESSERA_HAVE_CGAL
#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/spatial_sort.h>
#endif

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <random>
#include <sstream>
#include <string>
#include <vector>

using namespace tessera;
using Clock = std::chrono::steady_clock;

namespace
{

double Seconds(Clock::time_point since)
{
  return std::chrono::duration<double>(Clock::now() - since).count();
}

std::vector<std::string> SplitCsv(const std::string& line)
{
  std::vector<std::string> fields;
  std::string field;
  bool quoted = false;
  for (char c : line)
  {
    if (c == '"')
      quoted = !quoted;
    else if (c == ',' && !quoted)
    {
      fields.push_back(field);
      field.clear();
    }
    else
      field += c;
  }
  fields.push_back(field);
  return fields;
}

struct Colorado
{
  std::vector<Point2> Gauges;
  std::vector<std::size_t> RingOffsets{ 0 };
  std::vector<Point2> Ring;
  std::vector<std::vector<double>> Steps;
};

/// The examples' data: stations, the outline's coordinates (read from the GeoJSON text), and
/// the monthly values as one vector per month (NaN = missing).
Colorado ReadColorado(const std::string& dir)
{
  Colorado data;
  std::map<std::string, std::size_t> gaugeOf;
  std::ifstream stations(dir + "/colorado_stations.csv");
  std::string line;
  std::getline(stations, line);
  while (std::getline(stations, line))
  {
    const auto f = SplitCsv(line);
    gaugeOf[f[0]] = data.Gauges.size();
    data.Gauges.push_back({ std::stod(f[2]), std::stod(f[3]) });
  }
  std::ifstream outline(dir + "/colorado_boundary.geojson");
  std::stringstream text;
  text << outline.rdbuf();
  const std::string json = text.str();
  std::size_t at = json.find("[[[");
  const std::size_t end = json.find("]]]", at);
  for (at += 2; at < end;)
  {
    const std::size_t open = json.find('[', at);
    if (open == std::string::npos || open > end)
      break;
    const std::size_t comma = json.find(',', open);
    const std::size_t close = json.find(']', comma);
    data.Ring.push_back({ std::stod(json.substr(open + 1, comma - open - 1)),
      std::stod(json.substr(comma + 1, close - comma - 1)) });
    at = close + 1;
  }
  data.Ring.pop_back(); // GeoJSON repeats the first vertex
  data.RingOffsets.push_back(data.Ring.size());
  std::ifstream monthly(dir + "/colorado_monthly_precip.csv");
  std::getline(monthly, line);
  std::map<int, std::size_t> stepOf;
  std::vector<std::tuple<int, std::size_t, double>> rows;
  while (std::getline(monthly, line))
  {
    const auto f = SplitCsv(line);
    const int month = std::stoi(f[1]) * 12 + std::stoi(f[2]) - 1;
    stepOf[month] = 0;
    rows.emplace_back(month, gaugeOf.at(f[0]), std::stod(f[3]));
  }
  std::size_t k = 0;
  for (auto& entry : stepOf)
    entry.second = k++;
  data.Steps.assign(stepOf.size(), std::vector<double>(data.Gauges.size(), std::nan("")));
  for (const auto& [month, gauge, value] : rows)
    data.Steps[stepOf[month]][gauge] = value;
  return data;
}

double RunAll(ThiessenArealAverage& average,
  const std::vector<std::vector<double>>& steps,
  double& checksum,
  double* derivedPerStep = nullptr,
  double* clearPerStep = nullptr,
  double* deferredPerStep = nullptr)
{
  const auto start = Clock::now();
  double derived = 0.0, clear = 0.0, deferred = 0.0;
  for (const auto& values : steps)
  {
    const ArealStep step = average.Step(values);
    checksum += std::isnan(step.Mean) ? 0.0 : step.Mean;
    derived += step.TilesDerived;
    clear += step.TilesFoundClear;
    deferred += step.RemovalsDeferred;
  }
  if (derivedPerStep)
    *derivedPerStep = derived / double(steps.size());
  if (clearPerStep)
    *clearPerStep = clear / double(steps.size());
  if (deferredPerStep)
    *deferredPerStep = deferred / double(steps.size());
  return Seconds(start);
}

void RunColorado(const std::string& dir);
void RunDetailedOutlines();
void RunSynthetic(int repeats);

} // namespace

int main(int argc, char** argv)
{
  std::string dir = "examples/data";
  bool syntheticOnly = false;
  int repeats = 3;
  for (int k = 1; k < argc; ++k)
  {
    const std::string arg = argv[k];
    if (arg == "--help" || arg == "-h")
    {
      std::printf("usage: bench_areal_average [DATA_DIR] [--synthetic] [--repeats N]\n"
                  "  DATA_DIR     the examples' data (default examples/data)\n"
                  "  --synthetic  only the synthetic table (100k gauges, 1%% toggling)\n"
                  "  --repeats N  synthetic runs per mode, alternating, the fastest kept"
                  " (default 3)\n");
      return 0;
    }
    if (arg == "--synthetic")
      syntheticOnly = true;
    else if (arg == "--repeats" && k + 1 < argc)
    {
      repeats = std::atoi(argv[++k]);
      if (repeats < 1)
      {
        std::fprintf(
          stderr, "bench_areal_average: --repeats wants a positive count, not %s\n", argv[k]);
        return 1;
      }
    }
    else
      dir = arg;
  }
  if (!syntheticOnly)
  {
    RunColorado(dir);
    RunDetailedOutlines();
  }
  RunSynthetic(repeats);
  return 0;
}

namespace
{

void RunColorado(const std::string& dir)
{
  const Colorado data = ReadColorado(dir);
  std::printf("Colorado: %zu gauges, %zu months, outline of %zu vertices\n\n",
    data.Gauges.size(),
    data.Steps.size(),
    data.Ring.size());
  std::printf(
    "| Colorado, all months        | area method      | seconds | areal-mean checksum |\n");
  std::printf(
    "|-----------------------------|------------------|---------|---------------------|\n");
  for (bool incremental : { true, false })
  {
    for (AreaMethod method : { AreaMethod::EqualAreaPlane, AreaMethod::GeodesicPolygon })
    {
      ArealAverageSettings settings;
      settings.Incremental = incremental;
      settings.Areas = method;
      const auto build = Clock::now();
      ThiessenArealAverage average(data.Gauges, data.RingOffsets, data.Ring, settings);
      double checksum = 0.0;
      const double seconds = RunAll(average, data.Steps, checksum) + Seconds(build);
      std::printf("| %-27s | %-16s | %7.3f | %19.10f |\n",
        incremental ? "incremental updates" : "rebuild every month",
        method == AreaMethod::EqualAreaPlane ? "equal-area plane" : "geodesic polygon",
        seconds,
        checksum);
    }
  }
}

#ifdef TESSERA_HAVE_CGAL
/// Seconds per step (after the first) of CGAL's Delaunay triangulation of the reporting gauges:
/// updated (first) and rebuilt (second).
std::pair<double, double> CgalTopologyPerStep(const std::vector<Point2>& gauges,
  const std::vector<std::vector<double>>& steps)
{
  using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
  using Delaunay = CGAL::Delaunay_triangulation_2<Kernel>;
  using Point = Kernel::Point_2;
  const std::size_t n = gauges.size();
  const auto reporting = [&](std::size_t t, std::size_t g) { return !std::isnan(steps[t][g]); };
  // Updated: handles kept per gauge.
  Delaunay dt;
  std::vector<Delaunay::Vertex_handle> handle(n);
  for (std::size_t g = 0; g < n; ++g)
    if (reporting(0, g))
      handle[g] = dt.insert(Point(gauges[g].x, gauges[g].y));
  auto start = Clock::now();
  std::vector<std::pair<Point, std::size_t>> started;
  for (std::size_t t = 1; t < steps.size(); ++t)
  {
    started.clear();
    for (std::size_t g = 0; g < n; ++g)
    {
      const bool on = reporting(t, g);
      if (handle[g] != Delaunay::Vertex_handle() && !on)
      {
        dt.remove(handle[g]);
        handle[g] = Delaunay::Vertex_handle();
      }
      else if (handle[g] == Delaunay::Vertex_handle() && on)
      {
        started.emplace_back(Point(gauges[g].x, gauges[g].y), g);
      }
    }
    CGAL::spatial_sort(started.begin(),
      started.end(),
      CGAL::Spatial_sort_traits_adapter_2<Kernel,
        CGAL::First_of_pair_property_map<std::pair<Point, std::size_t>>>());
    Delaunay::Face_handle hint;
    for (const auto& [p, g] : started)
    {
      handle[g] = dt.insert(p, hint);
      hint = handle[g]->face();
    }
  }
  const double updated = Seconds(start) / double(steps.size() - 1);
  // Rebuilt.
  start = Clock::now();
  std::size_t vertices = 0;
  for (std::size_t t = 1; t < steps.size(); ++t)
  {
    std::vector<Point> points;
    for (std::size_t g = 0; g < n; ++g)
      if (reporting(t, g))
        points.emplace_back(gauges[g].x, gauges[g].y);
    Delaunay rebuilt;
    rebuilt.insert(points.begin(), points.end());
    vertices += rebuilt.number_of_vertices();
  }
  const double rebuiltTime = Seconds(start) / double(steps.size() - 1);
  if (vertices == 0)
    std::printf("(no vertices)\n");
  return { updated, rebuiltTime };
}
#endif

void RunDetailedOutlines()
{
  std::printf("\n| outline vertices | gauges | steps | construction s | incremental ms/step |"
              " tiles for display ms | display piece vertices |\n");
  std::printf("|------------------|--------|-------|----------------|---------------------|"
              "----------------------|------------------------|\n");
  constexpr int DisplayRepeats = 3;
  for (const std::size_t vertices : { 1000u, 30000u, 300000u })
  {
    std::mt19937_64 random(3);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::vector<Point2> ring(vertices);
    for (std::size_t k = 0; k < vertices; ++k)
    {
      const double angle = 2.0 * M_PI * double(k) / double(vertices);
      const double radius = 3.0 *
        (1.0 + 0.08 * std::sin(7 * angle) + 0.04 * std::sin(53 * angle) +
          0.01 * std::sin(1009 * angle) + 0.003 * (unit(random) - 0.5));
      ring[k] = { -105.5 + radius * std::cos(angle), 39.0 + 0.8 * radius * std::sin(angle) };
    }
    std::vector<Point2> gauges(376);
    for (Point2& g : gauges)
    {
      g = { -111.0 + 11.0 * unit(random), 34.0 + 10.0 * unit(random) };
    }
    const int stepCount = 100;
    std::vector<std::vector<double>> steps(stepCount, std::vector<double>(gauges.size()));
    for (std::vector<double>& step : steps)
    {
      for (double& value : step)
      {
        value = unit(random) < 0.6 ? unit(random) : std::nan("");
      }
    }
    const auto start = Clock::now();
    ThiessenArealAverage average(gauges, { 0, vertices }, ring);
    const double built = Seconds(start);
    const auto stepping = Clock::now();
    for (const std::vector<double>& step : steps)
    {
      average.Step(step);
    }
    const double stepped = Seconds(stepping);
    // The tiles for display (what ParaView's time slider waits for at each step): at the last
    // step, DisplayRepeats times, the fastest kept.
    double display = HUGE_VAL;
    std::size_t pieceVertices = 0;
    for (int k = 0; k < DisplayRepeats; ++k)
    {
      const auto showing = Clock::now();
      const ClippedTilesLonLat shown = average.CurrentClippedTiles(2000.0);
      display = std::min(display, Seconds(showing));
      pieceVertices = shown.Pieces.Vertices.size();
    }
    std::printf("| %16zu | %6zu | %5d | %14.3f | %19.2f | %20.1f | %22zu |\n",
      vertices,
      gauges.size(),
      stepCount,
      built,
      1e3 * stepped / stepCount,
      1e3 * display,
      pieceVertices);
  }
}

// Synthetic: N gauges in a 10 x 10 degree box, a catchment inside it, 1% toggling per step. Each
// mode runs `repeats` times, the modes alternating, and the fastest run of each is reported: on
// this shared machine a run can take 1.5x another for reasons outside the program.
void RunSynthetic(int repeats)
{
  std::vector<std::string> peerRows;
  std::printf("\n| gauges | steps | toggling per step | update s/step | rebuild s/step | ratio |"
              " tiles re-derived per update | changed tiles found clear | removals deferred |\n");
  std::printf("|--------|-------|-------------------|---------------|----------------|-------|"
              "-----------------------------|---------------------------|-------------------|\n");
  for (std::size_t n : { 10000u, 100000u })
  {
    std::mt19937_64 random(42);
    std::uniform_real_distribution<double> lon(-110.0, -100.0), lat(35.0, 45.0), value(0.0, 10.0);
    std::vector<Point2> gauges(n);
    for (auto& g : gauges)
      g = { lon(random), lat(random) };
    const std::vector<std::size_t> offsets{ 0, 4 };
    const std::vector<Point2> square{ { -108, 37 }, { -102, 37 }, { -102, 43 }, { -108, 43 } };
    const int stepCount = n >= 100000 ? 200 : 200;
    std::vector<std::vector<double>> steps(stepCount, std::vector<double>(n));
    std::vector<char> on(n, 1);
    std::uniform_int_distribution<std::size_t> pick(0, n - 1);
    for (int t = 0; t < stepCount; ++t)
    {
      for (std::size_t k = 0; k < n / 100; ++k)
      {
        const std::size_t g = pick(random);
        on[g] = !on[g];
      }
      for (std::size_t g = 0; g < n; ++g)
        steps[t][g] = on[g] ? value(random) : std::nan("");
    }
    double perStep[2] = { HUGE_VAL, HUGE_VAL };
    double checksum[2] = { 0.0, 0.0 };
    double derived[2] = { 0.0, 0.0 }; // mean tiles derived per step
    double clear = 0.0;               // mean changed tiles found clear per update
    double deferred = 0.0;            // mean removals deferred per update
    const std::vector<std::vector<double>> rest(steps.begin() + 1, steps.end());
    for (int run = 0; run < 2 * repeats; ++run)
    {
      const int mode = run % 2;
      ArealAverageSettings settings;
      settings.Incremental = mode == 0;
      ThiessenArealAverage average(gauges, offsets, square, settings);
      average.Step(steps[0]); // the first step builds in both modes: not timed
      checksum[mode] = 0.0;   // (every run gives the same)
      const double seconds = RunAll(average,
        rest,
        checksum[mode],
        &derived[mode],
        mode == 0 ? &clear : nullptr,
        mode == 0 ? &deferred : nullptr);
      perStep[mode] = std::min(perStep[mode], seconds / double(rest.size()));
    }
    std::printf(
      "| %6zu | %5d | %17zu | %13.5f | %14.5f | %5.1f | %13.0f of %13.0f | %25.0f | %17.0f |\n",
      n,
      stepCount,
      n / 100,
      perStep[0],
      perStep[1],
      perStep[1] / perStep[0],
      derived[0],
      derived[1],
      clear,
      deferred);
    if (std::abs(checksum[0] - checksum[1]) > 1e-9 * std::abs(checksum[1]))
      std::printf("   (checksums differ: %.12f vs %.12f)\n", checksum[0], checksum[1]);
#ifdef TESSERA_HAVE_CGAL
    double updated = HUGE_VAL, rebuilt = HUGE_VAL; // the fastest runs, as for Tessera's
    for (int run = 0; run < repeats; ++run)
    {
      const auto [update, rebuild] = CgalTopologyPerStep(gauges, steps);
      updated = std::min(updated, update);
      rebuilt = std::min(rebuilt, rebuild);
    }
    char row[200];
    std::snprintf(row,
      sizeof row,
      "| %6zu | %22.5f | %23.5f | %5.1f |",
      n,
      updated,
      rebuilt,
      rebuilt / updated);
    peerRows.push_back(row);
#endif
  }
  if (!peerRows.empty())
  {
    std::printf("\n| gauges | CGAL DT2 update s/step | CGAL DT2 rebuild s/step | ratio |   "
                "(topology only: no tiles, clipping or areas)\n");
    std::printf("|--------|------------------------|-------------------------|-------|\n");
    for (const std::string& row : peerRows)
      std::printf("%s\n", row.c_str());
  }
}

} // namespace
