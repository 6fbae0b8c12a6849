#pragma once
// Geographic coordinates (longitude, latitude in degrees on WGS84) to a plane and back, with
// GeographicLib; the projection chosen from the data's extent; densification of edges that are
// straight in lon/lat (RFC 7946); ellipsoidal polygon areas.
//
// Longitudes are never assumed to lie in [-180, 180]: the data's longitudes are treated as angles,
// the extent is the shortest arc that holds them all (so a set crossing the antimeridian, such as
// 177..181.6, has a 4.6 degree extent, not 358), and Inverse returns longitudes within 180 degrees
// of the central meridian, so data that crossed the antimeridian comes back continuous.

#include "errors.h" // InputError, which the functions below throw
#include "geometry.h"

#include <string>
#include <vector>

namespace tessera
{

enum class ProjectionKind
{
  AlbersEqualArea,
  LambertConformalConic,
  TransverseMercator,
  UTM,
  AzimuthalEquidistant,
  LambertAzimuthalEqualArea,
  Mercator,   ///< on the ellipsoid, scale 1 on the equator (EPSG:3395 about lon0 0)
  WebMercator ///< WGS84 latitudes by the sphere's formulas (EPSG:3857 about lon0 0)
};

/// Every kind, in the enum's order: a record's name is read by it (FromString), and the VTK
/// filter's Projection values after Automatic follow it.
constexpr ProjectionKind ProjectionKinds[] = { ProjectionKind::AlbersEqualArea,
  ProjectionKind::LambertConformalConic,
  ProjectionKind::TransverseMercator,
  ProjectionKind::UTM,
  ProjectionKind::AzimuthalEquidistant,
  ProjectionKind::LambertAzimuthalEqualArea,
  ProjectionKind::Mercator,
  ProjectionKind::WebMercator };

const char* ProjectionKindName(ProjectionKind kind);
/// Whether a projection keeps areas (the two equal-area ones: Albers, Lambert azimuthal), so
/// that plane areas are ellipsoidal areas.
bool KeepsAreas(ProjectionKind kind);

/// Everything needed to repeat a projection. Unused fields are ignored by a kind
/// (e.g. StandardParallel1/2 only matter to the two conics).
struct ProjectionParameters
{
  ProjectionKind Kind = ProjectionKind::AlbersEqualArea;
  double CentralLongitude = 0.0;  ///< central meridian (all but UTM, whose zone has its own)
  double CentralLatitude = 0.0;   ///< centre latitude of the azimuthal projections
  double StandardParallel1 = 0.0; ///< conics
  double StandardParallel2 = 0.0; ///< conics
  int UTMZone = 0;                ///< 1..60 for UTM
  bool UTMNorth = true;           ///< UTM hemisphere (false northing 0 in the north, 1e7 m south)

  /// The grid a projected coordinate system lays on the plane above (PROJ's +x_0, +y_0, +k_0,
  /// +lat_0; EPSG's false easting and northing, scale factor at the natural origin and latitude of
  /// natural origin): grid x = ScaleFactor * (x - x_O) + FalseEasting, and alike for y, where
  /// (x_O, y_O) is the plane's image of (CentralLongitude, OriginLatitude) when HasOriginLatitude,
  /// else (0, 0): each plane's own origin, which for the conics is a latitude GeographicLib
  /// chooses between the standard parallels (EPSG:5070, the USGS Albers, puts it at 23 N, so its
  /// northings need OriginLatitude 23). The defaults leave the plane as it is. An origin latitude
  /// is read by the conics, the transverse Mercator and the Mercators only: UTM has its own grid,
  /// and the azimuthal projections' origin is their centre (CentralLatitude). The grid applies on
  /// top of UTM's false easting and northing and scale. Records write these keys only when they
  /// differ from the defaults, so a record without them is a plane without a grid.
  double FalseEasting = 0.0;  ///< metres (record key x0)
  double FalseNorthing = 0.0; ///< metres (record key y0)
  double ScaleFactor = 1.0;   ///< 0.1 to 10 (record key k0)
  bool HasOriginLatitude = false;
  double OriginLatitude = 0.0; ///< degrees, with HasOriginLatitude (record key origin_lat)
  /// Whether the grid terms leave the plane as it is (all at their defaults).
  bool PlaneWithoutGrid() const;

