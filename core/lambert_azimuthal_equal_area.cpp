#include "lambert_azimuthal_equal_area.h"

#include <GeographicLib/Math.hpp>

#include <algorithm>
#include <cmath>

namespace tessera
{

namespace
{
using GeographicLib::Math;

/// Centres closer than this (degrees) to a pole are the polar aspect: there cos(xi0) and the
/// meridian's scale vanish together and D is their limit, 1.
constexpr double PolarAspectDegrees = 1e-10;

/// 1 + cos(c) below this is the centre's antipode: within some 4.5e-8 radians (0.3 m) of it,
/// where B = Rq sqrt(2 / (1 + cos(c))) passes 4e7 Rq and the image is a rim of no width.
constexpr double AntipodeOnePlusCos = 1e-15;

/// A plane point up to this much (relative) beyond the image's rim, 2 Rq from the centre, is on
/// it: the rim is the antipode's image, and rounding puts points within a metre of the antipode
/// a few ulps outside.
constexpr double RimRoundingAllowance = 1e-12;

double Squared(double v)
{
  return v * v;
}

/// cos(xi), xi the authalic latitude of lat, from q(lat) = (1 - e^2) (s / (1 - e^2 s^2) +
/// atanh(e s) / e), s = sin(lat), with q_p - q written in 1 - s = 2 sin^2(colatitude / 2): near a
/// pole, cos(xi) through xi in degrees kept some 1e-14 degree of it, and D then erred by 1.4e-14
/// over the centre's distance from the pole in degrees (95 m at 2e-10 degree, 5 m at 1e-8).
double AuthalicCosine(double e2, double lat)
{
  double s = 0.0, c = 0.0;
  Math::sincosd(std::abs(lat), s, c);
  if (e2 == 0.0)
  {
    return c;
  }
  const double e = std::sqrt(e2);
  const double oneMinusS = 2.0 * Squared(Math::sind(0.5 * (90.0 - std::abs(lat))));
  const double q = (1.0 - e2) * (s / (1.0 - e2 * s * s) + std::atanh(e * s) / e);
  const double qp = (1.0 - e2) * (1.0 / (1.0 - e2) + std::atanh(e) / e);
  const double qpMinusQ = oneMinusS * (1.0 + e2 * s) / (1.0 - e2 * s * s) +
    (1.0 - e2) * std::atanh(e * oneMinusS / (1.0 - e2 * s)) / e;
  return std::sqrt(qpMinusQ * (qp + q)) / qp;
}
} // namespace

LambertAzimuthalEqualArea::LambertAzimuthalEqualArea(double a, double f, double lat0)
  : Earth(a, f)
{
  this->Rq = std::sqrt(this->Earth.Area() / (4.0 * Math::pi()));
  this->Xi0 = this->Earth.AuthalicLatitude(lat0);
  // (cos xi0 from xi0 as rounded, as the forward's half angles take xi0: the two agree, which the
  // inverse near the antipode needs to 1e-13; D alone takes the true cosine)
  Math::sincosd(this->Xi0, this->SinXi0, this->CosXi0);
  if (90.0 - std::abs(lat0) < PolarAspectDegrees)
  {
    this->Xi0 = lat0 > 0.0 ? 90.0 : -90.0;
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
  this->D = a * m0 / (this->Rq * AuthalicCosine(e2, lat0));
}

void LambertAzimuthalEqualArea::Forward(double lon0,
  double lat,
  double lon,
  double& x,
  double& y) const
{
  const double xi = this->Earth.AuthalicLatitude(lat);
  const double dLon = Math::AngDiff(lon0, lon);
  double sinXi = 0.0, cosXi = 0.0, sinDLon = 0.0, cosDLon = 0.0, sinHalf = 0.0, cosHalf = 0.0;
  Math::sincosd(xi, sinXi, cosXi);
  Math::sincosd(dLon, sinDLon, cosDLon);
  Math::sincosd(0.5 * dLon, sinHalf, cosHalf);
  // 1 + cos(c), c the angular distance from the centre on the authalic sphere, and the northing's
  // factor cos xi0 sin xi - sin xi0 cos xi cos dLon, in the half-angle forms that keep their
  // digits: about the centre, 1 + cos(c) = 2 (1 - hav(c)) and the factor is
  // sin(xi - xi0) + 2 sin xi0 cos xi sin^2(dLon / 2); about the antipode (latitude -xi0, longitude
  // lon0 + 180), 1 + cos(c) = 2 hav(pi - c) and the factor is
  // sin(xi + xi0) - 2 sin xi0 cos xi cos^2(dLon / 2). (The plain forms cancel where they are small:
  // points 0.1 degree from the antipode came back 3 m off, and within a metre of it beyond the
  // rim.)
  const double cosProduct = this->CosXi0 * cosXi;
  const double havC = Squared(Math::sind(0.5 * (xi - this->Xi0))) + cosProduct * Squared(sinHalf);
  const bool nearCentre = havC <= 0.5;
  const double onePlusCos = nearCentre
    ? 2.0 * (1.0 - havC)
    : 2.0 * (Squared(Math::sind(0.5 * (xi + this->Xi0))) + cosProduct * Squared(cosHalf));
  if (onePlusCos < AntipodeOnePlusCos)
  {
    // (the antipode itself once gave 1 + cos(c) of 1e-17 and a finite point near the centre)
    x = y = Math::NaN();
    return;
  }
  const double northing = nearCentre
    ? Math::sind(xi - this->Xi0) + 2.0 * this->SinXi0 * cosXi * Squared(sinHalf)
    : Math::sind(xi + this->Xi0) - 2.0 * this->SinXi0 * cosXi * Squared(cosHalf);
  const double b = this->Rq * std::sqrt(2.0 / onePlusCos);
  x = b * this->D * cosXi * sinDLon;
  y = b / this->D * northing;
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
  double half = rho / (2.0 * this->Rq); // sin(c / 2)
  if (!(half <= 1.0 + RimRoundingAllowance))
  {
    lat = lon = Math::NaN();
    return;
  }
  half = std::min(half, 1.0);
  const double cosHalf = std::sqrt((1.0 - half) * (1.0 + half)); // cos(c / 2)
  const double sinC = 2.0 * half * cosHalf, cosC = (cosHalf - half) * (cosHalf + half);
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
