#pragma once
// Thiessen (1911) areal averages of gauge time series over a catchment, from lon/lat gauges.
//
// Per Green and Sibson section 1.2 the tessellation is built in a convex window holding every
// gauge and the catchment (a padded rectangle in the projected plane), and the catchment is
// imposed afterwards: a gauge outside the catchment still owns the part of it nearest to it.
// At each time step only the gauges that reported take part: a gauge without a value is removed
// and its neighbours take its area.
//
// Reuse between steps. The reporting set changes a little from one step to the next (in the
// Colorado record, 1236 months have 1071 distinct sets, so caching by set is useless), so the
// tessellation is updated, not rebuilt: gauges that stopped reporting are removed and those that
// started are inserted (Green-Sibson removal and insertion). Only the tiles whose areas can have
// changed (those of the changed gauges' neighbours, each taken as it is removed or inserted) are
// derived and clipped against the catchment again; the others keep their clipped areas.
// (Comparing each new polygon with the previous one to skip the clip did not pay: in the
// synthetic benchmark 99% of them had changed.) Of those tiles, the ones provably still clear of
// the catchment are not even derived: each gauge keeps a box holding its tile, grown by the box of
// each removed neighbour (ArealStep's TilesFoundClear counts them), and a gauge whose tile is
// clear of it stays in the tessellation, unused, when it stops reporting (RemovalsDeferred). A
// gauge that reports again is inserted under its old engine id, so that the engine's ids, given
// along a Hilbert curve at the first step, stay near each other in space; the per-step work on
// the changed gauges' neighbours is done in those ids.
//
// Areas on the ellipsoid. The weight of a gauge is the ellipsoidal area of its tile inside the
// catchment over the catchment's ellipsoidal area. Two ways, chosen by AreaMethod:
// - EqualAreaPlane (default when the projection is equal-area: Albers, as the automatic choice
//   is, or Lambert azimuthal): the projection's area scale is exactly 1, so the planar area of a
//   clipped tile IS the ellipsoidal area of its preimage. Exact, additive (weights sum to 1 to
//   round-off), fast.
// - GeodesicPolygon (any projection): the clipped rings are densified in the plane, unprojected
//   and measured with GeographicLib::PolygonArea (edges become geodesic chords: the sum over the
//   pieces matches the catchment to about 1e-9 at the default 1 km spacing).

#include "clip.h"
#include "geo.h"
#include "errors.h"         // InputError, which the constructor and Step throw
#include "piece_outlines.h" // RegionOutlines
#include "geometry.h"

