#include "geo.h"

#include "errors.h"
#include "lambert_azimuthal_equal_area.h"
#include "mercator.h"
#include "polygon_validation.h"

#include <GeographicLib/AlbersEqualArea.hpp>
#include <GeographicLib/AzimuthalEquidistant.hpp>
#include <GeographicLib/Constants.hpp>
#include <GeographicLib/Geodesic.hpp>
#include <GeographicLib/LambertConformalConic.hpp>
#include <GeographicLib/PolygonArea.hpp>
#include <GeographicLib/TransverseMercator.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <sstream>

namespace tessera
{
namespace
{

// Transverse Mercator (GeographicLib's series, 5 nm accurate within 3900 km of the central
// meridian) degrades far from it: beyond this many degrees of longitude a point is refused.
constexpr double TransverseMercatorMaxLongitudeOffset = 45.0;
// UTM eastings are valid in [0, 1000 km] (GeographicLib's UTMUPS range).
constexpr double UTMFalseEasting = 500000.0;
constexpr double UTMMaxEastingOffset = 500000.0;
constexpr double UTMSouthFalseNorthing = 10000000.0;
constexpr double UTMScale = 0.9996;
// A projected coordinate beyond 2.5 Earth circumferences means the point sits at (or next to) a
// singularity of the projection, such as the far pole of a Lambert cone: refused, not returned.
constexpr double MaxProjectedMagnitude = 1.0e8;
// How far the forward projection of an inverse may land from the point inverted (GeographicLib's
// and the Mercators' round trips are good to nanometres): beyond, the point lies past the
// projection's edge (an Albers point past the pole's arc, a transverse Mercator easting of 3e7 m),
// whose inverse GeographicLib still gives as a place (a pole, a meridian 90 degrees away).
constexpr double InverseRoundTripMetres = 1e-3;
// How near a projection's edge (the transverse Mercator's 45 degrees, a conic's cut) an inverse's
// longitude counts as on it: its rounding is some ulps of 180.
constexpr double EdgeDegrees = 1e-9;
// The scale factors a grid may have (ProjectionParameters::ScaleFactor).
constexpr double MinGridScale = 0.1;
constexpr double MaxGridScale = 10.0;

/// A distance to a tenth ("683.3"): NumberText's 17 digits are noise in a message.
std::string TenthsText(double value)
{
  char text[64];
  std::snprintf(text, sizeof text, "%.1f", value);
  return text;
}

std::string DescribePoint(const char* what, long long id, const Point2& p)
{
  std::string text = what;
  if (id >= 0)
  {
    text += ' ' + std::to_string(id);
  }
  return text + " (" + NumberText(p.x) + ", " + NumberText(p.y) + ")";
}

/// Signed difference b - a of two longitudes, in [-180, 180).
double LongitudeDifference(double a, double b)
{
  double d = std::remainder(b - a, 360.0);
  if (d >= 180.0)
  {
    d -= 360.0;
  }
  return d;
}

/// The longitude x as one value in (-180, 180], exactly (IEEE remainder is exact): 181.5 and
/// -178.5, or 180 and -180, become one number, so that whatever is computed from them next is the
/// same for both. (Reducing b - a instead rounded the difference first: the two copies of a place
/// projected some 1e-9 m apart and were not found duplicates.)
double CanonicalLongitude(double x)
{
  const double r = std::remainder(x, 360.0);
  return r == -180.0 ? 180.0 : r;
}

bool IsValidLatitude(double lat)
{
  return std::isfinite(lat) && std::abs(lat) <= 90.0;
}

} // namespace

const char* ProjectionKindName(ProjectionKind kind)
{
  switch (kind)
  {
    case ProjectionKind::AlbersEqualArea:
      return "AlbersEqualArea";
    case ProjectionKind::LambertConformalConic:
      return "LambertConformalConic";
    case ProjectionKind::TransverseMercator:
      return "TransverseMercator";
    case ProjectionKind::UTM:
      return "UTM";
    case ProjectionKind::AzimuthalEquidistant:
      return "AzimuthalEquidistant";
    case ProjectionKind::LambertAzimuthalEqualArea:
      return "LambertAzimuthalEqualArea";
    case ProjectionKind::Mercator:
      return "Mercator";
    case ProjectionKind::WebMercator:
      return "WebMercator";
  }
  return "Unknown";
}

bool KeepsAreas(ProjectionKind kind)
{
  return kind == ProjectionKind::AlbersEqualArea ||
    kind == ProjectionKind::LambertAzimuthalEqualArea;
}

bool ProjectionParameters::PlaneWithoutGrid() const
{
  return this->FalseEasting == 0.0 && this->FalseNorthing == 0.0 && this->ScaleFactor == 1.0 &&
    !this->HasOriginLatitude;
}

bool KeepsAreas(const ProjectionParameters& parameters)
{
  return KeepsAreas(parameters.Kind) && parameters.ScaleFactor == 1.0;
}

namespace
{
bool SameGrid(const ProjectionParameters& a, const ProjectionParameters& b)
{
  return a.FalseEasting == b.FalseEasting && a.FalseNorthing == b.FalseNorthing &&
    a.ScaleFactor == b.ScaleFactor && a.HasOriginLatitude == b.HasOriginLatitude &&
    (!a.HasOriginLatitude || a.OriginLatitude == b.OriginLatitude);
}

/// The record's grid keys, those that differ from the defaults (" x0=4321000 y0=3210000").
std::string GridText(const ProjectionParameters& p)
{
  std::string text;
  if (p.FalseEasting != 0.0)
    text += " x0=" + NumberText(p.FalseEasting);
  if (p.FalseNorthing != 0.0)
    text += " y0=" + NumberText(p.FalseNorthing);
  if (p.ScaleFactor != 1.0)
    text += " k0=" + NumberText(p.ScaleFactor);
  if (p.HasOriginLatitude)
    text += " origin_lat=" + NumberText(p.OriginLatitude);
  return text;
}
} // namespace

bool SameProjection(const ProjectionParameters& a, const ProjectionParameters& b)
{
  if (a.Kind != b.Kind || !SameGrid(a, b))
  {
    return false;
  }
  switch (a.Kind)
  {
    case ProjectionKind::AlbersEqualArea:
    case ProjectionKind::LambertConformalConic:
      return a.CentralLongitude == b.CentralLongitude &&
        a.StandardParallel1 == b.StandardParallel1 && a.StandardParallel2 == b.StandardParallel2;
    case ProjectionKind::TransverseMercator:
    case ProjectionKind::Mercator:
    case ProjectionKind::WebMercator:
      return a.CentralLongitude == b.CentralLongitude;
    case ProjectionKind::UTM:
      return a.UTMZone == b.UTMZone && a.UTMNorth == b.UTMNorth;
    case ProjectionKind::AzimuthalEquidistant:
    case ProjectionKind::LambertAzimuthalEqualArea:
      return a.CentralLongitude == b.CentralLongitude && a.CentralLatitude == b.CentralLatitude;
  }
  return false;
}

std::string ProjectionParameters::ToString() const
{
  return std::string("projection=") + ProjectionKindName(this->Kind) +
    " lon0=" + NumberText(this->CentralLongitude) + " lat0=" + NumberText(this->CentralLatitude) +
    " lat1=" + NumberText(this->StandardParallel1) +
    " lat2=" + NumberText(this->StandardParallel2) + " zone=" + std::to_string(this->UTMZone) +
    " north=" + (this->UTMNorth ? "1" : "0") + GridText(*this);
}

namespace
{
/// A record, or a part of one, as a message quotes it: in full, or its first 120 characters and
/// how long it is (a record of 10^5 characters was echoed whole).
std::string Quoted(const std::string& text)
{
  constexpr std::size_t shown = 120;
  return text.size() <= shown
    ? "'" + text + "'"
    : "'" + text.substr(0, shown) + "...' (" + std::to_string(text.size()) + " characters)";
}

/// Throws InputError unless the record gives the parameters its projection needs: a missing one
/// was 0 without a word ("projection=AlbersEqualArea" alone made standard parallels at the
/// equator, and a point of Colorado 11700 km from the origin). UTM needs its zone (north defaults
/// to 1), the conics their central meridian and standard parallels, the others their centre.
void CheckRecordComplete(const std::string& text,
  ProjectionKind kind,
  const std::vector<std::string>& seen)
{
  std::vector<const char*> needed;
  switch (kind)
  {
    case ProjectionKind::AlbersEqualArea:
    case ProjectionKind::LambertConformalConic:
      needed = { "lon0", "lat1", "lat2" };
      break;
    case ProjectionKind::TransverseMercator:
    case ProjectionKind::Mercator:
    case ProjectionKind::WebMercator:
      needed = { "lon0" };
      break;
    case ProjectionKind::UTM:
      needed = { "zone" };
      break;
    case ProjectionKind::AzimuthalEquidistant:
    case ProjectionKind::LambertAzimuthalEqualArea:
      needed = { "lon0", "lat0" };
      break;
  }
  std::string missing;
  for (const char* key : needed)
  {
    if (std::find(seen.begin(), seen.end(), key) == seen.end())
    {
      missing += (missing.empty() ? "" : ", ") + std::string(key);
    }
  }
  if (!missing.empty())
  {
    throw InputError("projection record " + Quoted(text) + " lacks " + missing + ", which " +
      ProjectionKindName(kind) + " needs");
  }
}
/// A record's value as a finite number, else an InputError naming key and value.
double RecordNumber(const std::string& key, const std::string& value)
{
  char* end = nullptr;
  const double v = std::strtod(value.c_str(), &end);
  if (value.empty() || *end != '\0' || !std::isfinite(v))
  {
    // (nan and inf parse as numbers: lon0=nan was taken, and failed later elsewhere)
    throw InputError("projection record: " + key + "=" + Quoted(value) + " is not a finite number");
  }
  return v;
}

ProjectionKind RecordKind(const std::string& value)
{
  for (const ProjectionKind kind : ProjectionKinds)
  {
    if (value == ProjectionKindName(kind))
    {
      return kind;
    }
  }
  throw InputError("projection record: unknown projection " + Quoted(value));
}

int RecordZone(const std::string& value)
{
  const double zone = RecordNumber("zone", value);
  if (zone != std::floor(zone) || zone < 0.0 || zone > 60.0)
  {
    // (a cast of 1e20 to int was -2147483648)
    throw InputError("projection record: zone=" + Quoted(value) + " is not a UTM zone (0 to 60)");
  }
  return static_cast<int>(zone);
}

/// Sets the field that key names (but the projection's kind) from value.
void SetRecordField(ProjectionParameters& p, const std::string& key, const std::string& value)
{
  const auto number = [&]() { return RecordNumber(key, value); };
  if (key == "lon0")
    p.CentralLongitude = number();
  else if (key == "lat0")
    p.CentralLatitude = number();
  else if (key == "lat1")
    p.StandardParallel1 = number();
  else if (key == "lat2")
    p.StandardParallel2 = number();
  else if (key == "zone")
    p.UTMZone = RecordZone(value);
  else if (key == "north")
    p.UTMNorth = number() != 0.0;
  else if (key == "x0")
    p.FalseEasting = number();
  else if (key == "y0")
    p.FalseNorthing = number();
  else if (key == "k0")
    p.ScaleFactor = number();
  else if (key == "origin_lat")
  {
    p.HasOriginLatitude = true;
    p.OriginLatitude = number();
  }
  else
    throw InputError("projection record: unknown key " + Quoted(key));
}

} // namespace

ProjectionParameters ProjectionParameters::FromString(const std::string& text)
{
  ProjectionParameters result;
  std::istringstream in(text);
  std::string item;
  bool sawKind = false;
  std::vector<std::string> seen; // keys given, each once
  while (in >> item)
  {
    const auto equals = item.find('=');
    if (equals == std::string::npos)
    {
      throw InputError("projection record: " + Quoted(item) + " is not key=value");
    }
    const std::string key = item.substr(0, equals);
    const std::string value = item.substr(equals + 1);
    if (std::find(seen.begin(), seen.end(), key) != seen.end())
    {
      // (the later one won: zone=13 zone=14 projected in zone 14 without a word)
      throw InputError("projection record " + Quoted(text) + " gives " + key + " twice");
    }
    seen.push_back(key);
    if (key == "projection")
    {
      result.Kind = RecordKind(value);
      sawKind = true;
    }
    else
    {
      SetRecordField(result, key, value);
    }
  }
  if (!sawKind)
  {
    throw InputError("projection record " + Quoted(text) + " names no projection");
  }
  CheckRecordComplete(text, result.Kind, seen);
  return result;
}

bool InLonLatRange(const Point2& p)
{
  return std::abs(p.y) <= 90.0 && std::abs(p.x) <= 360.0;
}

std::string LonLatFault(const Point2& p)
{
  if (!std::isfinite(p.x) || !std::isfinite(p.y))
  {
    return "a NaN or infinite coordinate";
  }
  if (std::abs(p.y) > 90.0)
  {
    // (a longitude that would be a valid latitude: a file of lat, lon read as lon, lat)
    return std::abs(p.x) <= 90.0 && std::abs(p.y) <= 180.0
      ? "a latitude beyond 90 degrees (are longitude and latitude swapped?)"
      : "a latitude beyond 90 degrees";
  }
  return std::abs(p.x) > 360.0 ? "a longitude beyond 360 degrees" : std::string();
}

void ValidateLonLat(const std::vector<Point2>& lonlat)
{
  for (std::size_t i = 0; i < lonlat.size(); ++i)
  {
    const std::string fault = LonLatFault(lonlat[i]);
    if (!fault.empty())
    {
      throw InputError(DescribePoint("point", static_cast<long long>(i), lonlat[i]) + " has " +
        fault + ProjectedCoordinatesNote(lonlat[i]));
    }
  }
}

bool LooksProjected(const Point2& p)
{
  return std::isfinite(p.x) && std::isfinite(p.y) && (std::abs(p.x) >= 1e4 || std::abs(p.y) >= 1e4);
}

std::string ProjectedCoordinatesNote(const Point2& p)
{
  return LooksProjected(p)
    ? ": these look like projected coordinates (metres); give longitude and latitude "
      "in degrees (a projection's inverse gives them back)"
    : std::string();
}

GeographicExtent ComputeExtent(const std::vector<Point2>& lonlat)
{
  ValidateLonLat(lonlat);
  if (lonlat.empty())
  {
    throw InputError("no points to compute a geographic extent from");
  }
  GeographicExtent extent;
  extent.SouthLatitude = extent.NorthLatitude = lonlat[0].y;
  std::vector<double> longitudes;
  longitudes.reserve(lonlat.size());
  for (const Point2& p : lonlat)
  {
    extent.SouthLatitude = std::min(extent.SouthLatitude, p.y);
    extent.NorthLatitude = std::max(extent.NorthLatitude, p.y);
    double lon = std::fmod(p.x, 360.0);
    longitudes.push_back(lon < 0.0 ? lon + 360.0 : lon);
  }
  std::sort(longitudes.begin(), longitudes.end());
  // The extent is the circle minus its largest empty gap between consecutive longitudes.
  std::size_t gapEnd = 0; // the longitude after the largest gap starts the arc
  double largestGap = longitudes.front() + 360.0 - longitudes.back();
  for (std::size_t i = 1; i < longitudes.size(); ++i)
  {
    const double gap = longitudes[i] - longitudes[i - 1];
    if (gap > largestGap)
    {
      largestGap = gap;
      gapEnd = i;
    }
  }
  double west = longitudes[gapEnd];
  if (west >= 180.0)
  {
    west -= 360.0;
  }
  if (west + (360.0 - largestGap) > 360.0)
  {
    // The arc would end beyond 360 degrees (data round the globe from 120 east: its centre at
    // 300), and the inverse, within 180 degrees of the centre, gave longitudes of 450 back.
    west -= 360.0;
  }
  extent.WestLongitude = west;
  extent.LongitudeSpan = std::max(0.0, 360.0 - largestGap);
  return extent;
}

int UTMZoneOfLongitude(double longitude)
{
  if (!std::isfinite(longitude))
  {
    // (Cast from NaN to int, the zone was -2147483647.)
    throw InputError("longitude " + NumberText(longitude) + " has no UTM zone: it is not finite");
  }
  double lon = std::fmod(longitude + 180.0, 360.0);
  if (lon < 0.0)
  {
    lon += 360.0;
  }
  return std::min(60, static_cast<int>(std::floor(lon / 6.0)) + 1);
}

ProjectionParameters ParametersFromExtent(ProjectionKind kind, const GeographicExtent& extent)
{
  ProjectionParameters p;
  p.Kind = kind;
  p.CentralLongitude = extent.CentralLongitude();
  p.CentralLatitude = extent.CentralLatitude();
  const double span = extent.NorthLatitude - extent.SouthLatitude;
  p.StandardParallel1 = extent.SouthLatitude + span / 6.0;
  p.StandardParallel2 = extent.SouthLatitude + 5.0 * span / 6.0;
  p.UTMZone = UTMZoneOfLongitude(p.CentralLongitude);
  p.UTMNorth = p.CentralLatitude >= 0.0;
  return p;
}

ProjectionParameters AutomaticParameters(const std::vector<Point2>& lonlat)
{
  return ParametersFromExtent(ProjectionKind::AlbersEqualArea, ComputeExtent(lonlat));
}

struct GeographicProjection::Engines
{
  std::unique_ptr<GeographicLib::AlbersEqualArea> Albers;
  std::unique_ptr<GeographicLib::LambertConformalConic> Lambert;
  std::unique_ptr<GeographicLib::TransverseMercator> Transverse;
  std::unique_ptr<GeographicLib::AzimuthalEquidistant> Azimuthal;
  std::unique_ptr<LambertAzimuthalEqualArea> AzimuthalEqualArea;
  std::unique_ptr<Mercator> Cylinder; // Mercator and Web Mercator
  double CentralMeridian = 0.0;       // for UTM: the zone's
  // GeographicLib 2.1's AlbersEqualArea given two southern standard parallels builds the
  // northern cone and flips y, which mirrors the map and puts the true-scale parallels in the
  // wrong hemisphere. A southern Albers is therefore computed as the northern one of the data
  // mirrored across the equator, mirrored back: (lon, lat) -> (lon, -lat) -> cone -> (x, -y).
  // Two reflections: orientation and areas are kept.
  bool MirrorAcrossEquator = false;
  bool Grid = false;   // whether the parameters lay a grid on the plane (PlaneWithoutGrid)
  Point2 GridOrigin{}; // the plane's image of the grid's origin, (x_O, y_O) in geo.h

