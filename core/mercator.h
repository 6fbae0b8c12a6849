#pragma once
// The Mercator projection on the ellipsoid (EPSG method 9804, World Mercator EPSG:3395: scale 1
// on the equator), and with a sphere of the ellipsoid's equatorial radius in place of the
// ellipsoid, the Web ("Pseudo") Mercator of web maps (EPSG method 1024, EPSG:3857), which projects
// WGS84 latitudes by the sphere's formulas. GeographicLib 2.1 has no Mercator class; this one
// follows its projections' calling shape (Forward(lon0, lat, lon, x, y)).
//
//     x = a (lon - lon0),   y = a psi(lat),   psi the isometric latitude (radians):
//     psi = asinh(tan lat) - e atanh(e sin lat) on the ellipsoid, asinh(tan lat) for Web Mercator.
//
// Conformal; the poles are at infinity (their y is infinite, for the caller to refuse).

#include <GeographicLib/Ellipsoid.hpp>

namespace tessera
{

class Mercator
{
public:
  /// a: equatorial radius (m); f: flattening, 0 for Web Mercator (the sphere of radius a).
  Mercator(double a, double f);

  /// lat, lon (degrees) to x, y (metres), x from the central meridian lon0.
  void Forward(double lon0, double lat, double lon, double& x, double& y) const;
  /// x, y (metres) to lat, lon (degrees, lon = lon0 + x / a, within 180 degrees of lon0); NaN
  /// for an x beyond pi a, where Forward puts nothing.
  void Reverse(double lon0, double x, double y, double& lat, double& lon) const;

private:
  GeographicLib::Ellipsoid Earth;
  double A;
};

} // namespace tessera