#include <cstdint>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace tessera
{

enum class AreaMethod
{
  Automatic,       ///< EqualAreaPlane for an equal-area projection, else GeodesicPolygon
  EqualAreaPlane,  ///< planar areas; only with an equal-area projection (else an InputError)
  GeodesicPolygon, ///< unprojected, densified rings measured with GeographicLib::PolygonArea
};

struct ArealAverageSettings
{
  /// Projection of gauges and catchment; without one, AutomaticParameters of the catchment (where
  /// the tiles are measured: gauges far from it do not change it).
  bool HaveProjection = false;
  ProjectionParameters Projection;
  AreaMethod Areas = AreaMethod::Automatic;
  /// The window: the projected bounding box of gauges and catchment, padded on every side by this
  /// fraction of its larger side (at least 0.01 of it is used). From 0 to MaxPadding, else an
  /// InputError naming it: a window far larger than the data rounds its tiles (at 1e13 the
  /// covered fraction was 0.9999).
  double Padding = 0.1;
  static constexpr double MaxPadding = 1000.0;
  /// Catchment edges are straight in lon/lat: cut into pieces of at most this many degrees before
  /// projecting. Finite and above 0, else an InputError naming it. An edge whose longitudes differ
  /// by more than 270 degrees as written is taken the shorter way round (179 to -179 across the
  /// 180th meridian); one that differs by 180 to 270 degrees could be meant either way and is an
  /// InputError naming its ring and segment (EdgeReadsBothWays, geo.h). More than 20 million pieces
  /// in all (200000 degrees of boundary at 0.01) is an InputError giving the count: they would take
  /// gigabytes; so is an edge of more than a million (MaxDensifiedPieces, geo.h), naming it.
  double CatchmentEdgeDegrees = 0.01;
  /// Gauges closer than this (projected metres) are at one place, as exact repeats are: at each
  /// step the first of them that reported is used (DuplicateGauges lists them). Gauges much
  /// closer than a millimetre have tiles too thin for their rounded vertices (a strip a few
  /// nanometres wide folds), whose clipped areas are unreliable; the same gauge written with
  /// longitudes 360 degrees apart lands some nanometres from itself. 0 groups exact repeats only.
  double CoLocatedMetres = 0.01;
  /// A catchment vertex this close (degrees) to another ring's edge, and farther from its ends, is
  /// on that edge: made a vertex of it too (SnapVerticesOntoSegments). 1e-6 degrees (about 11 cm)
  /// holds a vertex of a shared border rounded to the 6 decimals GeoJSON writers use (RFC 7946:
  /// up to some 7e-7 degrees off the other side's edge).
  static constexpr double SharedBorderDegrees = 1e-6;
  /// GeodesicPolygon only: spacing, in projected metres, of the points added along clipped ring
  /// edges before unprojecting. At least MinGeodesicStepMetres, and finite, else an InputError
  /// naming it (a millimetre's step took gigabytes; NaN, 0 or less turned densifying off).
  double GeodesicStepMetres = 1000.0;
  static constexpr double MinGeodesicStepMetres = 1.0;
  /// Optional names of the gauges for error messages, one per gauge (e.g. their station ids):
  /// gauge g is then "gauge g (station NAME)". Empty: gauges are named by index only.
  std::vector<std::string> GaugeNames;
  /// false: every step from scratch, nothing reused (rebuild the tessellation, clip every tile):
  /// the baseline that incremental updates are compared with in benchmarks. Both give the same
  /// weights and areas, to the bit while no removal is deferred (the tiles do not depend on how
  /// the engine numbers the gauges, nor on the order of the updates). A gauge whose removal is
  /// deferred (its tile is clear of the catchment) stays in the tessellation: it changes no area
  /// of the exact tiles, but the rounding of vertices outside the catchment, so areas can then
  /// differ in their last bits (some 1e-16 relative; about 1e-9 for GeodesicPolygon, whose
  /// densified rings can then be cut at other points).
  bool Incremental = true;
};

/// One time step's result.
struct ArealStep
{
  double Mean = 0.0;        ///< sum of weight * value over weighted gauges / sum of weights; NaN
                            ///< when no gauge reported
  int StationsUsed = 0;     ///< gauges that reported (co-located repeats counted once)
  int StationsWeighted = 0; ///< of those, gauges whose tile reaches into the catchment
  double CoveredFraction = 0.0; ///< sum of weights (1 when any gauge reported)
  int TilesDerived = 0; ///< tiles derived for this step: all after a rebuild, few after an update
  /// Tiles that an update may have changed but did not derive: their bounds show them clear of
  /// the catchment (clipped area 0). Always 0 after a rebuild.
  int TilesFoundClear = 0;
  /// Gauges that stopped reporting at this step but stay in the tessellation, unused, because
  /// their tiles are clear of the catchment: removing them would change no clipped area. (Updates
  /// only; such a gauge is removed once a tile change next to it brings its tile near the
  /// catchment, and is used as it is if it reports again.)
  int RemovalsDeferred = 0;
  std::vector<std::int32_t> Gauges; ///< weighted gauges, ascending
  std::vector<double> Weights;      ///< per weighted gauge
  std::vector<double> AreasM2;      ///< per weighted gauge: clipped ellipsoidal area, m^2
};

/// The clipped tiles of the current step, for display, in lon/lat: each tile's part of the
/// catchment as pieces that are simple polygons without holes (x-monotone, display_pieces.h): one
/// for most tiles, several for a part with a hole or lobes joined only at the tile's edge. Each
/// is a fan about its first vertex in lon/lat: a piece bent so that no vertex sees it whole is
/// split along diagonals (fan_diagonals.h; up to 64 parts, each measured in the plane, their
/// areas scaled to the piece's), and only a part for which no diagonal is found is left as it
/// is (3 of 36,492 pieces under a noisy outline of 10^5 vertices; none in Colorado's tiles). A
/// tile's pieces do not overlap and their areas add up to its clipped area.
struct ClippedTilesLonLat
{
  std::vector<std::int32_t> Gauges;               ///< one entry per tile with a non-empty clip
  std::vector<std::size_t> TilePieceOffsets{ 0 }; ///< pieces of tile k: [k], [k+1]
  ClippedRings Pieces;                            ///< one ring per piece, lon/lat degrees
  std::vector<double> PieceAreasM2; ///< per piece: ellipsoidal area, m^2, measured as weights are
  /// The same parts of the catchment as polygons with holes, for a GIS (piece_outlines.h): tile
  /// k's are polygons TileOutlineOffsets[k] .. TileOutlineOffsets[k + 1] - 1 of Outlines, joined
  /// from its pieces in lon/lat (one polygon for most tiles; a polygon with a hole for a tile
  /// round a lake, several for lobes across a bay). Their edges are the pieces' outer edges,
  /// vertex for vertex, so neighbouring tiles' outlines share their borders as the pieces do (to
  /// rounding). A tile across the 180th meridian is cut there (meridian_cut.h): each polygon lies
  /// on one side of it (a tile whose border runs along the meridian to rounding, as between two
  /// gauges mirrored across it, can leave a sliver some 1e-12 degrees wide beyond it).
  std::vector<std::size_t> TileOutlineOffsets{ 0 };
  RegionOutlines Outlines;
};

/// Threads: separate objects may be used on separate threads; one object's const methods
/// (CurrentClippedTiles, GaugesUsed, ...) may be called from several threads at once while no
/// thread calls Step or another non-const method.
class ThiessenArealAverage
{
public:
  /// gaugesLonLat: one point per gauge (id = index). Throws InputError naming the gauge (by index
  /// and, given settings.GaugeNames, by name) for a NaN/Inf coordinate, |latitude| > 90,
  /// |longitude| > 360 or a place the projection cannot represent, and naming the ring and vertex
  /// for a catchment vertex out of those ranges. The catchment: rings in lon/lat (flat offsets,
  /// even-odd rule); throws InputError naming ring, vertex or segments when a ring is degenerate or
  /// self-intersecting or two rings cross. Gauges at one place (within CoLocatedMetres; a gauge
  /// at a pole is at the pole whatever its longitude) are grouped: at each step the first of a
  /// group that reported is used (see DuplicateGauges).
  ThiessenArealAverage(const std::vector<Point2>& gaugesLonLat,
    const std::vector<std::size_t>& catchmentRingOffsets,
    const std::vector<Point2>& catchmentLonLat,
    const ArealAverageSettings& settings = {});
  ~ThiessenArealAverage();
  ThiessenArealAverage(const ThiessenArealAverage&) = delete;
  ThiessenArealAverage& operator=(const ThiessenArealAverage&) = delete;

  const ProjectionParameters& Projection() const;
  AreaMethod Method() const;
  /// (gauge, first gauge at the same place) for every gauge at the place of an earlier one
  /// (within CoLocatedMetres of it, or of another gauge of that place).
  const std::vector<std::pair<std::int32_t, std::int32_t>>& DuplicateGauges() const;
  /// Per gauge, 1 when Step would use its value among these values (NaN: missing): it reported,
  /// and no gauge at its place with a smaller index did.
  std::vector<char> GaugesUsed(const std::vector<double>& values) const;
  /// The catchment's ellipsoidal area, m^2, measured as the tiles are.
  double CatchmentAreaM2() const;
  /// How many catchment vertices lay within SharedBorderDegrees of another ring's edge and were
  /// made vertices of it too (snap_to_segments.h): T-junctions of shared sub-basin borders,
  /// written with rounded coordinates, which made the rings cross.
  std::size_t CatchmentVerticesPutOnEdges() const;
  /// Projected gauge positions (metres).
  const std::vector<Point2>& ProjectedGauges() const;
  /// Whether gauge g lies inside the catchment (even-odd; on its boundary: either answer). An
  /// InputError naming g when there is no gauge g.
  bool GaugeInsideCatchment(std::size_t g) const;
  /// The catchment rings (numbered as given) that enclose ring r, ascending: r is a hole when
  /// their number is odd. An InputError naming r when there is no ring r.
  std::vector<std::int32_t> CatchmentRingsAround(std::size_t r) const;

  /// Advances to a step: values[g] is gauge g's value, NaN where it did not report. Throws
  /// InputError if values has the wrong size or an infinite value (naming the gauge as above).
  ArealStep Step(const std::vector<double>& values);

  /// The current step's clipped tiles in lon/lat, edges densified every maxStepMetres (projected)
  /// so that they follow the planar tile edges when drawn in lon/lat. maxStepMetres: finite and
  /// at least ArealAverageSettings::MinGeodesicStepMetres, else an InputError naming it. Made on
  /// the machine's cores (TESSERA_THREADS, parallel_chunks.h), the same bits on any number.
  ClippedTilesLonLat CurrentClippedTiles(double maxStepMetres = 2000.0) const;

private:
  struct State;
  std::unique_ptr<State> Impl;
};

} // namespace tessera
