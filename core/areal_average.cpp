#include "areal_average.h"

#include "dirichlet_tessellation.h"
#include "errors.h"
#include "polygon_validation.h"
#include "tiles.h"
#include "window.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <sstream>

namespace tessera
{
namespace
{

constexpr std::int32_t NotInTessellation = -1;

/// Points along a ring's edges in the plane so that no piece is longer than step (closing edge
/// included; the first vertex is not repeated).
void DensifyPlanarRing(const Point2* ring, std::size_t count, double step, std::vector<Point2>& out)
{
  out.clear();
  for (std::size_t k = 0; k < count; ++k)
  {
    const Point2& a = ring[k];
    const Point2& b = ring[(k + 1) % count];
    const double length = std::hypot(b.x - a.x, b.y - a.y);
    const int pieces = step > 0.0 ? std::max(1, static_cast<int>(std::ceil(length / step))) : 1;
    for (int i = 0; i < pieces; ++i)
    {
      const double t = static_cast<double>(i) / pieces;
      out.push_back({ a.x + t * (b.x - a.x), a.y + t * (b.y - a.y) });
    }
  }
}

bool SameVertices(const std::vector<Point2>& cached, const Point2* tile, std::size_t count)
{
  return cached.size() == count && std::equal(cached.begin(), cached.end(), tile);
}

} // namespace

struct ThiessenArealAverage::State
{
  ArealAverageSettings Settings;
  ProjectionParameters Parameters;
  std::unique_ptr<GeographicProjection> Projector;
  AreaMethod Method = AreaMethod::EqualAreaPlane;

  std::vector<Point2> GaugesXY;
  std::vector<std::int32_t> FirstAtPlace; // per gauge: smallest gauge id at its coordinates
  std::vector<std::pair<std::int32_t, std::int32_t>> Duplicates;

  std::unique_ptr<Catchment> Region;
  double CatchmentArea = 0.0;
  std::unique_ptr<Window> TheWindow;

  std::unique_ptr<DirichletTessellation> Tessellation;
  std::vector<std::int32_t> EngineOfGauge; // engine id, or NotInTessellation
  std::vector<std::int32_t> GaugeOfEngine;

  // Per gauge: the tile polygon last clipped and its clipped area (m^2).
  std::vector<std::vector<Point2>> CachedTile;
  std::vector<double> CachedArea;
  Catchment::Workspace Work;
  ClippedRings Scratch;
  std::vector<Point2> Dense;

  TileSet CurrentTiles;

  double MeasureRings(const ClippedRings& rings, std::size_t firstRing, std::size_t lastRing)
  {
    double total = 0.0;
    std::vector<Point2> lonlat;
    for (std::size_t r = firstRing; r < lastRing; ++r)
    {
      const std::size_t begin = rings.RingOffsets[r];
      const std::size_t count = rings.RingOffsets[r + 1] - begin;
      if (count < 3)
      {
        continue;
      }
      DensifyPlanarRing(
        &rings.Vertices[begin], count, this->Settings.GeodesicStepMetres, this->Dense);
      lonlat.resize(this->Dense.size());
      for (std::size_t i = 0; i < this->Dense.size(); ++i)
      {
        lonlat[i] = this->Projector->Inverse(this->Dense[i]);
      }
      total += EllipsoidalRingArea(lonlat);
    }
    return total;
  }

  /// Ellipsoidal area (m^2) of tile & catchment.
  double ClippedArea(const Point2* tile, std::size_t count, std::size_t tileId)
  {
    if (this->Method == AreaMethod::EqualAreaPlane)
    {
      return this->Region->ClipInto(tile, count, tileId, this->Work, nullptr);
    }
    this->Scratch.RingOffsets.assign(1, 0);
    this->Scratch.Vertices.clear();
    const double planar = this->Region->ClipInto(tile, count, tileId, this->Work, &this->Scratch);
    if (planar <= 0.0)
    {
      return 0.0;
    }
    return this->MeasureRings(this->Scratch, 0, this->Scratch.RingOffsets.size() - 1);
  }