  /// A one-line "key=value" record, exact to the last bit (%.17g), e.g.
  /// "projection=AlbersEqualArea lon0=-105.5 lat0=39 lat1=37.33 lat2=40.67 zone=0 north=1",
  /// followed by the grid's keys that differ from the defaults (" x0=... y0=... k0=...
  /// origin_lat=...").
  std::string ToString() const;
  /// Parses ToString's format; throws InputError naming the bad key or value.
  static ProjectionParameters FromString(const std::string& text);
};

/// Throws InputError naming a grid term out of range (FalseEasting, FalseNorthing within 1e8 m,
/// ScaleFactor within 0.1 to 10, OriginLatitude a latitude), or an origin latitude set for a kind
/// whose origin is fixed (UTM, the azimuthal projections). GeographicProjection checks them; this
/// is for a caller that has a grid but no projection to make (no points to fit one to).
void CheckGridTerms(const ProjectionParameters& p);

/// Whether areas in the projection's grid are areas on the ellipsoid: an equal-area kind
/// (KeepsAreas) whose grid keeps scale 1.
bool KeepsAreas(const ProjectionParameters& parameters);

/// Whether two projections map every point alike: the same kind, and the same values of the
/// fields that kind uses (records of one projection may differ in the others, e.g. lat0 of a
/// conic fitted to the data and of one given by hand).
bool SameProjection(const ProjectionParameters& a, const ProjectionParameters& b);

/// The shortest longitude arc holding every longitude, and the latitude range.
struct GeographicExtent
{
  double WestLongitude = 0.0; ///< start of the arc; East = West + LongitudeSpan
  double LongitudeSpan = 0.0; ///< in [0, 360)
  double SouthLatitude = 0.0;
  double NorthLatitude = 0.0;
  double CentralLongitude() const { return this->WestLongitude + 0.5 * this->LongitudeSpan; }
  double CentralLatitude() const { return 0.5 * (this->SouthLatitude + this->NorthLatitude); }
};

/// Whether p is a longitude within -360 .. 360 degrees and a latitude within -90 .. 90 (false for
/// NaN). Wider longitudes are typos (-1031.5 for -103.15): a gauge would wrap round the globe, a
/// catchment span some 10^6 km^2, and one of 1e20 has no digit left below a turn of the globe.
bool InLonLatRange(const Point2& p);
/// What is wrong with p as a longitude/latitude: "a NaN or infinite coordinate", "a latitude
/// beyond 90 degrees" (asking whether the two are swapped where the longitude would be a valid
/// latitude and the latitude a longitude) or "a longitude beyond 360 degrees"; empty when it is
/// InLonLatRange.
std::string LonLatFault(const Point2& p);
/// Throws InputError naming the first point with a NaN/Inf coordinate or out of InLonLatRange.
void ValidateLonLat(const std::vector<Point2>& lonlat);

/// Whether a finite p has a coordinate of 10^4 or more: metres of a projection (UTM's eastings
/// run 1.6e5 to 8.4e5), not degrees.
bool LooksProjected(const Point2& p);
/// For a finite point out of the lon/lat ranges: ": these look like projected coordinates ..."
/// when a coordinate is 10^4 or more (metres of a projection, as UTM's eastings of 1.6e5 to
/// 8.4e5, fed as degrees), else "" (-1031.5 is a typo of -103.15, not metres). Appended to the
/// errors that name such a point.
std::string ProjectedCoordinatesNote(const Point2& p);
/// Extent of valid lon/lat points (validated first). Throws InputError if there are none.
GeographicExtent ComputeExtent(const std::vector<Point2>& lonlat);

/// Centre and standard parallels from the data: the central meridian at the middle of the
/// longitude arc, the centre latitude at the middle of the latitude range, standard parallels at
/// 1/6 and 5/6 of the latitude span, the UTM zone of the central meridian and the hemisphere of
/// the centre latitude.
ProjectionParameters ParametersFromExtent(ProjectionKind kind, const GeographicExtent& extent);
/// The automatic choice: an Albers equal-area conic with ParametersFromExtent.
ProjectionParameters AutomaticParameters(const std::vector<Point2>& lonlat);

/// UTM zone (1..60) whose central meridian is nearest to a longitude; InputError when it is not
/// finite.
int UTMZoneOfLongitude(double longitude);

class GeographicProjection
{
public:
  /// Throws InputError for parameters out of range (a NaN, a latitude beyond 90, a UTM zone
  /// outside 1..60, conic standard parallels at opposite poles).
  explicit GeographicProjection(const ProjectionParameters& parameters);
  ~GeographicProjection();
  GeographicProjection(const GeographicProjection&) = delete;
  GeographicProjection& operator=(const GeographicProjection&) = delete;

  const ProjectionParameters& Parameters() const { return this->Params; }
  /// The central meridian, degrees (a UTM zone's own for UTM).
  double CentralMeridian() const;