  // The engines' parts of Forward and InverseOfImage, for the projection of parameters p.
  /// lonlat (valid; lon its longitude reduced about CentralMeridian) in p's plane, before the
  /// grid; throws InputError naming id where a transverse Mercator refuses it.
  Point2 ToPlane(const ProjectionParameters& p,
    const Point2& lonlat,
    double lon,
    long long id) const;
  /// ToPlane for TransverseMercator and UTM (with UTM's false easting and northing).
  Point2 TransverseToPlane(const ProjectionParameters& p,
    const Point2& lonlat,
    double lon,
    long long id) const;
  /// The place (lon, lat) of a point xy of p's plane, the grid undone; its longitude as the
  /// engine gives it, and NaN or infinite where xy is no image.
  Point2 ToLonLat(const ProjectionParameters& p, const Point2& xy) const;
  /// The constructor's: the engine of p's kind (BuildConic: the conics', on the WGS84 a, f).
  void Build(const ProjectionParameters& p);
  void BuildConic(const ProjectionParameters& p, double a, double f);
};

void CheckGridTerms(const ProjectionParameters& p)
{
  for (const auto& [key, value] : { std::make_pair("false easting x0", p.FalseEasting),
         std::make_pair("false northing y0", p.FalseNorthing) })
  {
    if (!(std::abs(value) <= MaxProjectedMagnitude))
    {
      // (a grid 1e9 m off holds no coordinate a file gives: a typo, or degrees for metres)
      throw InputError(std::string("the projection's ") + key + " = " + NumberText(value) +
        " is not within 1e8 m");
    }
  }
  if (!(p.ScaleFactor >= MinGridScale && p.ScaleFactor <= MaxGridScale))
  {
    // (1e301 made coordinates infinite, 1e-300 every place one point; a real system's scale is
    // within a few parts in a thousand of 1)
    throw InputError("the projection's scale factor k0 = " + NumberText(p.ScaleFactor) +
      " is not within " + NumberText(MinGridScale) + " to " + NumberText(MaxGridScale));
  }
  if (!p.HasOriginLatitude)
  {
    return;
  }
  if (!IsValidLatitude(p.OriginLatitude))
  {
    throw InputError("the projection's latitude of origin origin_lat = " +
      NumberText(p.OriginLatitude) + " is not a latitude in [-90, 90]");
  }
  if (p.Kind == ProjectionKind::UTM || p.Kind == ProjectionKind::AzimuthalEquidistant ||
    p.Kind == ProjectionKind::LambertAzimuthalEqualArea)
  {
    throw InputError(std::string("the projection's latitude of origin origin_lat: ") +
      ProjectionKindName(p.Kind) + " takes none (" +
      (p.Kind == ProjectionKind::UTM ? "a UTM zone's grid is fixed"
                                     : "its origin is its centre, lat0") +
      ")");
  }
}

namespace
{

void RequireLatitude(double lat, const char* name)
{
  if (!IsValidLatitude(lat))
  {
    throw InputError(std::string("projection parameter ") + name + " = " + NumberText(lat) +
      " is not a latitude in [-90, 90]");
  }
}

/// The centre every kind is given: lon0 and lat0.
void CheckCentre(const ProjectionParameters& p)
{
  if (!(std::fabs(p.CentralLongitude) <= 360.0))
  {
    // (1e20 was taken, and every x came out 0)
    throw InputError("projection parameter lon0 = " + NumberText(p.CentralLongitude) +
      " is not a longitude in [-360, 360]");
  }
  // (unused by the conics and UTM, but written into the record; 100 was taken there)
  RequireLatitude(p.CentralLatitude, "lat0");
}

} // namespace

void GeographicProjection::Engines::BuildConic(const ProjectionParameters& p, double a, double f)
{
  RequireLatitude(p.StandardParallel1, "lat1");
  RequireLatitude(p.StandardParallel2, "lat2");
  if (std::fabs(p.StandardParallel1) == 90.0 && p.StandardParallel2 == -p.StandardParallel1)
  {
    // (GeographicLib took them: every point then projected onto the apex, or off the map)
    throw InputError("conic standard parallels lat1 = " + NumberText(p.StandardParallel1) +
      " and lat2 = " + NumberText(p.StandardParallel2) + " lie at opposite poles");
  }
  if (p.Kind == ProjectionKind::AlbersEqualArea)
  {
    this->MirrorAcrossEquator = p.StandardParallel1 + p.StandardParallel2 < 0.0;
    const double sign = this->MirrorAcrossEquator ? -1.0 : 1.0;
    this->Albers.reset(new GeographicLib::AlbersEqualArea(
      a, f, sign * p.StandardParallel1, sign * p.StandardParallel2, 1.0));
  }
  else
  {
    this->Lambert.reset(new GeographicLib::LambertConformalConic(
      a, f, p.StandardParallel1, p.StandardParallel2, 1.0));
  }
}

// The GeographicLib (or own) engine of p's kind.
void GeographicProjection::Engines::Build(const ProjectionParameters& p)
{
  const double a = GeographicLib::Constants::WGS84_a();
  const double f = GeographicLib::Constants::WGS84_f();
  this->CentralMeridian = p.CentralLongitude;
  switch (p.Kind)
  {
    case ProjectionKind::AlbersEqualArea:
    case ProjectionKind::LambertConformalConic:
      this->BuildConic(p, a, f);
      break;
    case ProjectionKind::TransverseMercator:
      this->Transverse.reset(new GeographicLib::TransverseMercator(a, f, 1.0));
      break;
    case ProjectionKind::UTM:
      if (p.UTMZone < 1 || p.UTMZone > 60)
      {
        throw InputError("UTM zone " + std::to_string(p.UTMZone) + " is not in 1..60");
      }
      this->Transverse.reset(new GeographicLib::TransverseMercator(a, f, UTMScale));
      this->CentralMeridian = 6.0 * p.UTMZone - 183.0;
      break;
    case ProjectionKind::AzimuthalEquidistant:
      this->Azimuthal.reset(
        new GeographicLib::AzimuthalEquidistant(GeographicLib::Geodesic::WGS84()));
      break;
    case ProjectionKind::LambertAzimuthalEqualArea:
      this->AzimuthalEqualArea.reset(new LambertAzimuthalEqualArea(a, f, p.CentralLatitude));
      break;
    case ProjectionKind::Mercator:
    case ProjectionKind::WebMercator:
      this->Cylinder.reset(new Mercator(a, p.Kind == ProjectionKind::Mercator ? f : 0.0));
      break;
  }
}

GeographicProjection::GeographicProjection(const ProjectionParameters& parameters)
  : Params(parameters)
  , Impl(new Engines)
{
  const auto& p = parameters;
  try
  {
    // (Inside the try, whose handler deletes Impl: thrown before it, Impl leaked.)
    CheckCentre(p);
    Impl->Build(p);
    CheckGridTerms(p);
    if (p.HasOriginLatitude)
    {
      Impl->GridOrigin = this->OriginInPlane();
    }
    Impl->Grid = !p.PlaneWithoutGrid();
  }
  catch (const GeographicLib::GeographicErr& e)
  {
    delete Impl;
    throw InputError(std::string("projection ") + ProjectionKindName(p.Kind) +
      " cannot be built from '" + p.ToString() + "': " + e.what());
  }
  catch (...)
  {
    delete Impl;
    throw;
  }
}

GeographicProjection::~GeographicProjection()
{
  delete Impl;
}

void GeographicProjection::CheckProjectsBack(const Point2& grid,
  const Point2& lonlat,
  long long id) const
{
  // The azimuthal projections refuse what lies beyond their rims themselves (and near the
  // antipode their forward is too ill-conditioned for this test); the Mercators refuse what lies
  // beyond half a turn of the meridian, and every y of theirs is a latitude.
  if (Params.Kind != ProjectionKind::AlbersEqualArea &&
    Params.Kind != ProjectionKind::LambertConformalConic &&
    Params.Kind != ProjectionKind::TransverseMercator && Params.Kind != ProjectionKind::UTM)
  {
    return;
  }
  const double lon0 = Impl->CentralMeridian;
  const double offset = LongitudeDifference(lon0, lonlat.x);
  Point2 probe = lonlat;
  const bool transverse =
    Params.Kind == ProjectionKind::TransverseMercator || Params.Kind == ProjectionKind::UTM;
  if (transverse && std::abs(lonlat.y) > 90.0 - EdgeDegrees)
  {
    probe.x = lon0; // (the pole is one point, whose longitude the inverse may give as lon0 + 180)
  }
  Point2 back;
  try
  {
    back = this->Forward(probe);
  }
  catch (const InputError&)
  {
    back = { HUGE_VAL, HUGE_VAL }; // (beyond 45 degrees of a transverse Mercator's meridian)
  }
  // (a conic's cut, half a turn from the meridian, has two edges, and an inverse there may come
  // back some ulps to either side: its forward may land on the other edge)
  const bool onCut = std::abs(offset) > 180.0 - EdgeDegrees;
  const double mirroredX = 2.0 * Params.FalseEasting - back.x; // (about the meridian's x)
  if (!(std::hypot(back.x - grid.x, back.y - grid.y) <= InverseRoundTripMetres) &&
    !(onCut && std::hypot(mirroredX - grid.x, back.y - grid.y) <= InverseRoundTripMetres))
  {
    throw InputError(DescribePoint("point", id, grid) + " lies where no place projects in the " +
      ProjectionKindName(Params.Kind) + " projection: beyond its edge, its inverse (" +
      NumberText(lonlat.x) + ", " + NumberText(lonlat.y) + ") does not project back to it");
  }
}

Point2 GeographicProjection::OriginInPlane() const
{
  try
  {
    return this->Forward({ Impl->CentralMeridian, Params.OriginLatitude });
  }
  catch (const InputError& e)
  {
    // (the Lambert cone's far pole: its apex is at infinity)
    throw InputError("the projection's latitude of origin origin_lat = " +
      NumberText(Params.OriginLatitude) + " puts the grid's origin where the " +
      ProjectionKindName(Params.Kind) + " projection has no place: " + e.what());
  }
}

double GeographicProjection::CentralMeridian() const
{
  return Impl->CentralMeridian;
}

namespace
{

/// Throws InputError naming the point (by id) when lonlat is no place: a NaN or infinite
/// coordinate, or a latitude beyond 90 degrees.
void CheckPlaceToProject(const Point2& lonlat, long long id)
{
  if (!std::isfinite(lonlat.x) || !std::isfinite(lonlat.y) || std::abs(lonlat.y) > 90.0)
  {
    throw InputError(DescribePoint("point", id, lonlat) + " has " + LonLatFault(lonlat));
  }
}

} // namespace

Point2 GeographicProjection::Engines::TransverseToPlane(const ProjectionParameters& p,
  const Point2& lonlat,
  double lon,
  long long id) const
{
  const double lon0 = this->CentralMeridian;
  // (EdgeDegrees beyond: a point Forward made on the 45-degree edge may come back from the
  // inverse some ulps beyond it, and must project back)
  if (std::abs(lon - lon0) > TransverseMercatorMaxLongitudeOffset + EdgeDegrees)
  {
    throw InputError(DescribePoint("point", id, lonlat) + " is " +
      NumberText(std::abs(lon - lon0)) + " degrees of longitude from the central meridian " +
      NumberText(lon0) + "; " + ProjectionKindName(p.Kind) + " represents at most 45 degrees");
  }
  Point2 xy;
  this->Transverse->Forward(lon0, lonlat.y, lon, xy.x, xy.y);
  if (p.Kind == ProjectionKind::UTM)
  {
    if (std::abs(xy.x) > UTMMaxEastingOffset)
    {
      throw InputError(DescribePoint("point", id, lonlat) + " lies " +
        TenthsText(std::abs(xy.x) / 1000.0) + " km from the central meridian of UTM zone " +
        std::to_string(p.UTMZone) + "; UTM eastings stop at 500 km");
    }
    xy.x += UTMFalseEasting;
    xy.y += p.UTMNorth ? 0.0 : UTMSouthFalseNorthing;
  }
  return xy;
}

Point2 GeographicProjection::Engines::ToPlane(const ProjectionParameters& p,
  const Point2& lonlat,
  double lon,
  long long id) const
{
  const double lon0 = this->CentralMeridian;
  Point2 xy;
  switch (p.Kind)
  {
    case ProjectionKind::AlbersEqualArea:
      if (this->MirrorAcrossEquator)
      {
        this->Albers->Forward(lon0, -lonlat.y, lon, xy.x, xy.y);
        xy.y = -xy.y;
      }
      else
      {
        this->Albers->Forward(lon0, lonlat.y, lon, xy.x, xy.y);
      }
      break;
    case ProjectionKind::LambertConformalConic:
      this->Lambert->Forward(lon0, lonlat.y, lon, xy.x, xy.y);
      break;
    case ProjectionKind::TransverseMercator:
    case ProjectionKind::UTM:
      xy = this->TransverseToPlane(p, lonlat, lon, id);
      break;
    case ProjectionKind::AzimuthalEquidistant:
      this->Azimuthal->Forward(p.CentralLatitude, lon0, lonlat.y, lon, xy.x, xy.y);
      break;
    case ProjectionKind::LambertAzimuthalEqualArea:
      this->AzimuthalEqualArea->Forward(lon0, lonlat.y, lon, xy.x, xy.y);
      break;
    case ProjectionKind::Mercator:
    case ProjectionKind::WebMercator:
      this->Cylinder->Forward(lon0, lonlat.y, lon, xy.x, xy.y);
      break;
  }
  return xy;
}

Point2 GeographicProjection::Forward(const Point2& lonlat, long long id) const
{
  CheckPlaceToProject(lonlat, id);
  const double lon0 = Impl->CentralMeridian;
  // Reduce first so that a longitude of 181.6 and one of -178.4 project to the same place.
  const double lon = lon0 + LongitudeDifference(lon0, CanonicalLongitude(lonlat.x));
  const Point2 xy = Impl->ToPlane(Params, lonlat, lon, id);
  if (!(std::abs(xy.x) <= MaxProjectedMagnitude) || !(std::abs(xy.y) <= MaxProjectedMagnitude))
  {
    throw InputError(DescribePoint("point", id, lonlat) + " cannot be represented by the " +
      ProjectionKindName(Params.Kind) + " projection (" + Params.ToString() + ")");
  }
  if (!Impl->Grid)
  {
    return xy;
  }
  const double k = Params.ScaleFactor;
  return { k * (xy.x - Impl->GridOrigin.x) + Params.FalseEasting,
    k * (xy.y - Impl->GridOrigin.y) + Params.FalseNorthing };
}

Point2 GeographicProjection::Inverse(const Point2& grid, long long id) const
{
  const Point2 lonlat = this->InverseOfImage(grid, id);
  this->CheckProjectsBack(grid, lonlat, id);
  return lonlat;
}

Point2 GeographicProjection::Engines::ToLonLat(const ProjectionParameters& p,
  const Point2& xy) const
{
  const double lon0 = this->CentralMeridian;
  Point2 lonlat;
  switch (p.Kind)
  {
    case ProjectionKind::AlbersEqualArea:
      if (this->MirrorAcrossEquator)
      {
        this->Albers->Reverse(lon0, xy.x, -xy.y, lonlat.y, lonlat.x);
        lonlat.y = -lonlat.y;
      }
      else
      {
        this->Albers->Reverse(lon0, xy.x, xy.y, lonlat.y, lonlat.x);
      }
      break;
    case ProjectionKind::LambertConformalConic:
      this->Lambert->Reverse(lon0, xy.x, xy.y, lonlat.y, lonlat.x);
      break;
    case ProjectionKind::TransverseMercator:
      this->Transverse->Reverse(lon0, xy.x, xy.y, lonlat.y, lonlat.x);
      break;
    case ProjectionKind::UTM:
      this->Transverse->Reverse(lon0,
        xy.x - UTMFalseEasting,
        xy.y - (p.UTMNorth ? 0.0 : UTMSouthFalseNorthing),
        lonlat.y,
        lonlat.x);
      break;
    case ProjectionKind::AzimuthalEquidistant:
      this->Azimuthal->Reverse(p.CentralLatitude, lon0, xy.x, xy.y, lonlat.y, lonlat.x);
      break;
    case ProjectionKind::LambertAzimuthalEqualArea:
      this->AzimuthalEqualArea->Reverse(lon0, xy.x, xy.y, lonlat.y, lonlat.x);
      break;
    case ProjectionKind::Mercator:
    case ProjectionKind::WebMercator:
      this->Cylinder->Reverse(lon0, xy.x, xy.y, lonlat.y, lonlat.x);
      break;
  }
  return lonlat;
}

Point2 GeographicProjection::InverseOfImage(const Point2& grid, long long id) const
{
  if (!std::isfinite(grid.x) || !std::isfinite(grid.y))
  {
    throw InputError(DescribePoint("point", id, grid) + " has a NaN or infinite coordinate");
  }
  const double k = Params.ScaleFactor;
  const Point2 xy = !Impl->Grid ? grid
                                : Point2{ (grid.x - Params.FalseEasting) / k + Impl->GridOrigin.x,
                                    (grid.y - Params.FalseNorthing) / k + Impl->GridOrigin.y };
  if (!(std::abs(xy.x) <= MaxProjectedMagnitude) || !(std::abs(xy.y) <= MaxProjectedMagnitude))
  {
    // (Forward refuses such points, so none is an image; the Mercators took y = 1e300 for a pole)
    throw InputError(DescribePoint("point", id, grid) + " lies beyond 1e8 m of the " +
      ProjectionKindName(Params.Kind) + " projection's origin" +
      (Impl->Grid ? " once its grid (false origin, scale) is undone" : "") +
      ", where no place projects");
  }
  Point2 lonlat = Impl->ToLonLat(Params, xy);
  if (!std::isfinite(lonlat.x) || !std::isfinite(lonlat.y))
  {
    throw InputError(DescribePoint("point", id, grid) + " has no inverse under the " +
      ProjectionKindName(Params.Kind) + " projection");
  }
  const double lon0 = Impl->CentralMeridian;
  lonlat.x = lon0 + LongitudeDifference(lon0, lonlat.x);
  return lonlat;
}

bool EdgeReadsBothWays(const Point2& a, const Point2& b)
{
  const double written = std::abs(b.x - a.x);
  return written >= 180.0 && written <= 270.0;
}

double WantedPieceCount(const Point2& a, const Point2& b, double maxStep, bool asWritten)
{
  if (!(maxStep > 0.0) || !std::isfinite(maxStep))
  {
    return 1.0;
  }
  const double dx = asWritten ? b.x - a.x : LongitudeDifference(a.x, b.x);
  const double dy = b.y - a.y;
  const double pieces = std::ceil(std::hypot(dx, dy) / maxStep);
  // (a NaN end, whose count cast to int was -2147483648, or a zero-length edge: 1)
  return pieces >= 1.0 ? pieces : 1.0;
}

int DensifiedPieceCount(const Point2& a,
  const Point2& b,
  double maxStep,
  bool* capped,
  bool asWritten)
{
  const double pieces = WantedPieceCount(a, b, maxStep, asWritten);
  if (capped)
  {
    *capped = pieces > double(MaxDensifiedPieces);
  }
  return static_cast<int>(std::min(pieces, double(MaxDensifiedPieces)));
}

Point2 InterpolateLonLat(const Point2& a, const Point2& b, double t)
{
  return { a.x + t * LongitudeDifference(a.x, b.x), a.y + t * (b.y - a.y) };
}

namespace
{
/// Throws InputError if ring r (vertices [begin, end) of lonlat) goes round a pole.
void CheckRingAvoidsPoles(const std::vector<Point2>& lonlat,
  std::size_t begin,
  std::size_t end,
  std::size_t r)
{
  double turn = 0.0, latitudes = 0.0;
  for (std::size_t k = begin; k < end; ++k)
  {
    turn += LongitudeDifference(lonlat[k].x, lonlat[NextInRing(k, begin, end)].x);
    latitudes += lonlat[k].y;
  }
  // A closed ring turns through a whole number of turns: 0 unless it goes round a pole.
  if (std::abs(turn) > 180.0)
  {
    throw InputError("catchment ring " + std::to_string(r) + " goes round the " +
      (latitudes > 0.0 ? "North" : "South") + " Pole (its edges, read the shorter way round in " +
      "longitude, turn through " + NumberText(std::round(turn)) +
      " degrees): a catchment containing a pole cannot be projected onto one conic, and "
      "Thiessen areal averages over one are not supported");
  }
}
} // namespace

std::vector<Point2> RingsInOneTurn(const std::vector<std::size_t>& offsets,
  const std::vector<Point2>& lonlat)
{
  CheckRingOffsets(offsets, lonlat.size());
  for (std::size_t r = 0; r + 1 < offsets.size(); ++r)
  {
    CheckRingAvoidsPoles(lonlat, offsets[r], offsets[r + 1], r);
  }
  std::vector<Point2> turned = lonlat;
  const bool allFinite = std::all_of(lonlat.begin(),
    lonlat.end(),
    [](const Point2& p) { return std::isfinite(p.x) && std::isfinite(p.y); });
  if (lonlat.empty() || !allFinite)
  {
    return turned; // (ring validation names a NaN or infinite vertex)
  }
  const GeographicExtent extent = ComputeExtent(lonlat);
  const double gap = 360.0 - extent.LongitudeSpan;
  if (gap <= 180.0)
  {
    return turned; // (no meridian is clearly clear of the catchment)
  }
  // The turn [cut, cut + 360) starts halfway across the gap west of the vertices' arc.
  const double cut = extent.WestLongitude - 0.5 * gap;
  for (Point2& p : turned)
  {
    while (p.x < cut)
    {
      p.x += 360.0;
    }
    while (p.x >= cut + 360.0)
    {
      p.x -= 360.0;
    }
  }
  return turned;
}

double EllipsoidalRingArea(const std::vector<Point2>& lonlat)
{
  GeographicLib::PolygonArea polygon(GeographicLib::Geodesic::WGS84());
  for (const Point2& p : lonlat)
  {
    polygon.AddPoint(p.y, p.x);
  }
  double perimeter = 0.0;
  double area = 0.0;
  // reverse = false: anticlockwise rings are positive; sign = true: keep the sign.
  polygon.Compute(false, true, perimeter, area);
  return area;
}

} // namespace tessera