  void Rebuild(const std::vector<std::int32_t>& active)
  {
    std::vector<Point2> points;
    points.reserve(active.size());
    std::fill(this->EngineOfGauge.begin(), this->EngineOfGauge.end(), NotInTessellation);
    this->GaugeOfEngine.clear();
    for (std::int32_t g : active)
    {
      this->EngineOfGauge[g] = static_cast<std::int32_t>(points.size());
      this->GaugeOfEngine.push_back(g);
      points.push_back(this->GaugesXY[g]);
    }
    this->Tessellation.reset(new DirichletTessellation(*this->TheWindow, std::move(points)));
  }

  /// Removes the gauges that stopped reporting and inserts those that started.
  void Update(const std::vector<char>& wanted)
  {
    for (std::size_t g = 0; g < wanted.size(); ++g)
    {
      if (!wanted[g] && this->EngineOfGauge[g] != NotInTessellation)
      {
        this->Tessellation->Remove(this->EngineOfGauge[g]);
        this->EngineOfGauge[g] = NotInTessellation;
      }
    }
    for (std::size_t g = 0; g < wanted.size(); ++g)
    {
      if (wanted[g] && this->EngineOfGauge[g] == NotInTessellation)
      {
        const std::int32_t id = this->Tessellation->Insert(this->GaugesXY[g]);
        this->EngineOfGauge[g] = id;
        if (static_cast<std::size_t>(id) >= this->GaugeOfEngine.size())
        {
          this->GaugeOfEngine.resize(id + 1, NotInTessellation);
        }
        this->GaugeOfEngine[id] = static_cast<std::int32_t>(g);
      }
    }
  }
};

ThiessenArealAverage::ThiessenArealAverage(const std::vector<Point2>& gaugesLonLat,
  const std::vector<std::size_t>& catchmentRingOffsets,
  const std::vector<Point2>& catchmentLonLat,
  const ArealAverageSettings& settings)
  : Impl(new State)
{
  State& s = *this->Impl;
  s.Settings = settings;
  for (std::size_t g = 0; g < gaugesLonLat.size(); ++g)
  {
    const Point2& p = gaugesLonLat[g];
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || std::abs(p.y) > 90.0)
    {
      std::ostringstream message;
      message.precision(17);
      message << "gauge " << g << " has an invalid longitude/latitude (" << p.x << ", " << p.y
              << ")";
      throw InputError(message.str());
    }
  }
  const CleanRings rings = ValidateRings(catchmentRingOffsets, catchmentLonLat);

  if (settings.HaveProjection)
  {
    s.Parameters = settings.Projection;
  }
  else
  {
    std::vector<Point2> everything = gaugesLonLat;
    everything.insert(everything.end(), rings.Vertices.begin(), rings.Vertices.end());
    s.Parameters = AutomaticParameters(everything);
  }
  s.Projector.reset(new GeographicProjection(s.Parameters));
  s.Method = settings.Areas;
  if (s.Method == AreaMethod::Automatic)
  {
    s.Method = s.Parameters.Kind == ProjectionKind::AlbersEqualArea ? AreaMethod::EqualAreaPlane
                                                                    : AreaMethod::GeodesicPolygon;
  }

  // Gauges: projected, and grouped by exact position (the first of a group is its name).
  s.GaugesXY.resize(gaugesLonLat.size());
  s.FirstAtPlace.resize(gaugesLonLat.size());
  std::map<std::pair<double, double>, std::int32_t> firstAt;
  for (std::size_t g = 0; g < gaugesLonLat.size(); ++g)
  {
    s.GaugesXY[g] = s.Projector->Forward(gaugesLonLat[g], static_cast<long long>(g));
    const auto key = std::make_pair(s.GaugesXY[g].x, s.GaugesXY[g].y);
    const auto found = firstAt.emplace(key, static_cast<std::int32_t>(g)).first->second;
    s.FirstAtPlace[g] = found;
    if (found != static_cast<std::int32_t>(g))
    {
      s.Duplicates.emplace_back(static_cast<std::int32_t>(g), found);
    }
  }

