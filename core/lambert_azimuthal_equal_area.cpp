#include "lambert_azimuthal_equal_area.h"

#include <GeographicLib/Math.hpp>

#include <cmath>

namespace tessera
{

namespace
{
using GeographicLib::Math;

/// Centres closer than this (degrees) to a pole are the polar aspect: there cos(xi0) and the
/// meridian's scale vanish together and D is their limit, 1.
constexpr double PolarAspectDegrees = 1e-10;

/// 1 + cos(c) below this is the centre's antipode, to rounding: within some 2e-8 radians (0.1 m)
/// of it, where 1 + cos(c) = c'^2 / 2 for the distance c' to the antipode is lost in the sum's
/// rounding.
constexpr double AntipodeOnePlusCos = 1e-15;
} // namespace

LambertAzimuthalEqualArea::LambertAzimuthalEqualArea(double a, double f, double lat0)
  : Earth(a, f)
{
  this->Rq = std::sqrt(this->Earth.Area() / (4.0 * Math::pi()));
  Math::sincosd(this->Earth.AuthalicLatitude(lat0), this->SinXi0, this->CosXi0);
  if (90.0 - std::abs(lat0) < PolarAspectDegrees)
  {
    this->SinXi0 = lat0 > 0.0 ? 1.0 : -1.0;
    this->CosXi0 = 0.0;
    this->D = 1.0;
    return;
  }
  // D = a m0 / (Rq cos xi0), m0 = cos(lat0) / sqrt(1 - e^2 sin^2 lat0): true scale at the centre.
  double sinLat0 = 0.0, cosLat0 = 0.0;
  Math::sincosd(lat0, sinLat0, cosLat0);
  const double e2 = f * (2.0 - f);
  const double m0 = cosLat0 / std::sqrt(1.0 - e2 * sinLat0 * sinLat0);
  this->D = a * m0 / (this->Rq * this->CosXi0);
}

void LambertAzimuthalEqualArea::Forward(double lon0,
  double lat,
  double lon,
  double& x,
  double& y) const
{
  double sinXi = 0.0, cosXi = 0.0, sinDLon = 0.0, cosDLon = 0.0;
  Math::sincosd(this->Earth.AuthalicLatitude(lat), sinXi, cosXi);
  Math::sincosd(Math::AngDiff(lon0, lon), sinDLon, cosDLon);
  // 1 + cos(c), c the angular distance from the centre on the authalic sphere (0 at the antipode).
  const double onePlusCos = 1.0 + this->SinXi0 * sinXi + this->CosXi0 * cosXi * cosDLon;
  if (onePlusCos < AntipodeOnePlusCos)
  {
    // (rounded, the antipode itself gave 1 + cos(c) of 1e-17 and a finite point near the centre)
    x = y = Math::NaN();
    return;
  }
  const double b = this->Rq * std::sqrt(2.0 / onePlusCos);
  x = b * this->D * cosXi * sinDLon;
  y = b / this->D * (this->CosXi0 * sinXi - this->SinXi0 * cosXi * cosDLon);
}

void LambertAzimuthalEqualArea::Reverse(double lon0,
  double x,
  double y,
  double& lat,
  double& lon) const
{
  // (x', y') on the sphere's projection: distance rho from the centre, azimuth from north.
  const double xs = x / this->D;
  const double ys = y * this->D;
  const double rho = std::hypot(xs, ys);
  if (rho == 0.0)
  {
    lat = this->Earth.InverseAuthalicLatitude(Math::atan2d(this->SinXi0, this->CosXi0));
    lon = lon0;
    return;
  }
  const double half = rho / (2.0 * this->Rq); // sin(c / 2)
  if (!(half <= 1.0))
  {
    lat = lon = Math::NaN();
    return;
  }
  const double c = 2.0 * std::asin(half);
  const double sinC = std::sin(c), cosC = std::cos(c);
  const double sinAz = xs / rho, cosAz = ys / rho;
  // The point's unit vector: the centre (cos xi0, 0, sin xi0) turned by c towards the azimuth,
  // north being (-sin xi0, 0, cos xi0) and east (0, 1, 0).
  const double vx = cosC * this->CosXi0 - sinC * cosAz * this->SinXi0;
  const double vy = sinC * sinAz;
  const double vz = cosC * this->SinXi0 + sinC * cosAz * this->CosXi0;
  lat = this->Earth.InverseAuthalicLatitude(Math::atan2d(vz, std::hypot(vx, vy)));
  lon = lon0 + Math::atan2d(vy, vx);
}

} // namespace tessera
