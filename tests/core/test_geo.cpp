// core/geo: projections against GeographicLib's published examples, round trips, the equal-area
// property against GeographicLib::PolygonArea, antimeridian handling and bad input.
#include "errors.h"
#include "geo.h"

#include "test_support.h"

#include <GeographicLib/Geodesic.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <regex>

using namespace tessera;
using tessera_test::ErrorOf;
using tessera_test::ShoelaceArea;

namespace
{

/// A lon/lat rectangle as a ring with every edge cut into `pieces` parts (edges along parallels
/// must follow them, not the geodesic).
std::vector<Point2> DensifiedCell(double west, double south, double size, int pieces)
{
  const Point2 corners[4] = {
    { west, south }, { west + size, south }, { west + size, south + size }, { west, south + size }
  };
  std::vector<Point2> ring;
  for (int edge = 0; edge < 4; ++edge)
  {
    for (int k = 0; k < pieces; ++k)
    {
      ring.push_back(InterpolateLonLat(corners[edge], corners[(edge + 1) % 4], double(k) / pieces));
    }
  }
  return ring;
}

double AngularDistance(double a, double b)
{
  return std::abs(std::remainder(a - b, 360.0));
}

} // namespace

TEST(Geo, UTMMatchesGeoConvertPublishedExample)
{
  // GeoConvert(1) lists "33.3 44.4" and "38n 444140.54 3684706.36" as the same place.
  ProjectionParameters p;
  p.Kind = ProjectionKind::UTM;
  p.UTMZone = 38;
  p.UTMNorth = true;
  GeographicProjection utm(p);
  const Point2 xy = utm.Forward({ 44.4, 33.3 });
  EXPECT_NEAR(xy.x, 444140.54, 0.01);
  EXPECT_NEAR(xy.y, 3684706.36, 0.01);
  EXPECT_EQ(UTMZoneOfLongitude(44.4), 38);
}

TEST(Geo, LambertMatchesConicProjPublishedExample)
{
  // ConicProj(1): "echo 39.95N 75.17W | ConicProj -c 40d58 39d56 -l 77d45W" prints
  // "220445 -52372 1.67 1.0" (Philadelphia in the Pennsylvania South conic).
  ProjectionParameters p;
  p.Kind = ProjectionKind::LambertConformalConic;
  p.StandardParallel1 = 40.0 + 58.0 / 60.0;
  p.StandardParallel2 = 39.0 + 56.0 / 60.0;
  p.CentralLongitude = -(77.0 + 45.0 / 60.0);
  GeographicProjection lambert(p);
  const Point2 xy = lambert.Forward({ -75.17, 39.95 });
  EXPECT_NEAR(xy.x, 220445.0, 0.5);
  EXPECT_NEAR(xy.y, -52372.0, 0.5);
}

TEST(Geo, RoundTripsToANanodegreeForEveryProjection)
{
  std::mt19937_64 random(7);
  std::uniform_real_distribution<double> lon(-109.5, -101.0), lat(36.5, 41.5);
  std::vector<Point2> points(500);
  for (auto& p : points)
  {
    p = { lon(random), lat(random) };
  }
  const GeographicExtent extent = ComputeExtent(points);
  for (const ProjectionKind kind : ProjectionKinds) // (every kind)
  {
    GeographicProjection projection(ParametersFromExtent(kind, extent));
    for (std::size_t i = 0; i < points.size(); ++i)
    {
      const Point2 back = projection.Inverse(projection.Forward(points[i], i), i);
      EXPECT_LT(AngularDistance(back.x, points[i].x), 1e-9) << ProjectionKindName(kind) << " " << i;
      EXPECT_NEAR(back.y, points[i].y, 1e-9) << ProjectionKindName(kind) << " " << i;
    }
  }
}

TEST(Geo, AutomaticPlacesStandardParallelsAtOneAndFiveSixths)
{
  const std::vector<Point2> points = { { -109.5, 36.5 }, { -101.0, 41.5 }, { -105.0, 38.0 } };
  const ProjectionParameters p = AutomaticParameters(points);
  EXPECT_EQ(p.Kind, ProjectionKind::AlbersEqualArea);
  EXPECT_DOUBLE_EQ(p.CentralLongitude, -105.25);
  EXPECT_DOUBLE_EQ(p.StandardParallel1, 36.5 + 5.0 / 6.0);
  EXPECT_DOUBLE_EQ(p.StandardParallel2, 36.5 + 25.0 / 6.0);
}

TEST(Geo, EqualAreaKeepsAOneDegreeCellAreaToOnePartInAMillion)
{
  // The planar area of the projected (densified) cell against GeographicLib's ellipsoidal area.
  const std::vector<Point2> cell = DensifiedCell(-105.0, 39.0, 1.0, 400);
  const double ellipsoidal = EllipsoidalRingArea(cell);
  for (double lat1 : { 20.0, 37.3, 60.0 })
  {
    ProjectionParameters p;
    p.Kind = ProjectionKind::AlbersEqualArea;
    p.CentralLongitude = -100.0;
    p.StandardParallel1 = lat1;
    p.StandardParallel2 = lat1 + 5.0;
    GeographicProjection albers(p);
    std::vector<Point2> projected;
    for (const Point2& q : cell)
    {
      projected.push_back(albers.Forward(q));
    }
    EXPECT_NEAR(ShoelaceArea(projected) / ellipsoidal, 1.0, 1e-6) << "lat1 " << lat1;
  }
}

TEST(Geo, SouthernEqualAreaKeepsAreaOrientationAndTrueScaleParallels)
{
  // Fiji-like: an anticlockwise cell at 20 S stays anticlockwise with its ellipsoidal area, and
  // along the standard parallel the scale is true (x distance = parallel arc length).
  const std::vector<Point2> cell = DensifiedCell(178.0, -21.0, 1.0, 400);
  const double ellipsoidal = EllipsoidalRingArea(cell);
  ASSERT_GT(ellipsoidal, 0.0);
  ProjectionParameters p;
  p.Kind = ProjectionKind::AlbersEqualArea;
  p.CentralLongitude = 178.5;
  p.StandardParallel1 = -23.0;
  p.StandardParallel2 = -17.0;
  GeographicProjection albers(p);
  std::vector<Point2> projected;
  for (const Point2& q : cell)
  {
    projected.push_back(albers.Forward(q));
  }
  EXPECT_NEAR(ShoelaceArea(projected) / ellipsoidal, 1.0, 1e-6);
  // North is up: a point further south has a smaller y.
  EXPECT_LT(albers.Forward({ 178.5, -22.0 }).y, albers.Forward({ 178.5, -18.0 }).y);
  // True scale on the standard parallel -23: 0.01 degree of longitude spans the parallel's arc.
  const double a = 6378137.0, e2 = 0.00669437999014;
  const double phi = -23.0 * M_PI / 180.0;
  const double parallelRadius =
    a * std::cos(phi) / std::sqrt(1.0 - e2 * std::sin(phi) * std::sin(phi));
  const Point2 west = albers.Forward({ 178.495, -23.0 }), east = albers.Forward({ 178.505, -23.0 });
  EXPECT_NEAR(std::hypot(east.x - west.x, east.y - west.y) / (parallelRadius * 0.01 * M_PI / 180.0),
    1.0,
    1e-6);
}