  // Catchment: edges straight in lon/lat are densified, then projected.
  std::vector<std::size_t> offsets{ 0 };
  std::vector<Point2> projected;
  for (std::size_t r = 0; r + 1 < rings.RingOffsets.size(); ++r)
  {
    const std::size_t begin = rings.RingOffsets[r], end = rings.RingOffsets[r + 1];
    for (std::size_t k = begin; k < end; ++k)
    {
      const Point2& a = rings.Vertices[k];
      const Point2& b = rings.Vertices[k + 1 < end ? k + 1 : begin];
      const int pieces = DensifiedPieceCount(a, b, settings.CatchmentEdgeDegrees);
      for (int i = 0; i < pieces; ++i)
      {
        projected.push_back(s.Projector->Forward(InterpolateLonLat(a, b, double(i) / pieces)));
      }
    }
    offsets.push_back(projected.size());
  }
  s.Region.reset(new Catchment(offsets, projected));
  if (s.Method == AreaMethod::EqualAreaPlane)
  {
    s.CatchmentArea = s.Region->Area();
  }
  else
  {
    ClippedRings stored;
    stored.RingOffsets = s.Region->RingOffsets();
    stored.Vertices = s.Region->Vertices();
    s.CatchmentArea = s.MeasureRings(stored, 0, stored.RingOffsets.size() - 1);
  }

  // The window: every gauge and the whole catchment, padded.
  Box2 box = s.Region->Bounds();
  for (const Point2& p : s.GaugesXY)
  {
    box.XMin = std::min(box.XMin, p.x);
    box.XMax = std::max(box.XMax, p.x);
    box.YMin = std::min(box.YMin, p.y);
    box.YMax = std::max(box.YMax, p.y);
  }
  const double pad =
    std::max(settings.Padding, 0.01) * std::max(box.XMax - box.XMin, box.YMax - box.YMin);
  s.TheWindow.reset(
    new Window(Window::Rectangle(box.XMin - pad, box.XMax + pad, box.YMin - pad, box.YMax + pad)));
  s.Tessellation.reset(new DirichletTessellation(*s.TheWindow));
  s.EngineOfGauge.assign(gaugesLonLat.size(), NotInTessellation);
  s.CachedTile.resize(gaugesLonLat.size());
  s.CachedArea.assign(gaugesLonLat.size(), 0.0);
}

ThiessenArealAverage::~ThiessenArealAverage() = default;

const ProjectionParameters& ThiessenArealAverage::Projection() const
{
  return this->Impl->Parameters;
}

AreaMethod ThiessenArealAverage::Method() const
{
  return this->Impl->Method;
}

const std::vector<std::pair<std::int32_t, std::int32_t>>& ThiessenArealAverage::DuplicateGauges()
  const
{
  return this->Impl->Duplicates;
}

double ThiessenArealAverage::CatchmentAreaM2() const
{
  return this->Impl->CatchmentArea;
}

const std::vector<Point2>& ThiessenArealAverage::ProjectedGauges() const
{
  return this->Impl->GaugesXY;
}