  /// lon/lat (degrees) to x/y (metres), in the parameters' grid. Throws InputError naming `id` and
  /// the value when the point is invalid or the projection cannot represent it (e.g. a transverse
  /// Mercator point more than 45 degrees of longitude from the central meridian, a UTM point more
  /// than 500 km from its zone's meridian, or any point whose projected coordinate exceeds 1e8 m: a
  /// singularity such as the Lambert cone's far pole).
  Point2 Forward(const Point2& lonlat, long long id = -1) const;
  /// x/y (metres) to lon/lat; longitude within 180 degrees of the central meridian (beyond 360
  /// east of a meridian beyond 180: vtkGeographicProjection moves such a data set a turn west,
  /// whole, and an automatic meridian keeps the data's own longitudes within 360). Throws
  /// InputError naming `id` and the value for a point no place projects to (one whose place would
  /// not project back to it: an Albers point past the pole's arc, a transverse Mercator point
  /// beyond 45 degrees of the central meridian).
  Point2 Inverse(const Point2& xy, long long id = -1) const;
  /// Inverse without the test that the place projects back, for points known to have one: those
  /// within a polygon of projected places (a catchment's clipped tiles), where the test would
  /// double the cost. Still throws for a NaN point or one beyond 1e8 m.
  Point2 InverseOfImage(const Point2& xy, long long id = -1) const;

private:
  /// Throws InputError naming the point when the forward projection of its inverse, lonlat, does
  /// not come back to grid: it lies past the projection's edge.
  void CheckProjectsBack(const Point2& grid, const Point2& lonlat, long long id) const;
  /// The plane's image of the grid's origin, (CentralLongitude, OriginLatitude); throws
  /// InputError naming origin_lat where the projection has no place for it.
  Point2 OriginInPlane() const;

  struct Engines;
  ProjectionParameters Params;
  Engines* Impl = nullptr;
};

/// The most pieces DensifiedPieceCount cuts an edge into: an absurdly fine step is capped
/// rather than allowed to exhaust memory.
constexpr int MaxDensifiedPieces = 1000000;

/// Number of equal pieces an edge from a to b (lon/lat, the shorter way round in longitude) is cut
/// into so that no piece is longer than maxStep degrees (in the lon/lat plane). maxStep <= 0 or
/// non-finite means no densification (1 piece).
/// With capped, also says whether the count was cut down to MaxDensifiedPieces.
/// With asWritten, the longitudes' difference is taken as written, not the shorter way round: for
/// places that are continuous as written, as an inverse's are about its meridian (a plane edge
/// whose ends come back 240 degrees apart spans 240, not 120).
int DensifiedPieceCount(const Point2& a,
  const Point2& b,
  double maxStep,
  bool* capped = nullptr,
  bool asWritten = false);
/// DensifiedPieceCount's count before the cap, as a double (at least 1): for a caller that limits
/// the pieces of many edges in all, and names how many it would take.
double WantedPieceCount(const Point2& a, const Point2& b, double maxStep, bool asWritten = false);
/// Whether the edge from a to b (lon/lat) can be read two ways round the globe: its longitudes
/// differ by 180 to 270 degrees as written, so straight in lon/lat (RFC 7946) it spans that much,
/// and the shorter way round (DensifiedPieceCount, InterpolateLonLat) 90 to 180 degrees the other
/// way; both are plausible and they are different lines (a box from -100 to 100 becomes one from
/// 100 to 260). Beyond 270 degrees the shorter way is meant (179 to -179 across the 180th
/// meridian, 359.5 to 0.5 in 0 .. 360 data); below 180 the two readings agree.
bool EdgeReadsBothWays(const Point2& a, const Point2& b);
/// The point a fraction t along the lon/lat-straight edge from a to b (longitude taken the shorter
/// way round, continuing from a's longitude, so it may leave [-180, 180]).
Point2 InterpolateLonLat(const Point2& a, const Point2& b, double t);

/// The rings (offsets into lonlat, as a catchment gives them) with their longitudes in one turn of
/// the globe as their edges are read: each vertex moved by whole turns of 360 degrees into the
/// turn that starts at the meridian halfway across the widest gap between the vertices'
/// longitudes. A ring that jumps the 180th meridian (179.5 to -179.6, as DensifiedPieceCount reads
/// it) then runs on past it (to 180.4), so that a test made on the lon/lat coordinates (a ring
/// crossing itself) sees the edges that are meant, not one across the whole map. A vertex already
/// in that turn is kept bit for bit, and equal vertices stay equal (rings sharing a boundary keep
/// sharing it). Unchanged when the vertices leave no gap wider than 180 degrees. Throws InputError
/// naming a ring whose edges, read so, turn through 360 degrees of longitude: it goes round a
/// pole, and no conic projection holds a catchment containing one; and naming an offset that does
/// not fit the vertices (CheckRingOffsets, polygon_validation.h).
std::vector<Point2> RingsInOneTurn(const std::vector<std::size_t>& offsets,
  const std::vector<Point2>& lonlat);

/// Area in square metres of a ring of lon/lat vertices on WGS84, joined by geodesics (GeographicLib
/// PolygonArea); densify edges first where they should follow parallels. Positive for
/// anticlockwise rings, negative for clockwise.
double EllipsoidalRingArea(const std::vector<Point2>& lonlat);

} // namespace tessera