TEST(Geo, ExtentCrossingTheAntimeridianIsTheShortArc)
{
  const std::vector<Point2> fiji = {
    { 165.67, -20.0 }, { 181.62, -15.0 }, { 179.0, -25.0 }, { -179.5, -30.0 }
  };
  const GeographicExtent extent = ComputeExtent(fiji);
  EXPECT_NEAR(extent.LongitudeSpan, 181.62 - 165.67, 1e-9);
  EXPECT_NEAR(extent.WestLongitude, 165.67, 1e-9);
  GeographicProjection projection(AutomaticParameters(fiji));
  // 181.62 and -178.38 are one meridian: they project to one point, and the inverse returns a
  // longitude continuous with the data (within 180 degrees of the central meridian).
  const Point2 a = projection.Forward({ 181.62, -15.0 });
  const Point2 b = projection.Forward({ -178.38, -15.0 });
  EXPECT_NEAR(a.x, b.x, 1e-6);
  EXPECT_NEAR(a.y, b.y, 1e-6);
  EXPECT_NEAR(projection.Inverse(a).x, 181.62, 1e-9);
  // Densification takes the short way across the antimeridian.
  EXPECT_EQ(DensifiedPieceCount({ 179.5, 0.0 }, { -179.5, 0.0 }, 0.25), 4);
  EXPECT_NEAR(InterpolateLonLat({ 179.5, 0.0 }, { -179.5, 0.0 }, 0.5).x, 180.0, 1e-12);
}

TEST(Geo, OnePlaceWrittenTwoWaysProjectsToOnePointExactly)
{
  // Exactly one place (the differences are whole turns): the same point, bit for bit, under
  // meridians whose differences from them round (the reduction of b - a did, and the two copies of
  // a gauge came out some 1e-9 m apart, not duplicates).
  const std::pair<double, double> pairs[] = { { 181.5, -178.5 },
    { 180.0, -180.0 },
    { 359.5, -0.5 },
    { 190.123456789, 190.123456789 - 360.0 },
    { -350.7, 9.3 } };
  for (const double lon0 : { 176.5, -170.25, 183.3, 0.1, -359.9 })
  {
    ProjectionParameters p;
    p.Kind = ProjectionKind::AlbersEqualArea;
    p.CentralLongitude = lon0;
    p.CentralLatitude = -20.0;
    p.StandardParallel1 = -25.0;
    p.StandardParallel2 = -15.0;
    const GeographicProjection projection(p);
    for (const auto& [east, west] : pairs)
    {
      if (std::remainder(east, 360.0) != std::remainder(west, 360.0)) // (exact)
      {
        continue; // (-350.7 and 9.3 differ in their last bits: two places)
      }
      const Point2 a = projection.Forward({ east, -20.0 });
      const Point2 b = projection.Forward({ west, -20.0 });
      EXPECT_TRUE(a.x == b.x && a.y == b.y) << lon0 << ": " << east << ", " << west;
    }
  }
}

TEST(Geo, DataRoundTheGlobeComeBackWithinATurn)
{
  // Stations all round the globe from 120 east: the arc held them to 480 degrees, its centre at
  // 300, and the inverse gave longitudes of 450 back, which every reader refuses.
  const std::vector<Point2> stations = { { 150.0, 5.0 },
    { 200.0, 10.0 },
    { 250.0, 15.0 },
    { 300.0, 5.0 },
    { 350.0, 10.0 },
    { 40.0, 15.0 },
    { 90.0, 5.0 } };
  const GeographicExtent extent = ComputeExtent(stations);
  EXPECT_LE(extent.WestLongitude + extent.LongitudeSpan, 360.0);
  EXPECT_NEAR(extent.LongitudeSpan, 300.0, 1e-12);
  const GeographicProjection projection(AutomaticParameters(stations));
  for (const Point2& s : stations)
  {
    const Point2 back = projection.Inverse(projection.Forward(s));
    EXPECT_LE(std::abs(back.x), 360.0) << s.x;
    EXPECT_NEAR(std::remainder(back.x - s.x, 360.0), 0.0, 1e-9) << s.x;
  }
}