ArealStep ThiessenArealAverage::Step(const std::vector<double>& values)
{
  State& s = *this->Impl;
  const std::size_t n = s.GaugesXY.size();
  if (values.size() != n)
  {
    throw InputError("a step has " + std::to_string(values.size()) + " values for " +
      std::to_string(n) + " gauges");
  }
  // The gauge used at each place: the first of its group that reported.
  std::vector<char> wanted(n, 0);
  std::vector<char> placeTaken(n, 0);
  for (std::size_t g = 0; g < n; ++g)
  {
    if (std::isinf(values[g]))
    {
      throw InputError("gauge " + std::to_string(g) + " has an infinite value");
    }
    if (!std::isnan(values[g]) && !placeTaken[s.FirstAtPlace[g]])
    {
      placeTaken[s.FirstAtPlace[g]] = 1;
      wanted[g] = 1;
    }
  }
  if (s.Settings.Incremental)
  {
    s.Update(wanted);
  }
  else
  {
    std::vector<std::int32_t> active;
    for (std::size_t g = 0; g < n; ++g)
    {
      if (wanted[g])
      {
        active.push_back(static_cast<std::int32_t>(g));
      }
    }
    s.Rebuild(active);
  }

  ArealStep step;
  step.StationsUsed = static_cast<int>(std::count(wanted.begin(), wanted.end(), 1));
  if (step.StationsUsed == 0)
  {
    s.CurrentTiles = TileSet();
    step.Mean = std::numeric_limits<double>::quiet_NaN();
    return step;
  }
  s.CurrentTiles = TessellationDual(*s.Tessellation).Tiles();
  const TileSet& tiles = s.CurrentTiles;
  double weighted = 0.0, weightSum = 0.0;
  for (std::size_t k = 0; k < tiles.PointIds.size(); ++k)
  {
    const std::int32_t g = s.GaugeOfEngine[tiles.PointIds[k]];
    const Point2* tile = &tiles.Vertices[tiles.Offsets[k]];
    const std::size_t count = static_cast<std::size_t>(tiles.Offsets[k + 1] - tiles.Offsets[k]);
    if (!SameVertices(s.CachedTile[g], tile, count))
    {
      s.CachedArea[g] = s.ClippedArea(tile, count, static_cast<std::size_t>(g));
      s.CachedTile[g].assign(tile, tile + count);
    }
    const double area = s.CachedArea[g];
    if (area > 0.0)
    {
      const double weight = area / s.CatchmentArea;
      step.Gauges.push_back(g);
      step.Weights.push_back(weight);
      step.AreasM2.push_back(area);
      weighted += weight * values[g];
      weightSum += weight;
    }
  }
  // Tiles come in ascending engine id; report gauges ascending.
  std::vector<std::size_t> order(step.Gauges.size());
  for (std::size_t i = 0; i < order.size(); ++i)
  {
    order[i] = i;
  }
  std::sort(order.begin(),
    order.end(),
    [&](std::size_t a, std::size_t b) { return step.Gauges[a] < step.Gauges[b]; });
  ArealStep sorted = step;
  for (std::size_t i = 0; i < order.size(); ++i)
  {
    sorted.Gauges[i] = step.Gauges[order[i]];
    sorted.Weights[i] = step.Weights[order[i]];
    sorted.AreasM2[i] = step.AreasM2[order[i]];
  }
  sorted.StationsWeighted = static_cast<int>(sorted.Gauges.size());
  sorted.CoveredFraction = weightSum;
  sorted.Mean = weightSum > 0.0 ? weighted / weightSum : std::numeric_limits<double>::quiet_NaN();
  return sorted;
}

ClippedTilesLonLat ThiessenArealAverage::CurrentClippedTiles(double maxStepMetres) const
{
  State& s = *this->Impl;
  ClippedTilesLonLat out;
  const TileSet& tiles = s.CurrentTiles;
  for (std::size_t k = 0; k < tiles.PointIds.size(); ++k)
  {
    const std::int32_t g = s.GaugeOfEngine[tiles.PointIds[k]];
    const Point2* tile = &tiles.Vertices[tiles.Offsets[k]];
    const std::size_t count = static_cast<std::size_t>(tiles.Offsets[k + 1] - tiles.Offsets[k]);
    ClippedRings rings;
    if (s.Region->ClipInto(tile, count, static_cast<std::size_t>(g), s.Work, &rings) <= 0.0)
    {
      continue;
    }
    out.Gauges.push_back(g);
    for (std::size_t r = 0; r + 1 < rings.RingOffsets.size(); ++r)
    {
      const std::size_t begin = rings.RingOffsets[r];
      DensifyPlanarRing(
        &rings.Vertices[begin], rings.RingOffsets[r + 1] - begin, maxStepMetres, s.Dense);
      for (const Point2& p : s.Dense)
      {
        out.Rings.Vertices.push_back(s.Projector->Inverse(p));
      }
      out.Rings.RingOffsets.push_back(out.Rings.Vertices.size());
    }
    out.TileRingOffsets.push_back(out.Rings.RingOffsets.size() - 1);
  }
  return out;
}

} // namespace tessera