TEST(Geo, BadPointsAreNamedById)
{
  GeographicProjection albers(AutomaticParameters({ { 0.0, 0.0 }, { 1.0, 1.0 } }));
  try
  {
    albers.Forward({ 0.0, 95.0 }, 17);
    FAIL() << "latitude 95 accepted";
  }
  catch (const InputError& e)
  {
    EXPECT_NE(std::string(e.what()).find("point 17"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("95"), std::string::npos) << e.what();
  }
  EXPECT_THROW(albers.Forward({ std::nan(""), 0.0 }, 3), InputError);
  EXPECT_THROW(ValidateLonLat({ { 0.0, 0.0 }, { INFINITY, 0.0 } }), InputError);
  try
  {
    ValidateLonLat({ { 0.0, 0.0 }, { 1.0, 2.0 }, { 3.0, -90.5 } });
    FAIL() << "latitude -90.5 accepted";
  }
  catch (const InputError& e)
  {
    EXPECT_NE(std::string(e.what()).find("point 2"), std::string::npos) << e.what();
  }
  // Longitudes: 0..360 and -360..0 are angles; beyond is a typo, or no angle at all (1e20).
  EXPECT_NO_THROW(ValidateLonLat({ { 359.0, 10.0 }, { -360.0, 10.0 } }));
  for (const double lon : { 360.5, -1031.5, 1e20 })
  {
    try
    {
      ValidateLonLat({ { 0.0, 0.0 }, { lon, 10.0 } });
      FAIL() << "longitude " << lon << " accepted";
    }
    catch (const InputError& e)
    {
      EXPECT_NE(std::string(e.what()).find("point 1"), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("longitude beyond 360"), std::string::npos) << e.what();
    }
  }
}

TEST(Geo, PointsAProjectionCannotRepresentAreRefused)
{
  ProjectionParameters p;
  p.Kind = ProjectionKind::UTM;
  p.UTMZone = 13;
  GeographicProjection utm(p);
  // On the zone's central meridian: the false easting, and k0 times the meridian's arc from the
  // equator (GeographicLib's geodesic, not its transverse Mercator, measures the arc).
  const Point2 onMeridian = utm.Forward({ -105.0, 40.0 });
  double arc = 0.0;
  GeographicLib::Geodesic::WGS84().Inverse(0.0, -105.0, 40.0, -105.0, arc);
  EXPECT_NEAR(onMeridian.x, 500000.0, 1e-6);
  EXPECT_NEAR(onMeridian.y, 0.9996 * arc, 1e-6);
  EXPECT_THROW(utm.Forward({ -60.0, 40.0 }, 5), InputError); // 45 degrees away
  EXPECT_THROW(utm.Forward({ -95.0, 40.0 }, 5), InputError); // 850 km east: beyond UTM eastings
  ProjectionParameters lcc;
  lcc.Kind = ProjectionKind::LambertConformalConic;
  lcc.StandardParallel1 = 30.0;
  lcc.StandardParallel2 = 60.0;
  GeographicProjection lambert(lcc);
  EXPECT_THROW(lambert.Forward({ 0.0, -90.0 }, 9), InputError); // the cone's far pole
  ProjectionParameters badZone;
  badZone.Kind = ProjectionKind::UTM;
  badZone.UTMZone = 61;
  EXPECT_THROW(GeographicProjection{ badZone }, InputError);
}

TEST(Geo, ParameterRecordRoundTripsExactly)
{
  ProjectionParameters p;
  p.Kind = ProjectionKind::LambertConformalConic;
  p.CentralLongitude = -105.123456789012345;
  p.CentralLatitude = 0.1 + 0.2;
  p.StandardParallel1 = 1.0 / 3.0;
  p.StandardParallel2 = 45.0;
  p.UTMZone = 13;
  p.UTMNorth = false;
  const ProjectionParameters q = ProjectionParameters::FromString(p.ToString());
  EXPECT_EQ(q.Kind, p.Kind);
  EXPECT_EQ(q.CentralLongitude, p.CentralLongitude);
  EXPECT_EQ(q.CentralLatitude, p.CentralLatitude);
  EXPECT_EQ(q.StandardParallel1, p.StandardParallel1);
  EXPECT_EQ(q.StandardParallel2, p.StandardParallel2);
  EXPECT_EQ(q.UTMZone, p.UTMZone);
  EXPECT_EQ(q.UTMNorth, p.UTMNorth);
  EXPECT_THROW(ProjectionParameters::FromString("projection=Mollweide"), InputError);
  EXPECT_THROW(ProjectionParameters::FromString("projection=UTM zone=x"), InputError);
  // A key given twice, or a parameter the projection needs left out (it was 0, silently), is an
  // error naming it; a short record with what its projection needs is read.
  const auto messageOf = [](const char* record)
  {
    try
    {
      ProjectionParameters::FromString(record);
    }
    catch (const InputError& e)
    {
      return std::string(e.what());
    }
    return std::string("read");
  };
  EXPECT_NE(
    messageOf("projection=UTM zone=13 zone=14").find("gives zone twice"), std::string::npos);
  EXPECT_NE(messageOf("projection=AlbersEqualArea")
              .find("lacks lon0, lat1, lat2, which "
                    "AlbersEqualArea needs"),
    std::string::npos);
  EXPECT_NE(
    messageOf("projection=AzimuthalEquidistant lon0=3").find("lacks lat0"), std::string::npos);
  EXPECT_NE(messageOf("projection=LambertAzimuthalEqualArea lat0=52").find("lacks lon0"),
    std::string::npos);
  EXPECT_NE(messageOf("projection=UTM north=1").find("lacks zone"), std::string::npos);
  EXPECT_EQ(messageOf("projection=UTM zone=13"), "read");
  EXPECT_EQ(messageOf("projection=TransverseMercator lon0=0.5"), "read");
  EXPECT_EQ(messageOf("projection=LambertConformalConic lon0=-105 lat1=33 lat2=45"), "read");
}

// SameProjection against the projections themselves: for each kind, changing one field at a time
// changes where sample points land exactly when SameProjection says the projections differ.
TEST(Geo, SameProjectionIsWhetherPointsLandAlike)
{
  // (between the meridians of UTM zones 12 and 13, so that both represent them)
  const std::vector<Point2> samples = { { -108.0, 39.0 }, { -107.5, 41.5 }, { -108.4, 36.4 } };
  const auto landings = [&samples](const ProjectionParameters& p)
  {
    const GeographicProjection projection(p);
    std::vector<Point2> xy;
    for (std::size_t i = 0; i < samples.size(); ++i)
    {
      xy.push_back(projection.Forward(samples[i], i));
    }
    return xy;
  };
  int different = 0;
  for (const ProjectionKind kind : ProjectionKinds) // (every kind)
  {
    ProjectionParameters base;
    base.Kind = kind;
    base.CentralLongitude = -105.5;
    base.CentralLatitude = 39.0;
    base.StandardParallel1 = 37.5;
    base.StandardParallel2 = 40.5;
    base.UTMZone = 13;
    base.UTMNorth = true;
    std::vector<ProjectionParameters> variants(6, base);
    variants[0].CentralLongitude = -104.5;
    variants[1].CentralLatitude = 38.0;
    variants[2].StandardParallel1 = 36.5;
    variants[3].StandardParallel2 = 41.5;
    variants[4].UTMZone = 12;
    variants[5].UTMNorth = false;
    const std::vector<Point2> expected = landings(base);
    EXPECT_TRUE(SameProjection(base, base));
    for (std::size_t v = 0; v < variants.size(); ++v)
    {
      const std::vector<Point2> got = landings(variants[v]);
      bool alike = true;
      for (std::size_t i = 0; i < got.size(); ++i)
      {
        alike = alike && got[i].x == expected[i].x && got[i].y == expected[i].y;
      }
      EXPECT_EQ(SameProjection(base, variants[v]), alike)
        << ProjectionKindName(kind) << ", variant " << v;
      EXPECT_EQ(SameProjection(variants[v], base), alike);
      different += alike ? 0 : 1;
    }
  }
  // Each kind uses some of the six fields: 3 + 3 + 1 + 2 + 2 + 2 + 1 + 1.
  EXPECT_EQ(different, 15);
  ProjectionParameters other;
  other.Kind = ProjectionKind::LambertConformalConic;
  ProjectionParameters same = other;
  same.Kind = ProjectionKind::AlbersEqualArea;
  EXPECT_FALSE(SameProjection(other, same));
}

// Found by a C++ user's review: a NaN longitude's UTM zone was a cast of NaN to int
// (-2147483647), a NaN edge end gave -2147483648 pieces, a NaN central longitude leaked the
// projection's engines (a sanitizer build of this test would report it).
TEST(Geo, NonFiniteValuesAreErrorsOrSafe)
{
  EXPECT_THROW(tessera::UTMZoneOfLongitude(std::nan("")), tessera::InputError);
  EXPECT_THROW(tessera::UTMZoneOfLongitude(HUGE_VAL), tessera::InputError);
  EXPECT_EQ(tessera::UTMZoneOfLongitude(-105.0), 13);
  EXPECT_EQ(tessera::DensifiedPieceCount({ 0.0, 0.0 }, { std::nan(""), 1.0 }, 0.01, nullptr), 1);
  tessera::ProjectionParameters p;
  p.Kind = tessera::ProjectionKind::AlbersEqualArea;
  p.CentralLongitude = std::nan("");
  EXPECT_THROW(tessera::GeographicProjection{ p }, tessera::InputError);
  // Finite but no longitude or latitude (1e20 gave every x 0; a lat0 of 100 was taken where the
  // projection does not use it, and written into its record).
  p.CentralLongitude = 1e20;
  EXPECT_EQ(ErrorOf([&] { tessera::GeographicProjection{ p }; }),
    "projection parameter lon0 = 1e+20 is not a longitude in [-360, 360]");
  p.CentralLongitude = -105.0;
  p.CentralLatitude = 100.0;
  for (const auto kind : { tessera::ProjectionKind::AlbersEqualArea, tessera::ProjectionKind::UTM })
  {
    p.Kind = kind;
    p.UTMZone = 13;
    EXPECT_EQ(ErrorOf([&] { tessera::GeographicProjection{ p }; }),
      "projection parameter lat0 = 100 is not a latitude in [-90, 90]");
  }
}

// Found by a C++ user's review: FromString took lon0=nan, lat1=inf and zone=1e20 (cast to
// -2147483648), and conic standard parallels at opposite poles were not refused as documented.
TEST(Geo, BadRecordsAndOppositePolesAreErrors)
{
  for (const char* record : { "projection=AlbersEqualArea lon0=nan lat0=39 lat1=37 lat2=41",
         "projection=AlbersEqualArea lon0=-105 lat0=39 lat1=inf lat2=41",
         "projection=UTM lon0=-105 zone=99999999999999999999 north=1",
         "projection=UTM lon0=-105 zone=13.5 north=1" })
  {
    EXPECT_THROW(tessera::ProjectionParameters::FromString(record), tessera::InputError) << record;
  }
  EXPECT_EQ(
    tessera::ProjectionParameters::FromString("projection=UTM lon0=-105 zone=13 north=1").UTMZone,
    13);
  // A long record is quoted by its start and length, not whole (10^5 characters were echoed).
  const std::string longRecord = "projection=UTM zone=13 " + std::string(100000, 'x');
  try
  {
    tessera::ProjectionParameters::FromString(longRecord);
    ADD_FAILURE() << "a record of 10^5 x taken";
  }
  catch (const tessera::InputError& e)
  {
    const std::string message = e.what();
    EXPECT_LT(message.size(), 250u) << message;
    EXPECT_NE(message.find("...' (100000 characters) is not key=value"), std::string::npos)
      << message;
  }
  for (const tessera::ProjectionKind kind :
    { tessera::ProjectionKind::AlbersEqualArea, tessera::ProjectionKind::LambertConformalConic })
  {
    tessera::ProjectionParameters p;
    p.Kind = kind;
    p.StandardParallel1 = 90.0;
    p.StandardParallel2 = -90.0;
    EXPECT_THROW(tessera::GeographicProjection{ p }, tessera::InputError);
  }
}

namespace
{
/// The angle between two lon/lat directions on the sphere (degrees).
double GreatCircleDegrees(const Point2& a, const Point2& b)
{
  const double d = M_PI / 180.0;
  const double c = std::sin(a.y * d) * std::sin(b.y * d) +
    std::cos(a.y * d) * std::cos(b.y * d) * std::cos((a.x - b.x) * d);
  return std::acos(std::min(1.0, std::max(-1.0, c))) / d;
}

/// A projection's scale at a point along the meridian and along the parallel: its plane
/// distances over 111 m steps (y keeps 1e-9 m there, where steps of a metre lose it to rounding)
/// against the arcs of the WGS84 ellipsoid's radii of curvature.
struct Scales
{
  double AlongMeridian, AlongParallel, ParallelRadius;
};

Scales ScalesAt(const tessera::GeographicProjection& projection, const Point2& at)
{
  const double a = 6378137.0, f = 1.0 / 298.257223563, e2 = f * (2.0 - f);
  const double s = std::sin(at.y * M_PI / 180.0), w = std::sqrt(1.0 - e2 * s * s);
  const double meridianRadius = a * (1.0 - e2) / (w * w * w);
  const double parallelRadius = a * std::cos(at.y * M_PI / 180.0) / w;
  const double step = 1e-3, radians = step * M_PI / 180.0;
  const Point2 north = projection.Forward({ at.x, at.y + step });
  const Point2 south = projection.Forward({ at.x, at.y - step });
  const Point2 east = projection.Forward({ at.x + step, at.y });
  const Point2 west = projection.Forward({ at.x - step, at.y });
  return { std::hypot(north.x - south.x, north.y - south.y) / (2.0 * meridianRadius * radians),
    std::hypot(east.x - west.x, east.y - west.y) / (2.0 * parallelRadius * radians),
    parallelRadius };
}

/// The point `degrees` from `from` in the direction `azimuth` (degrees from north) on the
/// sphere.
Point2 AtDistance(const Point2& from, double degrees, double azimuth)
{
  const double r = M_PI / 180.0, d = degrees * r, az = azimuth * r, lat = from.y * r;
  const double sinLat = std::sin(lat) * std::cos(d) + std::cos(lat) * std::sin(d) * std::cos(az);
  const double dLon =
    std::atan2(std::sin(az) * std::sin(d) * std::cos(lat), std::cos(d) - std::sin(lat) * sinLat);
  return { from.x + dLon / r, std::asin(sinLat) / r };
}

tessera::GeographicProjection LambertAzimuthal(double lat0, double lon0)
{
  tessera::ProjectionParameters p;
  p.Kind = tessera::ProjectionKind::LambertAzimuthalEqualArea;
  p.CentralLatitude = lat0;
  p.CentralLongitude = lon0;
  return tessera::GeographicProjection(p);
}
} // namespace

// Against PROJ 9.1.1, an independent implementation (cs2cs -f %.6f +proj=lonlat +datum=WGS84
// +to +proj=laea +lat_0=LAT0 +lon_0=LON0 +datum=WGS84), in every aspect: oblique (LAEA Europe's
// centre; EPSG Guidance Note 7-2's example, 50 N 5 E, is E 3962799.45 N 2999718.85 with its false
// origin 4321000, 3210000), north and south polar, equatorial, and far from the centre. A metre
// from the pole, PROJ's polar formula loses 1.5 mm to cancellation (a sqrt(q_p - q) gives
// -11.170932): there the value is the exact one, from that formula in 40-digit arithmetic.
TEST(Geo, LambertAzimuthalEqualAreaMatchesProjInEveryAspect)
{
  struct Case
  {
    double Lat0, Lon0, Lon, Lat, X, Y;
  };
  const Case cases[] = {
    { 52, 10, 5, 50, -358200.549042, -210281.146841 },
    { 52, 10, -10, 35, -1822462.000392, -1644428.233992 },
    { 52, 10, 40, 70, 1116144.602579, 2246815.649100 },
    { 52, 10, 10, 52, 0, 0 },
    { 90, -40, -60, 80, -381492.363476, -1048141.654344 },
    { 90, -40, 100, 60.5, 2092901.780708, 2494223.216106 },
    { 90, -40, -40, 89.9999, 0, -11.169397955911 },
    { -90, 0, -60, -80, -965972.573742, 557704.525480 },
    { -90, 0, 135, -55, 2718393.549057, -2718393.549057 },
    { 0, 10, 30, -20, 2113450.793159, -2234031.895832 },
    { 0, 10, -70, 10, -8085103.626888, 1437923.676135 },
    { 0, 10, 100, 1, 9018686.302373, 156367.914071 },
    { 45, 10, 170, -75, 2099833.092261, -12081707.594796 },
    { 45, 10, -170, 30, 0, 10119420.782086 },
  };
  for (const Case& c : cases)
  {
    const auto projection = LambertAzimuthal(c.Lat0, c.Lon0);
    const Point2 xy = projection.Forward({ c.Lon, c.Lat });
    EXPECT_NEAR(xy.x, c.X, 2e-6) << c.Lat0 << " " << c.Lon0 << ": " << c.Lon << " " << c.Lat;
    EXPECT_NEAR(xy.y, c.Y, 2e-6) << c.Lat0 << " " << c.Lon0 << ": " << c.Lon << " " << c.Lat;
    const Point2 back = projection.Inverse({ c.X, c.Y });
    EXPECT_LT(AngularDistance(back.x, c.Lon), 1e-9) << c.Lat0 << " " << c.Lon0 << ": " << c.Lon;
    EXPECT_NEAR(back.y, c.Lat, 1e-9) << c.Lat0 << " " << c.Lon0 << ": " << c.Lat;
  }
}

// Round trips to 1e-9 degrees (0.1 mm) up to 0.1 degree from the centre's antipode, in the polar,
// equatorial and oblique aspects, including points a nanometre from the centre and from the
// pole; and to 1e-8 degrees (1 mm) at 0.1 to 0.001 degree from the antipode, where the plane's rim
// is and the inverse is ill-conditioned (PROJ's came back 1.7 m off at 0.1 degree; the plain
// formulas here, 3 m). A point 1e-5 degree (1 m) from the antipode still comes back, 0.3 m from it
// has no image.
TEST(Geo, LambertAzimuthalEqualAreaRoundTripsInEveryAspect)
{
  std::mt19937_64 random(11);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  const auto expectBack = [](
                            const GeographicProjection& projection, const Point2& q, double degrees)
  {
    const Point2 back = projection.Inverse(projection.Forward(q));
    const double lonError = std::abs(q.y) > 90.0 - 1e-9 ? 0.0 : AngularDistance(back.x, q.x);
    EXPECT_LT(lonError * std::cos(q.y * M_PI / 180.0), degrees) << q.x << " " << q.y;
    EXPECT_NEAR(back.y, q.y, degrees) << q.x << " " << q.y;
  };
  for (const double lat0 : { 90.0, 89.99, 52.0, 0.0, -33.0, -90.0 })
  {
    SCOPED_TRACE(lat0);
    const double lon0 = 17.0;
    const auto projection = LambertAzimuthal(lat0, lon0);
    std::vector<Point2> points = {
      { lon0, lat0 }, { lon0 + 1e-14, lat0 }, { lon0, 90.0 }, { lon0 + 30.0, -90.0 + 1e-12 }
    };
    for (int i = 0; i < 2000; ++i)
    {
      // Uniform on the sphere: sine of the latitude uniform.
      points.push_back({ lon0 + 180.0 * unit(random), std::asin(unit(random)) * 180.0 / M_PI });
    }
    const Point2 antipode = { lon0 + 180.0, -lat0 };
    for (const Point2& q : points)
    {
      if (GreatCircleDegrees(q, antipode) > 0.1)
      {
        expectBack(projection, q, 1e-9);
      }
    }
    for (const double away : { 0.1, 0.01, 0.001 })
    {
      for (int i = 0; i < 50; ++i)
      {
        expectBack(projection, AtDistance(antipode, away, 180.0 * unit(random)), 1e-8);
      }
    }
    EXPECT_NO_THROW(projection.Inverse(
      projection.Forward({ antipode.x, antipode.y + (lat0 > 0 ? 1e-5 : -1e-5) })));
    EXPECT_THROW(
      projection.Forward({ antipode.x, antipode.y + (lat0 > 0 ? 3e-6 : -3e-6) * 0.1 }), InputError);
  }
}

// A centre a hair from a pole projects as the polar aspect does, to within what moving the centre
// by that hair moves the points (at most twice the hair's angle times the image's 1.3e7 m): D's
// cos(xi0), taken through xi0 in degrees, once put points 33 m off at 1e-9 degree from the pole.
TEST(Geo, LambertAzimuthalEqualAreaNearAPoleIsThePolarAspect)
{
  for (const double pole : { 90.0, -90.0 })
  {
    const auto polar = LambertAzimuthal(pole, 30.0);
    for (const double hair : { 1e-10, 1e-9, 1e-8, 1e-6, 1e-4 })
    {
      const auto near = LambertAzimuthal(pole - std::copysign(hair, pole), 30.0);
      const double bound = 2.0 * hair * M_PI / 180.0 * 1.3e7 + 1e-6;
      for (const Point2& q :
        { Point2{ 120.0, 0.0 }, Point2{ -45.0, pole / 2.0 }, Point2{ 30.0, -pole / 3.0 } })
      {
        const Point2 a = polar.Forward(q), b = near.Forward(q);
        EXPECT_LT(std::hypot(a.x - b.x, a.y - b.y), bound)
          << pole << " " << hair << ": " << q.x << " " << q.y;
      }
    }
  }
}

// Equal area: the planar area of a projected cell is its ellipsoidal area (GeographicLib's
// PolygonArea), near and far from the centre, in each aspect; and the scale at the centre is
// true along the meridian and the parallel (from the ellipsoid's radii of curvature).
TEST(Geo, LambertAzimuthalEqualAreaKeepsAreasAndTrueScaleAtTheCentre)
{
  struct Cell
  {
    double Lat0, Lon0, West, South;
  };
  for (const Cell& c : { Cell{ 52, 10, 5, 50 },
         Cell{ 52, 10, -30, 20 },
         Cell{ 90, 0, 100, 70 },
         Cell{ -90, 0, -60, -80 },
         Cell{ 0, 10, 60, -40 },
         Cell{ -33, 150, 140, -10 } })
  {
    const std::vector<Point2> cell = DensifiedCell(c.West, c.South, 1.0, 400);
    const auto projection = LambertAzimuthal(c.Lat0, c.Lon0);
    std::vector<Point2> projected;
    for (const Point2& q : cell)
    {
      projected.push_back(projection.Forward(q));
    }
    EXPECT_NEAR(ShoelaceArea(projected) / EllipsoidalRingArea(cell), 1.0, 1e-7)
      << "centre " << c.Lat0 << " " << c.Lon0 << ", cell " << c.West << " " << c.South;
  }
  for (const double lat0 : { 52.0, 0.0, -33.0 })
  {
    const Scales scales = ScalesAt(LambertAzimuthal(lat0, 10.0), { 10.0, lat0 });
    EXPECT_NEAR(scales.AlongMeridian, 1.0, 1e-9) << lat0;
    EXPECT_NEAR(scales.AlongParallel, 1.0, 1e-9) << lat0;
  }
}

// The centre's antipode has no image, and a plane point beyond the image's rim no preimage: both
// are errors naming the point, not NaN coordinates.
TEST(Geo, LambertAzimuthalEqualAreaRefusesTheAntipodeAndPointsBeyondTheRim)
{
  const auto projection = LambertAzimuthal(52.0, 10.0);
  EXPECT_NE(ErrorOf(
              [&] {
                projection.Forward({ -170.0, -52.0 }, 7);
              })
              .find("cannot be represented by the LambertAzimuthalEqualArea projection"),
    std::string::npos);
  EXPECT_NE(ErrorOf(
              [&] {
                projection.Inverse({ 0.0, 1.3e7 }, 8);
              })
              .find("has no inverse"),
    std::string::npos);
  EXPECT_NE(ErrorOf(
              [&] {
                projection.Inverse({ 0.0, 1.3e7 }, 8);
              })
              .find("point 8"),
    std::string::npos);
}

// Against PROJ 9.1.1 (cs2cs -f %.6f EPSG:4326 EPSG:3395, EPSG:3857, and +proj=merc +lon_0=-100
// +datum=WGS84): the ellipsoid's Mercator and the web maps' one, about meridian 0 and another;
// the inverse gives the point back. Web Mercator's y is the sphere's: 32.75 km north of
// the ellipsoid's at 50 N.
TEST(Geo, MercatorsMatchProj)
{
  struct Case
  {
    ProjectionKind Kind;
    double Lon0, Lon, Lat, X, Y;
  };
  const Case cases[] = {
    { ProjectionKind::Mercator, 0, 5, 50, 556597.453966, 6413524.594164 },
    { ProjectionKind::Mercator, 0, -105, 39, -11688546.533294, 4694777.271649 },
    { ProjectionKind::Mercator, 0, 176, -39, 19592230.379616, -4694777.271649 },
    { ProjectionKind::Mercator, 0, 179.9, 85, 20026376.393710, 19929239.113379 },
    { ProjectionKind::Mercator, 0, -120, -80, -13358338.895193, -15496570.739724 },
    { ProjectionKind::Mercator, 0, 10, 89.999, 1113194.907933, 74256950.065168 },
    { ProjectionKind::Mercator, -100, -105, 39, -556597.453966, 4694777.271649 },
    { ProjectionKind::WebMercator, 0, 5, 50, 556597.453966, 6446275.841017 },
    { ProjectionKind::WebMercator, 0, -105, 39, -11688546.533294, 4721671.572580 },
    { ProjectionKind::WebMercator, 0, 176, -39, 19592230.379616, -4721671.572580 },
    { ProjectionKind::WebMercator, 0, 179.9, 85, 20026376.393710, 19971868.880409 },
    { ProjectionKind::WebMercator, 0, -120, -80, -13358338.895193, -15538711.096309 },
    { ProjectionKind::WebMercator, 0, 10, 89.999, 1113194.907933, 74299743.400553 },
  };
  for (const Case& c : cases)
  {
    ProjectionParameters p;
    p.Kind = c.Kind;
    p.CentralLongitude = c.Lon0;
    const GeographicProjection projection(p);
    const Point2 xy = projection.Forward({ c.Lon, c.Lat });
    const std::string where = std::string(ProjectionKindName(c.Kind)) + " " +
      std::to_string(c.Lon) + " " + std::to_string(c.Lat);
    EXPECT_NEAR(xy.x, c.X, 2e-6) << where;
    // (y moves a / cos(lat) metres a radian: the last bits of 89.999 are some 4e-5 m of y)
    const double lastBits = 4e-16 * 6378137.0 / std::cos(c.Lat * M_PI / 180.0);
    EXPECT_NEAR(xy.y, c.Y, 2e-6 + lastBits) << where;
    const Point2 back = projection.Inverse({ c.X, c.Y });
    EXPECT_LT(AngularDistance(back.x, c.Lon), 1e-9) << where;
    EXPECT_NEAR(back.y, c.Lat, 1e-9) << where;
  }
}

// The ellipsoid's Mercator is conformal: along the parallel and along the meridian the scale is
// the same (from the ellipsoid's radii of curvature), a / (N cos lat), 1 on the equator. Neither
// Mercator reaches a pole: the point is named.
TEST(Geo, MercatorIsConformalAndRefusesThePoles)
{
  ProjectionParameters p;
  p.Kind = ProjectionKind::Mercator;
  p.CentralLongitude = 20.0;
  const GeographicProjection mercator(p);
  for (const double lat : { 0.0, 23.5, -47.0, 71.0 })
  {
    const Scales scales = ScalesAt(mercator, { 20.0, lat });
    EXPECT_NEAR(scales.AlongMeridian / scales.AlongParallel, 1.0, 1e-9) << lat;
    EXPECT_NEAR(scales.AlongParallel * scales.ParallelRadius, 6378137.0, 1e-9 * 6378137.0) << lat;
  }
  for (const ProjectionKind kind : { ProjectionKind::Mercator, ProjectionKind::WebMercator })
  {
    p.Kind = kind;
    const GeographicProjection projection(p);
    EXPECT_NE(ErrorOf(
                [&] {
                  projection.Forward({ 3.0, 90.0 }, 4);
                })
                .find("cannot be represented by the " + std::string(ProjectionKindName(kind))),
      std::string::npos);
    EXPECT_NE(ErrorOf(
                [&] {
                  projection.Forward({ 3.0, -90.0 }, 4);
                })
                .find("point 4"),
      std::string::npos);
    // Nor does anything beyond the poles' 1e8 m or half a turn from the central meridian invert
    // (y = 1e300 came back as the pole, x = 1e12 as longitude 72.84).
    for (const Point2& far :
      { Point2{ 0.0, 1e300 }, Point2{ 0.0, -1.5e8 }, Point2{ 1e12, 0.0 }, Point2{ 2.1e7, 0.0 } })
    {
      EXPECT_NE(ErrorOf([&] { projection.Inverse(far, 5); }).find("point 5"), std::string::npos)
        << far.x << " " << far.y;
    }
    const Point2 edge = projection.Forward({ 20.0 + 180.0, 10.0 });
    EXPECT_NEAR(std::abs(projection.Inverse(edge).x - 20.0), 180.0, 1e-9);
  }
}

// Grids on the planes (false easting and northing, scale, latitude of origin) against PROJ 9.1.1
// (cs2cs -f %.6f +proj=longlat +ellps=WGS84 +to ... +ellps=WGS84): the USGS Albers of the
// conterminous US (EPSG:5070's terms: its northings start at 23 N, not at GeographicLib's origin
// between the standard parallels), LAEA Europe (EPSG:3035's false origin; EPSG Guidance Note 7-2's
// example, 50 N 5 E, is E 3962799.45 N 2999718.85), a Lambert conic of Europe (EPSG:3034's
// terms), a transverse Mercator with the British grid's origin, scale and false origin, and a
// Mercator with a scale (EPSG:3002's terms). The inverse gives each point back.
TEST(Geo, GridsOnThePlanesMatchProj)
{
  struct Case
  {
    const char* Record;
    double Lon, Lat, X, Y;
  };
  const char* albers =
    "projection=AlbersEqualArea lon0=-96 lat1=29.5 lat2=45.5 origin_lat=23"; // EPSG:5070
  const char* laea = "projection=LambertAzimuthalEqualArea lon0=10 lat0=52 x0=4321000 y0=3210000";
  const char* lcc =
    "projection=LambertConformalConic lon0=10 lat1=35 lat2=65 x0=4000000 y0=2800000 origin_lat=52";
  const char* tmerc =
    "projection=TransverseMercator lon0=-2 x0=400000 y0=-100000 k0=0.9996012717 origin_lat=49";
  const char* merc = "projection=Mercator lon0=110 x0=3900000 y0=900000 k0=0.997";
  const Case cases[] = {
    { albers, -105.5, 39.0, -813760.923180, 1815617.850413 },
    { albers, -96, 23, 0, 0 },
    { albers, -80.25, 25.75, 1588474.302999, 432229.562263 },
    { albers, -122.5, 47.6, -1980402.161020, 3011940.646637 },
    { laea, 5, 50, 3962799.450958, 2999718.853159 },
    { lcc, 5, 50, 3654072.121868, 2596848.659964 },
    { lcc, -20, 70, 2847036.070927, 5019300.355375 },
    { lcc, 30, 36, 5773951.303690, 1308064.247455 },
    { tmerc, -2, 49, 400000, -100000 },
    { tmerc, -3.2, 55.9, 324967.427522, 668145.822544 },
    { tmerc, 1.5, 51.1, 645033.470671, 139317.598411 },
    { merc, 120, -3, 5009855.323209, 569119.095390 },
  };
  for (const Case& c : cases)
  {
    const GeographicProjection projection(ProjectionParameters::FromString(c.Record));
    const Point2 xy = projection.Forward({ c.Lon, c.Lat });
    EXPECT_NEAR(xy.x, c.X, 2e-6) << c.Record << ": " << c.Lon << " " << c.Lat;
    EXPECT_NEAR(xy.y, c.Y, 2e-6) << c.Record << ": " << c.Lon << " " << c.Lat;
    const Point2 back = projection.Inverse({ c.X, c.Y });
    EXPECT_LT(AngularDistance(back.x, c.Lon), 1e-9) << c.Record << ": " << c.Lon;
    EXPECT_NEAR(back.y, c.Lat, 1e-9) << c.Record << ": " << c.Lat;
  }
}

// The grid is the plane moved and scaled: for every kind, a grid's coordinates are
// k0 * (plane - plane's image of the origin) + false origin, checked against the plane without a
// grid; the defaults leave the plane's coordinates bit for bit (a record without grid keys is
// the plane it always was); records carry the grid exactly, and SameProjection tells grids apart.
TEST(Geo, GridIsThePlaneMovedAndScaled)
{
  const std::vector<std::string> planes = {
    "projection=AlbersEqualArea lon0=-105.5 lat0=39 lat1=37.33 lat2=40.67",
    "projection=AlbersEqualArea lon0=147 lat1=-40 lat2=-20", // GeographicLib's cone, mirrored
    "projection=LambertConformalConic lon0=-105 lat1=33 lat2=45",
    "projection=TransverseMercator lon0=-105",
    "projection=UTM zone=13 north=1",
    "projection=AzimuthalEquidistant lon0=-105 lat0=40",
    "projection=LambertAzimuthalEqualArea lon0=-105 lat0=40",
    "projection=Mercator lon0=-100",
    "projection=WebMercator lon0=0",
  };
  const std::vector<Point2> places = { { -105.5, 39.0 }, { -103.1, 41.9 }, { -108.0, 36.6 } };
  for (const std::string& record : planes)
  {
    const ProjectionParameters plain = ProjectionParameters::FromString(record);
    EXPECT_TRUE(plain.PlaneWithoutGrid()) << record;
    EXPECT_EQ(plain.ToString().find("x0="), std::string::npos) << record;
    const GeographicProjection plane(plain);
    ProjectionParameters gridded = plain;
    gridded.FalseEasting = 4321000.25;
    gridded.FalseNorthing = -1e5 / 3.0;
    gridded.ScaleFactor = 0.9996;
    const bool takesOrigin = plain.Kind != ProjectionKind::UTM &&
      plain.Kind != ProjectionKind::AzimuthalEquidistant &&
      plain.Kind != ProjectionKind::LambertAzimuthalEqualArea;
    gridded.HasOriginLatitude = takesOrigin;
    gridded.OriginLatitude = takesOrigin ? 37.5 : 0.0;
    const ProjectionParameters read = ProjectionParameters::FromString(gridded.ToString());
    EXPECT_EQ(read.FalseEasting, gridded.FalseEasting) << record;
    EXPECT_EQ(read.FalseNorthing, gridded.FalseNorthing) << record;
    EXPECT_EQ(read.ScaleFactor, gridded.ScaleFactor) << record;
    EXPECT_EQ(read.HasOriginLatitude, gridded.HasOriginLatitude) << record;
    EXPECT_EQ(read.OriginLatitude, gridded.OriginLatitude) << record;
    EXPECT_TRUE(SameProjection(read, gridded)) << record;
    EXPECT_FALSE(SameProjection(plain, gridded)) << record;
    ProjectionParameters otherOrigin = gridded;
    otherOrigin.OriginLatitude += 1.0;
    EXPECT_EQ(SameProjection(otherOrigin, gridded), !takesOrigin) << record;

    const GeographicProjection grid(read);
    const Point2 origin = takesOrigin
      ? plane.Forward({ plain.Kind == ProjectionKind::UTM ? -105.0 : plain.CentralLongitude, 37.5 })
      : Point2{ 0.0, 0.0 };
    for (const Point2& place : places)
    {
      const Point2 xy = plane.Forward(place);
      const Point2 onGrid = grid.Forward(place);
      EXPECT_NEAR(onGrid.x, 0.9996 * (xy.x - origin.x) + 4321000.25, 1e-8) << record;
      EXPECT_NEAR(onGrid.y, 0.9996 * (xy.y - origin.y) - 1e5 / 3.0, 1e-8) << record;
      const Point2 back = grid.Inverse(onGrid);
      EXPECT_LT(AngularDistance(back.x, place.x), 1e-11) << record;
      EXPECT_NEAR(back.y, place.y, 1e-11) << record;
      // (the default terms: the very same bits, -0 included)
      const Point2 again =
        GeographicProjection(ProjectionParameters::FromString(record + " x0=0 y0=0 k0=1"))
          .Forward(place);
      EXPECT_EQ(std::signbit(again.x), std::signbit(xy.x)) << record;
      EXPECT_EQ(again.x, xy.x) << record;
      EXPECT_EQ(again.y, xy.y) << record;
    }
  }
  // Equal-area grids keep areas only at scale 1.
  ProjectionParameters scaled = ProjectionParameters::FromString(planes[0]);
  EXPECT_TRUE(KeepsAreas(scaled));
  scaled.FalseEasting = 1e6;
  scaled.HasOriginLatitude = true;
  EXPECT_TRUE(KeepsAreas(scaled));
  scaled.ScaleFactor = 0.9996;
  EXPECT_FALSE(KeepsAreas(scaled));
}

// Grid terms out of range, and an origin latitude where the kind's origin is fixed or where the
// projection has no place, are errors naming the term.
TEST(Geo, BadGridTermsAreNamed)
{
  const auto messageOf = [](const std::string& record)
  {
    try
    {
      GeographicProjection projection(ProjectionParameters::FromString(record));
    }
    catch (const InputError& e)
    {
      return std::string(e.what());
    }
    return std::string("built");
  };
  const std::string albers = "projection=AlbersEqualArea lon0=-96 lat1=29.5 lat2=45.5";
  // (a scale of 1e301 made coordinates infinite, one of 1e-300 every place one point)
  for (const char* k0 : { "0", "-1", "1e301", "1e-300", "0.09" })
  {
    EXPECT_NE(
      messageOf(albers + " k0=" + k0)
        .find("scale factor k0 = " + NumberText(std::stod(k0)) + " is not within 0.1 to 10"),
      std::string::npos)
      << k0;
  }
  EXPECT_NE(
    messageOf(albers + " k0=nan").find("k0='nan' is not a finite number"), std::string::npos);
  EXPECT_NE(messageOf(albers + " x0=1e9").find("false easting x0 = 1000000000 is not within 1e8 m"),
    std::string::npos);
  EXPECT_NE(
    messageOf(albers + " y0=-2e8").find("false northing y0 = -200000000"), std::string::npos);
  EXPECT_NE(messageOf(albers + " origin_lat=91")
              .find("latitude of origin origin_lat = 91 is not a latitude"),
    std::string::npos);
  EXPECT_NE(messageOf("projection=UTM zone=13 origin_lat=0")
              .find("origin_lat: UTM takes none (a UTM zone's grid is fixed)"),
    std::string::npos);
  EXPECT_NE(messageOf("projection=LambertAzimuthalEqualArea lon0=10 lat0=52 origin_lat=52")
              .find("its origin is its centre, lat0"),
    std::string::npos);
  EXPECT_NE(messageOf("projection=AzimuthalEquidistant lon0=10 lat0=52 origin_lat=0")
              .find("AzimuthalEquidistant takes none"),
    std::string::npos);
  // The Lambert cone's far pole is at infinity: no grid can start there.
  EXPECT_NE(messageOf("projection=LambertConformalConic lon0=10 lat1=35 lat2=65 origin_lat=-90")
              .find("origin_lat = -90 puts the grid's origin where the LambertConformalConic "
                    "projection has no place"),
    std::string::npos);
  EXPECT_EQ(messageOf(albers + " x0=-1e8 y0=1e8 k0=0.1 origin_lat=-90"), "built");
  EXPECT_EQ(messageOf(albers + " k0=10"), "built");
  // A grid point whose plane point lies beyond 1e8 m is named by its grid coordinates, and the
  // distance said to be the plane's.
  const GeographicProjection small(ProjectionParameters::FromString(albers + " k0=0.1"));
  EXPECT_NE(ErrorOf(
              [&small]() {
                small.Inverse({ 2e7, 0.0 }, 4);
              })
              .find("point 4 (20000000, 0) lies beyond 1e8 m of the AlbersEqualArea projection's "
                    "origin once its grid (false origin, scale) is undone"),
    std::string::npos);
}

// A point past a projection's edge has no place, though GeographicLib's inverse gives one: an
// Albers point past the arc its pole projects to came back as the pole, a transverse Mercator
// easting of 3e7 m as a meridian 90 degrees away (PROJ refuses both). Each is named; points on
// the edge itself (the pole's arc, both edges of the conic's cut half a turn from the meridian)
// go back.
TEST(Geo, PointsPastAProjectionsEdgeHaveNoPlace)
{
  const GeographicProjection albers(ProjectionParameters::FromString(
    "projection=AlbersEqualArea lon0=-96 lat1=29.5 lat2=45.5 origin_lat=23"));
  const GeographicProjection tmerc(
    ProjectionParameters::FromString("projection=TransverseMercator lon0=-96"));
  const GeographicProjection utm(
    ProjectionParameters::FromString("projection=UTM zone=13 north=1"));
  for (const auto& [projection, point] : { std::make_pair(&albers, Point2{ 0.0, -2e7 }),
         std::make_pair(&tmerc, Point2{ 3e7, 0.0 }),
         std::make_pair(&tmerc, Point2{ 3e7, 8e6 }),
         std::make_pair(&tmerc, Point2{ 2e7, 0.0 }),
         std::make_pair(&utm, Point2{ 2.05e7, 4e6 }) })
  {
    const std::string error = ErrorOf([&]() { projection->Inverse(point, 7); });
    EXPECT_NE(error.find("point 7 (" + NumberText(point.x) + ", " + NumberText(point.y) +
                ") lies where no place projects"),
      std::string::npos)
      << error;
  }
  for (const double lon : { -96.0, -50.0, 84.0 - 1e-9, -276.0 + 1e-9 })
  {
    const Point2 pole = albers.Forward({ lon, -90.0 });
    EXPECT_NEAR(albers.Inverse(pole).y, -90.0, 1e-5) << lon; // (ill-conditioned: 0.2 m)
  }
  // (the distance of a point beyond a UTM zone to a tenth of a km, not to 17 digits)
  const std::string far = ErrorOf([&]() { utm.Forward({ -96.0, 40.0 }); });
  EXPECT_TRUE(
    std::regex_search(far, std::regex(" lies [0-9]+\\.[0-9] km from the central meridian")))
    << far;
  // Points Forward makes on the edges go back: on a conic's cut (an inverse there may come back
  // some ulps to either side of it, whose forward lands on the other edge), on the transverse
  // Mercator's 45 degrees, and at its pole (whose longitude the inverse may give as lon0 + 180).
  const std::vector<std::pair<std::string, double>> edges = {
    { "projection=LambertConformalConic lon0=0 lat1=30 lat2=60", 180.0 },
    { "projection=LambertConformalConic lon0=10 lat1=35 lat2=65 x0=4000000 y0=2800000 "
      "origin_lat=52",
      -170.0 },
    { "projection=LambertConformalConic lon0=145 lat1=-18 lat2=-36", -35.0 },
    { "projection=AlbersEqualArea lon0=0 lat1=30 lat2=60", 180.0 },
    { "projection=AlbersEqualArea lon0=-96 lat1=29.5 lat2=45.5 origin_lat=23", 84.0 },
    { "projection=AlbersEqualArea lon0=147 lat1=-40 lat2=-20 k0=0.9996", -33.0 },
    { "projection=TransverseMercator lon0=-96", -51.0 },
    { "projection=TransverseMercator lon0=-96", -141.0 },
  };
  for (const auto& [record, lon] : edges)
  {
    const GeographicProjection projection(ProjectionParameters::FromString(record));
    int refused = 0;
    for (double lat = -80.0; lat <= 80.0; lat += 0.1)
    {
      refused += ErrorOf(
                   [&]() {
                     projection.Inverse(projection.Forward({ lon, lat }));
                   })
                   .empty()
        ? 0
        : 1;
    }
    EXPECT_EQ(refused, 0) << record << " at longitude " << lon;
  }
  for (const auto& [record, lon0] : { std::make_pair("projection=UTM zone=33 north=1", 15.0),
         std::make_pair("projection=TransverseMercator lon0=173", 173.0) })
  {
    const GeographicProjection projection(ProjectionParameters::FromString(record));
    EXPECT_NEAR(projection.Inverse(projection.Forward({ lon0, 90.0 })).y, 90.0, 1e-9) << record;
  }
  // InverseOfImage, for points known to have a place, is the inverse without that test.
  const Point2 boulder = albers.Forward({ -105.27, 40.01 });
  EXPECT_EQ(albers.InverseOfImage(boulder).x, albers.Inverse(boulder).x);
  EXPECT_EQ(albers.InverseOfImage(boulder).y, albers.Inverse(boulder).y);
  const Point2 cut = albers.Forward({ 84.0, 40.0 }); // (half a turn from -96)
  for (const Point2& edge : { cut, Point2{ -cut.x, cut.y } })
  {
    const Point2 back = albers.Inverse(edge);
    EXPECT_LT(std::abs(std::remainder(back.x - 84.0, 360.0)), 1e-9);
    EXPECT_NEAR(back.y, 40.0, 1e-9);
  }
}
